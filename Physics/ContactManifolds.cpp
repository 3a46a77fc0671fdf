// ContactManifolds.cpp - this step's manifolds: the detector's contacts grouped per geometry pair (up to 4
// points each), last step's points that came apart by a hair kept, and each point matched with last step's
// point at the same place so that it starts from that point's impulses (warm starting).
#include "ContactSolver.h"
#include "SolverRows.h"

#include "MathEigen.h"
#include "RBDynamics.h"
#include "iCollisionGeometry.h"
#include "iCollisionSpace.h"
#include "iRigidBody.h"

#include <algorithm>
#include <cmath>

namespace physics {

namespace {
// Anchors are measured in a root's frame at the step's start, where the detector found the contacts; the
// static world's are world points.
Vec3 localAnchor(const SolverBody& b, const Vec3& world) {
    return b.root ? Vec3(b.startRotation.conjugate() * (world - b.startOrigin)) : world;
}
} // namespace

int ContactSolver::bodyIndex(RBDynamics* root, const SolverBodyAccess& access) {
    if (const int* known = m_bodyIndex.find(root)) return *known;
    int index = int(m_bodies.size());
    m_bodies.push_back(access.enter(root, index));
    m_bodyIndex.emplace(root, index);
    return index;
}

void ContactSolver::buildManifolds(const CollisionContact* contacts, size_t count,
                                   const SolverBodyAccess& access) {
    m_manifolds.clear();
    // Room to spare (this list and last step's swap every step): a warm scene whose pair count wanders a
    // little above any it had does not allocate each time it does.
    const size_t room = m_last.size() + m_last.size() / 2 + 16;
    if (m_manifolds.capacity() < room) m_manifolds.reserve(room);
    if (m_dormant.capacity() < m_last.size()) m_dormant.reserve(room); // last step's that rest, at most all
    FlatMap<PairKey, size_t, PairKeyHash>& current = m_current;
    current.clear();
    m_maxDepthBefore = 0;
    constexpr size_t kNone = ~size_t(0);
    // A space lists a pair's contacts one after another: what holds for the pair is worked out at its first.
    struct {
        const iCollisionGeometry *g1 = nullptr, *g2 = nullptr;
        iRigidBody *rb1 = nullptr, *rb2 = nullptr;
        RBDynamics *rootA = nullptr, *rootB = nullptr;
        bool skip = true;
        size_t manifold = kNone; // its place in m_manifolds, once it has one
    } pair;
    for (size_t i = 0; contacts && i < count; ++i) {
        const CollisionContact& c = contacts[i];
        if (!c.g1 || !c.g2) continue;
        if (c.g1 != pair.g1 || c.g2 != pair.g2) {
            pair.g1 = c.g1;
            pair.g2 = c.g2;
            pair.rb1 = c.g1->getRigidBody();
            pair.rb2 = c.g2->getRigidBody();
            pair.rootA = pair.rb1 ? pair.rb1->getDynamics().attachmentRoot() : nullptr;
            pair.rootB = pair.rb2 ? pair.rb2->getDynamics().attachmentRoot() : nullptr;
            const bool fixedA = !pair.rootA || immovable(*pair.rootA),
                       fixedB = !pair.rootB || immovable(*pair.rootB);
            pair.skip = pair.rootA == pair.rootB || (fixedA && fixedB) ||
                        joinedWithoutContact(pair.rootA, pair.rootB);
            const size_t* known = pair.skip ? nullptr : current.find(PairKey{c.g1, c.g2});
            pair.manifold = known ? *known : kNone;
        }
        if (pair.skip) continue;
        iRigidBody *rb1 = pair.rb1, *rb2 = pair.rb2;
        RBDynamics *rootA = pair.rootA, *rootB = pair.rootB;
        Vec3 n = toEigen(c.normal);
        if (!n.allFinite() || n.squaredNorm() < 0.5f || !std::isfinite(c.depth)) continue;
        n.normalize();

        if (pair.manifold == kNone) {
            pair.manifold = m_manifolds.size();
            current.emplace(PairKey{c.g1, c.g2}, pair.manifold);
            Manifold& m = m_manifolds.emplace_back();
            m.g1 = c.g1;
            m.g2 = c.g2;
            m.rootA = rootA;
            m.rootB = rootB;
            m.a = bodyIndex(rootA, access);
            m.b = bodyIndex(rootB, access);
            // A bodiless geometry has the default material of a body.
            static const RBDynamics defaults;
            const RBDynamics& matA = rb1 ? rb1->getDynamics() : defaults;
            const RBDynamics& matB = rb2 ? rb2->getDynamics() : defaults;
            m.friction = combine(m_settings.friction, matA.friction, matB.friction);
            m.restitution = combine(m_settings.restitution, matA.restitution, matB.restitution);
            m.size = std::fmin(c.g1->getBoundingRadius(), c.g2->getBoundingRadius());
        }
        Manifold& m = m_manifolds[pair.manifold];
        ManifoldPoint p;
        p.normal = n;
        tangentBasis(n, p.tangent);
        p.depth = std::max(0.0f, c.depth);
        // The two touching surface points: a's reaches depth/2 past the contact point along n, b's as far
        // back.
        Vec3 pos = toEigen(c.pos);
        Vec3 onA = pos + 0.5f * p.depth * n, onB = pos - 0.5f * p.depth * n;
        p.anchorA = localAnchor(m_bodies[m.a], onA);
        p.anchorB = localAnchor(m_bodies[m.b], onB);
        p.point = pos;
        m_maxDepthBefore = std::max(m_maxDepthBefore, p.depth);
        if (m.count < 4) {
            m.points[m.count++] = p;
        } else { // keep the four deepest
            ManifoldPoint* shallowest =
                std::min_element(m.points, m.points + 4, [](auto& x, auto& y) { return x.depth < y.depth; });
            if (shallowest->depth < p.depth) *shallowest = p;
        }
    }
    keepPoints(access, current);
}

// A collision detector reports only touching points, so a resting box that rocks by a hair loses the
// corners that lifted, stands on the others for a step, and rocks back: the contacts flicker and the warm
// start is lost with them. Like a persistent manifold (Bullet's contact breaking threshold), a pair still
// touching keeps last step's points that came apart by less than keepDistance, each with its impulses. Such
// a point is speculative: it holds only once its gap closes (see solveContacts), so it never pulls and never
// stops a body short of touching.
void ContactSolver::keepPoints(const SolverBodyAccess& access,
                               const FlatMap<PairKey, size_t, PairKeyHash>& reported) {
    if (m_settings.keepDistance <= 0.0f) return;
    const Real keep = m_settings.keepDistance, match2 = m_settings.matchDistance * m_settings.matchDistance;
    // Appends to m the points of old that m lacks and that are apart by less than keep.
    auto keepFrom = [&](const Manifold& old, Manifold& m) {
        const SolverBody &a = m_bodies[m.a], &b = m_bodies[m.b];
        const Vec3 n = m.count ? m.points[0].normal : old.points[0].normal;
        const int reportedCount = m.count;
        for (int j = 0; j < old.count && m.count < 4; ++j) {
            const ManifoldPoint& o = old.points[j];
            if (o.bounced) continue; // it left the surface
            bool known = false;
            for (int i = 0; i < reportedCount && !known; ++i)
                known = (m.points[i].anchorA - o.anchorA).squaredNorm() <= match2;
            if (known) continue;
            Vec3 onA = startPoint(a, o.anchorA), onB = startPoint(b, o.anchorB), gap = onB - onA;
            Real separation = n.dot(gap);
            if (separation <= 0.0f || separation > keep || (gap - separation * n).norm() > keep)
                continue; // touching again is the detector's to report; too far apart or slid off: broken
            ManifoldPoint p = o;
            p.normal = n;
            tangentBasis(n, p.tangent);
            p.point = 0.5f * (onA + onB);
            m.points[m.count++] = p;
        }
    };
    for (Manifold& m : m_manifolds) {
        if (const size_t* last = m_lastIndex.find(PairKey{m.g1, m.g2})) keepFrom(m_last[*last], m);
    }
    // A pair the detector no longer reports at all (lifted by a hair) keeps its points for one step; a pair
    // at rest (an island asleep: the detector skips it) keeps its manifold unsolved until it wakes.
    m_dormant.clear();
    for (const Manifold& old : m_last) {
        if (reported.find(PairKey{old.g1, old.g2}) || !access.alive(old.rootA) || !access.alive(old.rootB))
            continue;
        if (access.resting(old.rootA) && access.resting(old.rootB)) {
            if (old.age == 0 || old.dormant) {
                m_dormant.push_back(old);
                m_dormant.back().dormant = true;
            }
            continue;
        }
        if (old.age > 0 || old.dormant) continue;
        Manifold m = old;
        m.age = 1;
        m.count = 0;
        m.a = bodyIndex(old.rootA, access);
        m.b = bodyIndex(old.rootB, access);
        keepFrom(old, m);
        if (m.count > 0) m_manifolds.push_back(m);
    }
}

void ContactSolver::matchPreviousImpulses() {
    const Real best0 = m_settings.matchDistance * m_settings.matchDistance;
    for (Manifold& m : m_manifolds) {
        const size_t* last = m_settings.warmStart ? m_lastIndex.find(PairKey{m.g1, m.g2}) : nullptr;
        if (!last) continue;
        const Manifold& old = m_last[*last];
        for (int i = 0; i < m.count; ++i) {
            ManifoldPoint& p = m.points[i];
            // The old point at the same place on body a.
            const ManifoldPoint* match = nullptr;
            Real best = best0;
            for (int j = 0; j < old.count; ++j) {
                Real d2 = (old.points[j].anchorA - p.anchorA).squaredNorm();
                if (d2 <= best) {
                    best = d2;
                    match = &old.points[j];
                }
            }
            // A point that bounced left the surface: its impulse was an impact's, not a load to start from
            // (warm-started, it threw a ball chased by a kinematic paddle back at the paddle).
            if (!match || match->bounced) continue;
            p.normalImpulse = match->normalImpulse;
            Vec3 friction =
                match->tangent[0] * match->tangentImpulse[0] + match->tangent[1] * match->tangentImpulse[1];
            p.tangentImpulse[0] = friction.dot(p.tangent[0]);
            p.tangentImpulse[1] = friction.dot(p.tangent[1]);
        }
    }
}

void ContactSolver::setMemory(const Memory& memory) {
    m_manifolds = memory.last;
    storeImpulses(); // indexes them as last step's
    m_maxDepthBefore = memory.depthBefore;
    m_maxDepthAfter = memory.depthAfter;
}

// This step's manifolds become last step's, moved rather than copied (every one has a point).
void ContactSolver::storeImpulses() {
    m_last.swap(m_manifolds);
    m_manifolds.clear();
    for (Manifold& m : m_last) m.dormant = false;
    m_last.insert(m_last.end(), m_dormant.begin(), m_dormant.end());
    m_dormant.clear();
    m_lastIndex.clear();
    for (size_t i = 0; i < m_last.size(); ++i) m_lastIndex.emplace(PairKey{m_last[i].g1, m_last[i].g2}, i);
}

} // namespace physics
