// ContactRestitution.cpp - the end of a solve: deep overlaps projected out, and bounces that return e^2 of
// the energy the impact brought, never more.
//
// A contact is found at the step's start, after the body went in during the last step: it approaches at v_n
// with its overlap already d deep, and this step's forces add a_n dt more. Bouncing it at e times that
// approach speed from the surface it is projected to (as the solver did until issue 11) returned the energy
// the body gained falling through d and through this step's gravity: an elastic ball rose 2.9 % above its
// drop height on its first bounce and 45 % after 50. Instead, the energy is followed along the normal under
// the step's constant relative acceleration a_n (uniform gravity: 0 between two bodies, -g against the
// floor):
//   touching speed      v_t^2 = v_0^2 - 2 a_n s_0     (v_0: the approach at the step's start instant, s_0 the
//                                                     separation there, negative when overlapping)
//   leaving speed at s  u^2   = e^2 v_t^2 + 2 a_n s   (s: the separation the solve ends at)
// and the velocity written is u - a_n dt / 2: a body's velocity after a semi-implicit Euler step is its
// velocity half a step earlier than its position (v_k = v(t_k - dt/2)), and that pairing makes
// 1/2 v^2 + g y - g dt v / 2 exactly invariant over free flight. With it, peaks stay at e^2 times the drop
// height (plus g dt^2 / 8 = 0.34 mm at 60 Hz), wherever in the step the impact falls.
// A bouncing pair is projected apart by a hair (SolverSettings::bounceGap), and its points are not kept next
// step: the bounce leaves it in free flight. A residue of overlap would be pushed out next step, adding
// height; and a body in the solve moves by sub-steps, whose gravity drop is (n + 1) / (2n) g dt^2 rather than
// the integrator's g dt^2: a ball that stayed in the solve one step after each bounce rose 1 mm (0.1 %) a
// bounce.
#include "ContactSolver.h"
#include "GrowingStorage.h"
#include "SolverRows.h"

#include <algorithm>
#include <cmath>

namespace physics {

// A bouncing point's touching speed (and what the forces added), worked out after the sub-steps for the
// bouncing points only: what it is made of is as it was when the solve began (the start poses, the forces'
// share dv and dw, the approach speed, the normal row, which stays in the blocks until the next step).
void ContactSolver::prepareBounce(const SolverBody& a, const SolverBody& b, ManifoldPoint& p,
                                  const NormalRow& row, Real dt) {
    p.forceSpeed = p.normal.dot(b.dv - a.dv) + row.armB.dot(b.dw) - row.armA.dot(a.dw);
    const Real startSpeed = p.approachSpeed - 0.5f * p.forceSpeed;
    const Real startSeparation = p.normal.dot(startPoint(b, p.anchorB) - startPoint(a, p.anchorA));
    const Real accel = dt > 0.0f ? p.forceSpeed / dt : 0.0f;
    p.touchSpeed2 = std::max(Real(0), startSpeed * startSpeed - 2.0f * accel * startSeparation);
}

// The points that approached faster than the threshold and pushed in some sub-step bounce (after the
// sub-steps, so a resting contact never bounces).
void ContactSolver::findBounces() {
    const Real threshold = -m_settings.restitutionThreshold;
    m_bouncing.clear();
    for (size_t k = 0; k < m_manifolds.size(); ++k) {
        Manifold& m = m_manifolds[k];
        m.bounces = false;
        for (int i = 0; m.restitution > 0.0f && i < m.count; ++i)
            if (m.points[i].approachSpeed < threshold && m.points[i].maxNormalImpulse > 0.0f) {
                prepareBounce(m_bodies[size_t(m.a)], m_bodies[size_t(m.b)], m.points[i],
                              m_blocks.normalRow(m, i), m_dt);
                m_bouncing.push_back({k, i});
                m.bounces = true;
            }
    }
}

// Each bouncing point leaves at the speed above. The bouncing points are swept several times, alternately
// forward and backward: one sweep over a box's four corners spun a box that landed flat at 4.3 rad/s.
void ContactSolver::applyRestitution() {
    const Real dt = m_dt;
    for (int sweep = 0; sweep < kRestitutionSweeps && !m_bouncing.empty(); ++sweep) {
        for (size_t j = 0; j < m_bouncing.size(); ++j) {
            const auto& [k, i] = m_bouncing[sweep % 2 ? m_bouncing.size() - 1 - j : j];
            Manifold& m = m_manifolds[k];
            ManifoldPoint& p = m.points[i];
            SolverBody &a = m_bodies[m.a], &b = m_bodies[m.b];
            const NormalRow row = m_blocks.normalRow(m, i);
            const Real accel = dt > 0.0f ? p.forceSpeed / dt : 0.0f;
            const Real e = m.restitution;
            const Real leave2 = e * e * p.touchSpeed2 + 2.0f * accel * separation(a, b, p);
            const Real target = std::sqrt(std::max(Real(0), leave2)) - 0.5f * p.forceSpeed;
            Real vn = normalSpeed(a, b, p, row);
            Real total = std::max(Real(0), p.normalImpulse - row.mass * (vn - target));
            applyNormalImpulse(a, b, p, row, total - p.normalImpulse);
            p.normalImpulse = total;
            p.bounced = true;
        }
    }
}

// Overlap deeper than deepOverlap (which resting contacts never reach) comes from a fast body found after it
// went in: pushed out at a capped speed it would bounce from deep inside and lose height, so it is projected
// out at once, moving positions only (a bouncing pair entirely: its bounce accounts for the move). Each
// manifold's two bodies are moved apart along the normal by the deepest point's excess, shared by inverse
// mass; translation alone cannot overshoot the way corner pushes that also turn the body do.
// A pair is projected at most as far as it closed in the step (its approach speed times dt: the overlap a
// late find can explain); deeper overlap that was not flown into (bodies spawned inside each other) is left
// to the push out at its capped speed. Projecting all of it moved bodies of a crowd spawned at one point by
// 7.8 m in one step.
void ContactSolver::projectDeepOverlaps() {
    for (Manifold& m : m_manifolds) {
        m.projectable = 0;
        for (int i = 0; i < m.count; ++i)
            m.projectable = std::max(m.projectable, -m.points[i].approachSpeed * m_dt);
    }
    // Each manifold's deepest overlap when it was last measured, and when (a clock that ticks at every
    // measure and every move); each body's last move. A manifold neither of whose bodies moved since it was
    // measured has the same gaps: it had nothing to project then and has nothing now, and its deepest holds.
    assignGrowing(m_pairDeepest, m_manifolds.size(), 0.0f);
    assignGrowing(m_pairMeasured, m_manifolds.size(), 0u);
    assignGrowing(m_bodyMoved, m_bodies.size(), 0u);
    unsigned clock = 0;
    const auto movedSince = [&](const Manifold& m, size_t k) {
        return m_bodyMoved[size_t(m.a)] > m_pairMeasured[k] || m_bodyMoved[size_t(m.b)] > m_pairMeasured[k];
    };
    const auto measure = [&](const Manifold& m, size_t k, bool fresh, Real allowed) {
        // Fresh: nothing has moved since the last relax sweep measured the gaps at these very poses
        // (ContactBlocks::measureGaps: the same arithmetic, bit for bit with float lanes; a double build's
        // lanes may differ from separation() in the last bit).
        const SolverBody &a = m_bodies[size_t(m.a)], &b = m_bodies[size_t(m.b)];
        const bool measured = fresh && m.block >= 0;
        float deepest = 0;
        Real excess = 0;
        for (int i = 0; i < m.count; ++i) {
            const Real gap = measured ? m.points[i].gap : separation(a, b, m.points[i]);
            deepest = std::max(deepest, float(-gap));
            excess = std::max(excess, -gap - allowed);
        }
        m_pairDeepest[k] = deepest;
        m_pairMeasured[k] = ++clock;
        return excess;
    };
    bool moved = true;
    for (int iteration = 0; moved && iteration < kProjectionIterations; ++iteration) {
        moved = false;
        for (size_t k = 0; k < m_manifolds.size(); ++k) {
            Manifold& m = m_manifolds[k];
            if (iteration > 0 && !movedSince(m, k)) continue;
            const Real allowed = m.bounces ? -m_settings.bounceGap : m_settings.deepOverlap;
            SolverBody &a = m_bodies[size_t(m.a)], &b = m_bodies[size_t(m.b)];
            const bool fresh = m_bodyMoved[size_t(m.a)] == 0 && m_bodyMoved[size_t(m.b)] == 0;
            const Real excess = std::min(measure(m, k, fresh, allowed), m.projectable);
            Real invMass = a.invMass + b.invMass;
            if (excess <= 0.0f || invMass <= 0.0f) continue;
            m.projectable -= excess;
            moved = true;
            Vec3 push = m.points[0].normal * (excess / invMass);
            a.projected = a.projected || a.invMass > 0.0f;
            b.projected = b.projected || b.invMass > 0.0f;
            a.projection -= a.invMass * push;
            b.projection += b.invMass * push;
            a.com -= a.invMass * push;
            a.origin -= a.invMass * push;
            b.com += b.invMass * push;
            b.origin += b.invMass * push;
            ++clock;
            if (a.invMass > 0.0f) m_bodyMoved[size_t(m.a)] = clock; // the static world never moves
            if (b.invMass > 0.0f) m_bodyMoved[size_t(m.b)] = clock;
        }
    }
    // The overlap left where the solve leaves the bodies (restitution moves nothing): the manifolds moved
    // since they were measured are measured again.
    float deepest = 0;
    for (size_t k = 0; k < m_manifolds.size(); ++k) {
        if (movedSince(m_manifolds[k], k)) measure(m_manifolds[k], k, false, 0);
        deepest = std::max(deepest, m_pairDeepest[k]);
    }
    m_maxDepthAfter = deepest;
}

} // namespace physics
