// ContactBlocksSweeps.cpp - the wide sweeps over the contact blocks: forces, warm start, and the velocity,
// push-out and relax sweeps (ContactBlocks.h), each a block at a time with its bodies' velocities in lanes.
#include "ContactBlocks.h"
#include "GrowingStorage.h"
#include "SolverRows.h"

#include <algorithm>
#include <type_traits>

namespace physics {

namespace {

// The velocities of a block's bodies, one lane each, and the rows of 4-Real slots they come from.
struct BlockVelocity {
    Lanes3 va, wa, vb, wb;
};

// The relative speed of b against a along a row (sumOfDots' order).
GUARDIAN_ALWAYS_INLINE Lanes rowSpeed(const BlockRow& r, const BlockVelocity& u) {
    return (dot(r.dir, u.vb - u.va) + dot(r.armB, u.wb)) - dot(r.armA, u.wa);
}

// An impulse along a row: on b, and its opposite on a (the spins scaled: BodyFactor).
GUARDIAN_ALWAYS_INLINE void applyRow(const BlockRow& r, const Lanes& ima, const Lanes& imb,
                                     const Lanes& impulse, BlockVelocity& u) {
    u.va = u.va - (ima * impulse) * r.dir;
    u.wa = u.wa - impulse * r.armA;
    u.vb = u.vb + (imb * impulse) * r.dir;
    u.wb = u.wb + impulse * r.armB;
}

// A block's two bodies' velocities in each lane, from the flat array (V: ContactBlocks::Velocity), and back
// to where they are stored. Inlined into the sweeps (called, they cost a two-body step 3 % more instructions,
// the velocities returned through memory).
template <class V> GUARDIAN_ALWAYS_INLINE BlockVelocity gatherBlock(const ContactBlock& block, const V* u) {
    const Real *va[kLanes], *wa[kLanes], *vb[kLanes], *wb[kLanes];
    for (int l = 0; l < kLanes; ++l) {
        va[l] = u[block.read[0][l]].v;
        wa[l] = u[block.read[0][l]].w;
        vb[l] = u[block.read[1][l]].v;
        wb[l] = u[block.read[1][l]].w;
    }
    return {gatherRows(va), gatherRows(wa), gatherRows(vb), gatherRows(wb)};
}
template <class V>
GUARDIAN_ALWAYS_INLINE void scatterBlock(const ContactBlock& block, const BlockVelocity& vel, V* u) {
    Real *va[kLanes], *wa[kLanes], *vb[kLanes], *wb[kLanes];
    for (int l = 0; l < kLanes; ++l) {
        va[l] = u[block.write[0][l]].v;
        wa[l] = u[block.write[0][l]].w;
        vb[l] = u[block.write[1][l]].v;
        wb[l] = u[block.write[1][l]].w;
    }
    scatterRows(vel.va, va);
    scatterRows(vel.wa, wa);
    scatterRows(vel.vb, vb);
    scatterRows(vel.wb, wb);
}

} // namespace

void ContactBlocks::addForces(const std::vector<SolverBody>& bodies, Real share) {
    for (size_t i = 0; i < bodies.size(); ++i) {
        const SolverBody& b = bodies[i];
        if (!movable(b)) continue;
        Velocity& u = m_velocity[i];
        const Vec3 dw = m_factor[i].solve(b.dw);
        for (int k = 0; k < 3; ++k) {
            u.v[k] += share * b.dv[k];
            u.w[k] += share * dw[k];
        }
    }
}

void ContactBlocks::warmStart(bool firstSubstep, Real impactSpeed) {
    const Lanes impact(impactSpeed), zero(0);
    for (size_t j = 0; j < m_count; ++j) {
        ContactBlock& block = m_blocks[j];
        Velocity* u = m_velocity.data();
        BlockVelocity vel = gatherBlock(block, u);
        for (int i = 0; i < block.points; ++i) {
            BlockPoint& q = block.p[i];
            // An impact does not recur: its point starts the later sub-steps from nothing.
            if (!firstSubstep) {
                const LaneMask fast = less(q.approach, impact);
                for (int r = 0; r < 3; ++r) q.impulse[r] = select(fast, zero, q.impulse[r]);
            }
            applyRow(q.row[0], block.invMassA, block.invMassB, q.impulse[0], vel);
            if (!block.friction) continue;
            applyRow(q.row[1], block.invMassA, block.invMassB, q.impulse[1], vel);
            applyRow(q.row[2], block.invMassA, block.invMassB, q.impulse[2], vel);
        }
        scatterBlock(block, vel, u);
    }
}

void ContactBlocks::solve(const std::vector<SolverBody>& bodies, const Sweep& sweep) {
    if (sweep.measureGaps) loadPoses(bodies);
    const Lanes zero(0), one(1), h(sweep.h), touch(-sweep.touchOverlap), impact(-sweep.restitutionThreshold),
        maxPush(-sweep.maxPushSpeed);
    for (size_t j = 0; j < m_count; ++j) {
        ContactBlock& block = m_blocks[j];
        // Positions do not change within a sweep, nor between a relax sweep and the next sub-step's velocity
        // sweep and push out: the gaps are measured once for all three.
        if (sweep.measureGaps) measureGaps(block, m_anchors[j]);
        // Each point's target: reach v_n = -bias, softly (see ContactSolver::solveContacts).
        Lanes bias[4], massScale[4], impulseScale[4];
        for (int i = 0; i < block.points; ++i) {
            const BlockPoint& q = block.p[i];
            const LaneMask apart = less(zero, q.gap);
            const LaneMask rigid = andMask(less(touch, q.gap), less(q.approach, impact));
            bias[i] = select(apart, q.gap / h, zero);
            massScale[i] = one;
            impulseScale[i] = zero;
            if (sweep.pass == Pass::PushOut) {
                const LaneMask notSoft = orMask(apart, rigid);
                bias[i] = select(notSoft, bias[i], maxOf(block.biasRate * q.gap, maxPush));
                massScale[i] = select(notSoft, one, block.massScale);
                impulseScale[i] = select(notSoft, zero, block.impulseScale);
            }
        }
        Velocity* u = m_velocity.data();
        BlockVelocity vel = gatherBlock(block, u);
        // The normal rows' Gauss-Seidel passes, worked in the rows' speeds: each point's normal speed is
        // found once, each impulse change moves every point's speed by the block's coupling (ContactBlock),
        // and the impulses' net change reaches the bodies at the end, a row at a time. The same sweep as
        // applying each change to the velocities and reading the next row's speed from them (up to rounding),
        // but a row no longer waits on the one before through the bodies' twelve velocity components: a
        // two-body step 11.15 -> 10.3 us, the awake 210-box pyramid 1.044 -> 0.964 ms a step. soft: the push
        // out's soft rows; otherwise every row is rigid (mass scale 1, impulse scale 0: no need for those two
        // products, as the impulses are finite and never -0). The push out's normal impulses are pushed[],
        // started from the solved ones (which stay).
        Lanes pushed[4];
        auto solveNormal = [&](auto soft, int passes) {
            const int n = block.points;
            Lanes speed[4], start[4];
            for (int i = 0; i < n; ++i) {
                const BlockPoint& q = block.p[i];
                speed[i] = rowSpeed(q.row[0], vel);
                start[i] = decltype(soft)::value ? pushed[i] : q.impulse[0];
            }
            for (int pass = 0; pass < passes; ++pass)
                for (int i = 0; i < n; ++i) {
                    BlockPoint& q = block.p[i];
                    Lanes& impulse = decltype(soft)::value ? pushed[i] : q.impulse[0];
                    Lanes change;
                    if constexpr (decltype(soft)::value)
                        change = (-q.row[0].mass) * massScale[i] * (speed[i] + bias[i]) -
                                 impulseScale[i] * impulse;
                    else
                        change = (-q.row[0].mass) * (speed[i] + bias[i]);
                    const Lanes total = maxOf(zero, impulse + change); // push only, never pull
                    const Lanes delta = total - impulse;
                    impulse = total;
                    q.maxNormal = maxOf(q.maxNormal, total);
                    for (int j = 0; j < n; ++j) speed[j] = speed[j] + block.couplingOf(j, i) * delta;
                }
            for (int i = 0; i < n; ++i) {
                const BlockPoint& q = block.p[i];
                applyRow(q.row[0], block.invMassA, block.invMassB,
                         (decltype(soft)::value ? pushed[i] : q.impulse[0]) - start[i], vel);
            }
        };
        // The relax starts from velocities this sub-step solved already: one normal pass before friction. The
        // push out moves along the normals only: its velocities are thrown away after the move, and friction
        // there (bounded by the load the normal impulse carries) pushed stacked boxes sideways in every
        // sub-step. Measurements for both: ContactSolver.cpp, before solveContacts.
        if (sweep.pass == Pass::PushOut) {
            for (int i = 0; i < block.points; ++i) pushed[i] = block.p[i].impulse[0];
            solveNormal(std::true_type{}, 2);
        } else {
            solveNormal(std::false_type{}, sweep.pass == Pass::Velocity ? 2 : 1);
            if (block.friction)
                for (int i = 0; i < block.points; ++i) {
                    BlockPoint& q = block.p[i];
                    const Lanes limit = block.frictionCoefficient * q.impulse[0], lower = -limit;
                    for (int r = 1; r < 3; ++r) {
                        const Lanes total =
                            clampOf(q.impulse[r] - rowSpeed(q.row[r], vel) * q.row[r].mass, lower, limit);
                        applyRow(q.row[r], block.invMassA, block.invMassB, total - q.impulse[r], vel);
                        q.impulse[r] = total;
                    }
                }
            solveNormal(std::false_type{}, 1);
        }
        scatterBlock(block, vel, u);
    }
}

void ContactBlocks::saveVelocities() {
    reserveGrowing(m_saved, m_velocity.size());
    m_saved.assign(m_velocity.begin(), m_velocity.end());
}

void ContactBlocks::restoreVelocities() { std::copy(m_saved.begin(), m_saved.end(), m_velocity.begin()); }

} // namespace physics
