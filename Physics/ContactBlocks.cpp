// ContactBlocks.cpp - packing manifolds into blocks of kLanes, the bodies' scaled spin coordinates, their
// velocities and poses in and out, and the points' gaps (ContactBlocks.h; the sweeps:
// ContactBlocksSweeps.cpp).
#include "ContactBlocks.h"
#include "GrowingStorage.h"
#include "SolverRows.h"

#include <algorithm>

namespace physics {

// --- the bodies' scaled spins ---

// A movable body's L is the Cholesky factor of its I^-1 (symmetric positive definite, or zero when its
// rotation is locked), made in double: a thin rod's is ill-conditioned.
//
// An immovable body is read and never written, but within a block its lane's registers carry whatever the
// rows add to it from one row to the next, and nothing may. Its I^-1 is zero, so L = 0: its rows' s are
// zero and no row turns it. One that turns (a kinematic body with a spin) needs its spin in the row
// speeds, r x d . w: it gets L = 2^-20 (an exact power of two: s . u gives the bits of r x d . w), and what
// its rows add to its lane's spin comes back into their speeds scaled by 2^-40, |r x d|^2 p 1e-12: nothing.
BodyFactor BodyFactor::of(const SolverBody& b) {
    constexpr Real kSpinScale = Real(1.0 / 1048576.0); // 2^-20
    if (!movable(b)) {
        const bool spinning = b.w != Vec3::Zero();
        const Real l = spinning ? kSpinScale : Real(0), r = spinning ? 1 / kSpinScale : Real(0);
        return BodyFactor{l, 0, l, 0, 0, l, r, r, r, false};
    }
    if (b.invInertia.isZero(0.0f)) return BodyFactor{0, 0, 0, 0, 0, 0, 0, 0, 0, false}; // it does not turn
    const Eigen::Matrix3d a = b.invInertia.cast<double>();
    const double l00 = std::sqrt(a(0, 0)), l10 = a(1, 0) / l00, l20 = a(2, 0) / l00;
    const double l11 = std::sqrt(std::max(0.0, a(1, 1) - l10 * l10));
    const double l21 = l11 > 0 ? (a(2, 1) - l20 * l10) / l11 : 0.0;
    const double l22 = std::sqrt(std::max(0.0, a(2, 2) - l20 * l20 - l21 * l21));
    auto inverse = [](double x) { return x > 0 ? Real(1.0 / x) : Real(0); };
    return BodyFactor{Real(l00), Real(l10),    Real(l11),    Real(l20),    Real(l21),
                      Real(l22), inverse(l00), inverse(l11), inverse(l22), true};
}

Vec3 BodyFactor::times(const Vec3& u) const {
    return Vec3(l00 * u.x(), l10 * u.x() + l11 * u.y(), l20 * u.x() + l21 * u.y() + l22 * u.z());
}
Vec3 BodyFactor::solve(const Vec3& w) const {
    const Real x = r00 * w.x(), y = r11 * (w.y() - l10 * x);
    return Vec3(x, y, r22 * (w.z() - l20 * x - l21 * y));
}
Vec3 BodyFactor::timesT(const Vec3& a) const {
    return Vec3(l00 * a.x() + l10 * a.y() + l20 * a.z(), l11 * a.y() + l21 * a.z(), l22 * a.z());
}
Vec3 BodyFactor::solveT(const Vec3& s) const {
    const Real z = r22 * s.z(), y = r11 * (s.y() - l21 * z);
    return Vec3(r00 * (s.x() - l10 * y - l20 * z), y, z);
}

// Restitution and shock propagation work on the bodies' own velocities: the row back in world terms,
// r x n = L^-T s and I^-1 (r x n) = L s (none for a body that does not turn).
NormalRow ContactBlocks::normalRow(const Manifold& m, int point) const {
    const BlockRow& r = at(m).p[point].row[0];
    const int l = m.lane;
    const BodyFactor &fa = m_factor[size_t(m.a)], &fb = m_factor[size_t(m.b)];
    const Vec3 sA = laneOf(r.armA, l), sB = laneOf(r.armB, l);
    return NormalRow{fa.solveT(sA), fb.solveT(sB), fa.turns ? fa.times(sA) : Vec3(Vec3::Zero()),
                     fb.turns ? fb.times(sB) : Vec3(Vec3::Zero()), r.mass.lane(l)};
}

// --- packing ---

// Manifolds that share no movable body commute exactly: each reads and writes only its own two bodies'
// velocities (an immovable body is read, never written). So any order in which every movable body meets its
// manifolds in their order gives the very bits of the sequential sweep. Each manifold goes, in order, to the
// first block with a free lane after the last block holding either of its movable bodies (as soon as
// possible). Sweeps that reordered more (colour by colour, as Box2D v3 does) rested a 10-box tower 23 %
// deeper than its contacts' give, and ordered by height they let the 210-box pyramid's top drift 15 cm.
int ContactBlocks::openBlock(int from) {
    int j = from;
    while (j < int(m_count) && m_used[size_t(j)] == kLanes) j = m_nextOpen[size_t(j)];
    for (int k = from; k < j;) { // shorten the path walked (union-find's path compression)
        const int next = m_nextOpen[size_t(k)];
        m_nextOpen[size_t(k)] = j;
        k = next;
    }
    return j;
}

void ContactBlocks::fill(int j, int lane, Manifold& m, int index, const std::vector<SolverBody>& bodies) {
    ContactBlock& block = m_blocks[size_t(j)];
    BlockAnchors& anchors = m_anchors[size_t(j)];
    const SolverBody &a = bodies[size_t(m.a)], &b = bodies[size_t(m.b)];
    const int scratch = int(bodies.size()) + 1;
    block.manifold[lane] = index;
    block.read[0][lane] = m.a;
    block.read[1][lane] = m.b;
    block.write[0][lane] = movable(a) ? m.a : scratch;
    block.write[1][lane] = movable(b) ? m.b : scratch;
    block.points = std::max(block.points, m.count);
    block.friction = block.friction || m.friction > 0.0f;
    block.invMassA.setLane(lane, a.invMass);
    block.invMassB.setLane(lane, b.invMass);
    block.frictionCoefficient.setLane(lane, m.friction);
    const bool friction = m.friction > 0.0f; // a frictionless lane's tangent rows and impulses stay zero
    for (int i = 0; i < m.count; ++i) {
        const ManifoldPoint& p = m.points[i];
        BlockPoint& q = block.p[i];
        setLanes3(anchors.a[i], lane, p.anchorA);
        setLanes3(anchors.b[i], lane, p.anchorB);
        q.impulse[0].setLane(lane, p.normalImpulse);
        q.impulse[1].setLane(lane, friction ? p.tangentImpulse[0] : Real(0));
        q.impulse[2].setLane(lane, friction ? p.tangentImpulse[1] : Real(0));
    }
    m.lane = lane;
}

void ContactBlocks::pack(std::vector<Manifold>& manifolds, const std::vector<SolverBody>& bodies) {
    const int zero = int(bodies.size()), scratch = zero + 1;
    m_count = 0;
    m_used.clear();
    m_nextOpen.clear();
    // Kept with room to spare, so that a warm scene whose packing varies from step to step does not allocate.
    if (m_blocks.capacity() < manifolds.size()) {
        m_blocks.reserve(manifolds.size() + manifolds.size() / 2);
        m_anchors.reserve(m_blocks.capacity());
        m_used.reserve(m_blocks.capacity());
        m_nextOpen.reserve(m_blocks.capacity());
    }
    assignGrowing(m_lastBlock, bodies.size(), -1);
    for (size_t k = 0; k < manifolds.size(); ++k) {
        Manifold& m = manifolds[k];
        const bool moveA = movable(bodies[size_t(m.a)]), moveB = movable(bodies[size_t(m.b)]);
        const int after =
            std::max(moveA ? m_lastBlock[size_t(m.a)] : -1, moveB ? m_lastBlock[size_t(m.b)] : -1);
        const int j = openBlock(after + 1);
        if (j == int(m_count)) {
            openNew(zero, scratch);
            m_used.push_back(0);
            m_nextOpen.push_back(j + 1);
        }
        m.block = j;
        fill(j, m_used[size_t(j)]++, m, int(k), bodies);
        if (moveA) m_lastBlock[size_t(m.a)] = j;
        if (moveB) m_lastBlock[size_t(m.b)] = j;
    }
    m_factor.resize(bodies.size() + 1);
    for (size_t i = 0; i < bodies.size(); ++i) m_factor[i] = BodyFactor::of(bodies[i]);
    m_factor[size_t(zero)] = BodyFactor{0, 0, 0, 0, 0, 0, 0, 0, 0, false}; // an empty lane's: nothing turns
    m_velocity.resize(bodies.size() + 2);
    m_velocity[size_t(zero)] = Velocity{};
    m_pose.resize(bodies.size() + 1);
    m_pose[size_t(zero)] = Pose{{0, 0, 0, 1}, {0, 0, 0, 0}};
}

// The next block, empty. A block an earlier step used is reused rather than built (and zeroed: 2.5 KB)
// again; only what may be read before this step writes it is reset: the lanes' masses and soft settings,
// the impulses and the anchors (fill() sets them for its lane's points only). The rows, approach and gap are
// written for every lane up to the block's points before anything reads them (prepare, the first sweep's
// gaps); points beyond them and a frictionless block's tangent rows are never read.
void ContactBlocks::openNew(int zero, int scratch) {
    if (m_count == m_blocks.size()) {
        m_blocks.emplace_back();
        m_anchors.emplace_back();
    } else {
        ContactBlock& block = m_blocks[m_count];
        block.points = 0;
        block.friction = false;
        for (Lanes* x : {&block.invMassA, &block.invMassB, &block.frictionCoefficient, &block.biasRate,
                         &block.massScale, &block.impulseScale})
            *x = Lanes();
        for (BlockPoint& q : block.p) {
            for (Lanes& x : q.impulse) x = Lanes();
            q.maxNormal = Lanes();
        }
        m_anchors[m_count] = BlockAnchors();
    }
    ContactBlock& block = m_blocks[m_count++];
    for (int lane = 0; lane < kLanes; ++lane) {
        block.manifold[lane] = -1;
        block.read[0][lane] = block.read[1][lane] = zero;
        block.write[0][lane] = block.write[1][lane] = scratch;
    }
}

void ContactBlocks::unpack(std::vector<Manifold>& manifolds) const {
    for (Manifold& m : manifolds) {
        if (m.block < 0) continue;
        const ContactBlock& block = at(m);
        for (int i = 0; i < m.count; ++i) {
            ManifoldPoint& p = m.points[i];
            const BlockPoint& q = block.p[i];
            p.normalImpulse = q.impulse[0].lane(m.lane);
            p.tangentImpulse[0] = q.impulse[1].lane(m.lane);
            p.tangentImpulse[1] = q.impulse[2].lane(m.lane);
            p.maxNormalImpulse = q.maxNormal.lane(m.lane);
            p.gap = q.gap.lane(m.lane);
        }
    }
}

// --- bodies in and out ---

void ContactBlocks::loadVelocities(const std::vector<SolverBody>& bodies) {
    for (size_t i = 0; i < bodies.size(); ++i) {
        const SolverBody& b = bodies[i];
        const Vec3 u = m_factor[i].solve(b.w);
        m_velocity[i] = Velocity{{b.v.x(), b.v.y(), b.v.z(), 0}, {u.x(), u.y(), u.z(), 0}};
    }
}

void ContactBlocks::storeVelocities(std::vector<SolverBody>& bodies) const {
    for (size_t i = 0; i < bodies.size(); ++i) {
        SolverBody& b = bodies[i];
        if (!movable(b)) continue;
        const Velocity& u = m_velocity[i];
        b.v = Vec3(u.v[0], u.v[1], u.v[2]);
        b.w = m_factor[i].times(vec(u.w));
    }
}

void ContactBlocks::loadPoses(const std::vector<SolverBody>& bodies) {
    for (size_t i = 0; i < bodies.size(); ++i) {
        const SolverBody& b = bodies[i];
        if (!b.root) {
            m_pose[i] = Pose{{0, 0, 0, 1}, {0, 0, 0, 0}};
            continue;
        }
        const Quat& q = b.rotation;
        m_pose[i] = Pose{{q.x(), q.y(), q.z(), q.w()}, {b.origin.x(), b.origin.y(), b.origin.z(), 0}};
    }
}

// Each point's separation at the bodies' poses (separation() in SolverRows.h, lane by lane). The static
// world's anchors are world points: its pose is the identity.
void ContactBlocks::measureGaps(ContactBlock& block, const BlockAnchors& anchors) const {
    const Real *qa4[kLanes], *qb4[kLanes], *oa4[kLanes], *ob4[kLanes];
    for (int l = 0; l < kLanes; ++l) {
        const Pose& a = m_pose[size_t(std::min(block.read[0][l], int(m_pose.size()) - 1))];
        const Pose& b = m_pose[size_t(std::min(block.read[1][l], int(m_pose.size()) - 1))];
        qa4[l] = a.q;
        qb4[l] = b.q;
        oa4[l] = a.origin;
        ob4[l] = b.origin;
    }
    const Lanes qwa = lanesOf([&](int l) { return qa4[l][3]; }),
                qwb = lanesOf([&](int l) { return qb4[l][3]; });
    const Lanes3 qa = gatherRows(qa4), qb = gatherRows(qb4), oa = gatherRows(oa4), ob = gatherRows(ob4);
    for (int i = 0; i < block.points; ++i) {
        BlockPoint& q = block.p[i];
        const Lanes3 pa = rotateLanes(qa, qwa, anchors.a[i]) + oa,
                     pb = rotateLanes(qb, qwb, anchors.b[i]) + ob;
        q.gap = dot(q.row[0].dir, pb - pa);
    }
}

} // namespace physics
