// ContactBlocksPrepare.cpp - each point's rows at the step's start, a block's lanes at a time
// (ContactBlocks::prepare), and each manifold's soft contact in its lane.
#include "ContactBlocks.h"
#include "SolverRows.h"

#include <algorithm>
#include <limits>

namespace physics {

namespace {

// The rows of 3x3 matrices of the lanes' bodies (a column vector's product, Eigen's order: m0 v0 + (m1 v1 +
// m2 v2) per row).
struct Lanes33 {
    Lanes3 row[3];
};
GUARDIAN_ALWAYS_INLINE Lanes33 gatherMatrices(const Mat3* m[kLanes]) {
    Lanes33 out;
    for (int i = 0; i < 3; ++i)
        out.row[i] = Lanes3{lanesOf([&](int l) { return (*m[l])(i, 0); }),
                            lanesOf([&](int l) { return (*m[l])(i, 1); }),
                            lanesOf([&](int l) { return (*m[l])(i, 2); })};
    return out;
}
Lanes3 timesLanes(const Lanes33& m, const Lanes3& v) {
    return {dot(m.row[0], v), dot(m.row[1], v), dot(m.row[2], v)};
}
GUARDIAN_ALWAYS_INLINE Lanes3 gatherVectors(const Vec3* v[kLanes]) {
    return {lanesOf([&](int l) { return v[l]->x(); }), lanesOf([&](int l) { return v[l]->y(); }),
            lanesOf([&](int l) { return v[l]->z(); })};
}
// The lanes' bodies' factors L (BodyFactor), and L^T a.
struct LanesFactor {
    Lanes l00, l10, l11, l20, l21, l22;
};
GUARDIAN_ALWAYS_INLINE LanesFactor gatherFactors(const BodyFactor* f[kLanes]) {
    return {lanesOf([&](int l) { return f[l]->l00; }), lanesOf([&](int l) { return f[l]->l10; }),
            lanesOf([&](int l) { return f[l]->l11; }), lanesOf([&](int l) { return f[l]->l20; }),
            lanesOf([&](int l) { return f[l]->l21; }), lanesOf([&](int l) { return f[l]->l22; })};
}
Lanes3 transposedTimes(const LanesFactor& f, const Lanes3& a) {
    return {f.l00 * a.x + (f.l10 * a.y + f.l20 * a.z), f.l11 * a.y + f.l21 * a.z, f.l22 * a.z};
}
Lanes3 selectLanes3(LaneMask where, const Lanes3& yes, const Lanes3& no) {
    return {select(where, yes.x, no.x), select(where, yes.y, no.y), select(where, yes.z, no.z)};
}

} // namespace

// ContactSolver::prepare's rows, a block's lanes at a time, the same arithmetic in the same order: r from
// each centre of mass, r x d, I^-1 (r x d), the effective mass 1 / (1/m_a + 1/m_b + (r_a x d) I_a^-1
// (r_a x d) + ...), and the approach speed along the normal; the rows keep r x d in the bodies' scaled spin
// coordinates, L^T (r x d) (BodyFactor).
void ContactBlocks::prepare(std::vector<Manifold>& manifolds, const std::vector<SolverBody>& bodies, Real h) {
    static const Mat3 zeroMatrix = Mat3::Zero();
    static const Vec3 zeroVector = Vec3::Zero();
    const Lanes zero(0), one(1);
    for (size_t j = 0; j < m_count; ++j) {
        ContactBlock& block = m_blocks[j];
        const Mat3 *ia[kLanes], *ib[kLanes];
        const BodyFactor *fa[kLanes], *fb[kLanes];
        const Vec3 *ca[kLanes], *cb[kLanes], *va[kLanes], *wa[kLanes], *vb[kLanes], *wb[kLanes];
        for (int l = 0; l < kLanes; ++l) {
            const int k = block.manifold[l];
            if (k >= 0) manifolds[size_t(k)].load = std::numeric_limits<Real>::lowest();
            const SolverBody* a = k >= 0 ? &bodies[size_t(manifolds[size_t(k)].a)] : nullptr;
            const SolverBody* b = k >= 0 ? &bodies[size_t(manifolds[size_t(k)].b)] : nullptr;
            fa[l] = &m_factor[size_t(block.read[0][l])];
            fb[l] = &m_factor[size_t(block.read[1][l])];
            ia[l] = a ? &a->invInertia : &zeroMatrix;
            ib[l] = b ? &b->invInertia : &zeroMatrix;
            ca[l] = a ? &a->com : &zeroVector;
            cb[l] = b ? &b->com : &zeroVector;
            va[l] = a ? &a->v : &zeroVector;
            wa[l] = a ? &a->w : &zeroVector;
            vb[l] = b ? &b->v : &zeroVector;
            wb[l] = b ? &b->w : &zeroVector;
        }
        const Lanes33 invA = gatherMatrices(ia), invB = gatherMatrices(ib);
        const LanesFactor factorA = gatherFactors(fa), factorB = gatherFactors(fb);
        const Lanes3 comA = gatherVectors(ca), comB = gatherVectors(cb);
        const Lanes3 velA = gatherVectors(va), spinA = gatherVectors(wa), velB = gatherVectors(vb),
                     spinB = gatherVectors(wb);
        const LaneMask friction = less(zero, block.frictionCoefficient);
        const Lanes baseK = block.invMassA + block.invMassB;
        for (int i = 0; i < block.points; ++i) {
            const Vec3 *point[kLanes], *dirs[3][kLanes];
            Vec3 tangents[kLanes][2]; // (made here, not kept with the points: the manifolds stream faster)
            bool here[kLanes];        // the lanes whose manifold has this point
            for (int l = 0; l < kLanes; ++l) {
                const int k = block.manifold[l];
                here[l] = k >= 0 && i < manifolds[size_t(k)].count;
                const ManifoldPoint* p = here[l] ? &manifolds[size_t(k)].points[i] : nullptr;
                point[l] = p ? &p->point : &zeroVector;
                dirs[0][l] = p ? &p->normal : &zeroVector;
                if (p && block.friction) tangentBasis(p->normal, tangents[l]);
                dirs[1][l] = p ? &tangents[l][0] : &zeroVector;
                dirs[2][l] = p ? &tangents[l][1] : &zeroVector;
            }
            const LaneMask present = less(zero, lanesOf([&](int l) { return here[l] ? Real(1) : Real(0); }));
            const Lanes3 at = gatherVectors(point);
            const Lanes3 rA = at - comA, rB = at - comB;
            BlockPoint& q = block.p[i];
            for (int r = 0; r < 3; ++r) {
                if (r > 0 && !block.friction) break;
                const Lanes3 d = gatherVectors(dirs[r]);
                const Lanes3 armA = crossLanes(rA, d), armB = crossLanes(rB, d);
                const Lanes3 turnA = timesLanes(invA, armA), turnB = timesLanes(invB, armB);
                const Lanes k = (baseK + dot(armA, turnA)) + dot(armB, turnB);
                const LaneMask keep = r == 0 ? present : andMask(present, friction);
                const Lanes mass = select(andMask(keep, less(zero, k)), one / k, zero);
                BlockRow& row = q.row[r];
                row.dir = selectLanes3(keep, d, Lanes3{});
                row.armA = selectLanes3(keep, transposedTimes(factorA, armA), Lanes3{});
                row.armB = selectLanes3(keep, transposedTimes(factorB, armB), Lanes3{});
                row.mass = mass;
                if (r == 0) { // the approach in world terms (the spins are the bodies' own here)
                    const Lanes3 armNA = selectLanes3(keep, armA, Lanes3{}),
                                 armNB = selectLanes3(keep, armB, Lanes3{});
                    q.approach = (dot(row.dir, velB - velA) + dot(armNB, spinB)) - dot(armNA, spinA);
                }
            }
            const BlockRow& n = q.row[0];
            // The approach kept with the point (restitution), and the load it carried last step with the
            // manifold (the soft contact: ContactSolver::contactSoftness), while the mass is at hand.
            for (int l = 0; l < kLanes; ++l) {
                const int k = block.manifold[l];
                if (k < 0 || i >= manifolds[size_t(k)].count) continue;
                Manifold& m = manifolds[size_t(k)];
                ManifoldPoint& p = m.points[i];
                p.approachSpeed = q.approach.lane(l);
                p.maxNormalImpulse = 0; // found again by the sub-steps (unpack)
                const Real mass = n.mass.lane(l);
                if (mass > 0.0f) m.load = std::max(m.load, p.normalImpulse / (h * mass));
            }
        }
        prepareCoupling(block);
    }
}

void ContactBlocks::prepareCoupling(ContactBlock& block) {
    const Lanes baseK = block.invMassA + block.invMassB;
    for (int i = 0; i < block.points; ++i) {
        const BlockRow& a = block.p[i].row[0];
        block.diagonal[i] = (baseK * dot(a.dir, a.dir) + dot(a.armA, a.armA)) + dot(a.armB, a.armB);
        for (int j = i + 1; j < block.points; ++j) {
            const BlockRow& b = block.p[j].row[0];
            block.coupling[ContactBlock::pairIndex(i, j)] =
                (baseK * dot(a.dir, b.dir) + dot(a.armA, b.armA)) + dot(a.armB, b.armB);
        }
    }
}

void ContactBlocks::setSoftness(const Manifold& m, Real biasRate, Real massScale, Real impulseScale) {
    ContactBlock& block = at(m);
    block.biasRate.setLane(m.lane, biasRate);
    block.massScale.setLane(m.lane, massScale);
    block.impulseScale.setLane(m.lane, impulseScale);
}

} // namespace physics
