// ContactSolver.cpp - the sub-stepped solve: soft contacts, Coulomb friction, warm starting, restitution.
#include "ContactSolver.h"

#include "MathEigen.h"
#include "RBDynamics.h"
#include "iCollisionSpace.h"

#include <algorithm>
#include <cmath>

namespace physics {

float combine(CombineRule rule, float a, float b) {
    switch (rule) {
    case COMBINE_Sum:
        return a + b;
    case COMBINE_Average:
        return 0.5f * (a + b);
    case COMBINE_Max:
        return std::max(a, b);
    case COMBINE_Min:
        return std::min(a, b);
    case COMBINE_Product:
        return a * b;
    case COMBINE_GeometricMean:
        return std::sqrt(std::max(0.0f, a * b));
    }
    return a + b;
}

bool immovable(const RBDynamics& d) {
    return d.physicsType == PHYS_FixedInSpace || !(d.mass < INFINITE_MASS) || !(d.mass > 0.0f);
}

namespace {

bool movable(const SolverBody& b) { return b.root && b.invMass > 0.0f; }

// Row 0 is the normal, rows 1 and 2 the tangents; the row is a template argument so that the hot loops
// compile without a branch per impulse.
template <int Row> const Vec3& direction(const ContactPoint& p) {
    if constexpr (Row == 0)
        return p.normal;
    else
        return p.tangent[Row - 1];
}

// The relative velocity of b against a at the point, along a row's direction.
template <int Row>
inline float relativeSpeed(const SolverBody& a, const SolverBody& b, const ContactPoint& p) {
    return direction<Row>(p).dot(b.v - a.v) + p.armB[Row].dot(b.w) - p.armA[Row].dot(a.w);
}

// An impulse along a row's direction: on b, and its opposite on a.
template <int Row>
inline void applyImpulse(SolverBody& a, SolverBody& b, const ContactPoint& p, float impulse) {
    const Vec3& d = direction<Row>(p);
    a.v -= (a.invMass * impulse) * d;
    a.w -= impulse * p.turnA[Row];
    b.v += (b.invMass * impulse) * d;
    b.w += impulse * p.turnB[Row];
}

// Where an anchor is now (the static world's anchors are world points).
Vec3 worldPoint(const SolverBody& b, const Vec3& anchor) {
    return b.root ? Vec3(b.rotation * anchor + b.origin) : anchor;
}

// Moves b by dp and turns it about its centre of mass by the rotation vector dtheta (first order).
void turnAndMove(SolverBody& b, const Vec3& dp, const Vec3& dtheta) {
    Vec3 offset = b.rotation.conjugate() * (b.origin - b.com); // the root's origin, body axes
    Quat spin(0.0f, 0.5f * dtheta.x(), 0.5f * dtheta.y(), 0.5f * dtheta.z());
    b.rotation.coeffs() += (spin * b.rotation).coeffs();
    b.rotation.normalize();
    b.com += dp;
    b.origin = b.com + b.rotation * offset;
}

} // namespace

// --- default body access: one RBDynamics, no attachments ---
SolverBody SolverBodyAccess::load(RBDynamics* root) const {
    SolverBody b;
    b.root = root;
    if (!root) return b; // the static world
    b.origin = b.startOrigin = b.com = toEigen(root->position);
    b.rotation = b.startRotation = toQuat(root->orientation);
    b.v = toEigen(root->velocity);
    b.w = toEigen(root->angularVelocity);
    if (!immovable(*root)) {
        Mat3 r = b.rotation.toRotationMatrix();
        b.dv = m_forceVelocity;
        b.invMass = 1.0f / root->mass;
        b.invInertia = r * tensor(root->getInverseInertiaTensor()) * r.transpose();
    }
    return b;
}

void SolverBodyAccess::storeVelocity(const SolverBody& b) const {
    if (!movable(b)) return; // immovable bodies keep their own (kinematic) velocity
    Mat3 r = b.rotation.toRotationMatrix();
    b.root->velocity = toVector(b.v);
    b.root->angularVelocity = toVector(b.w);
    b.root->angularMomentum = toVector(r * tensor(b.root->getInertiaTensor()) * r.transpose() * b.w);
}

void SolverBodyAccess::storePose(const SolverBody& b) const {
    b.root->position = toVector(b.origin);
    b.root->orientation = toOrientation(b.rotation);
}

// --- the solve, top to bottom ---
void ContactSolver::solve(const CollisionContact* contacts, size_t count, float dt,
                          const SolverBodyAccess& access) {
    buildManifolds(contacts, count, access);
    matchPreviousImpulses();
    prepare();
    startBodies();
    const int n = std::max(1, m_settings.substeps);
    const float h = dt / float(n);
    // The soft contact (a damped spring in impulse form, Catto's "Soft Step"): stiff, but never stiffer than
    // a quarter of the sub-step rate can follow.
    const float omega = 2.0f * 3.14159265f * std::min(m_settings.contactHertz, 0.25f / h);
    const float a1 = 2.0f * m_settings.dampingRatio + h * omega, a2 = h * omega * a1, a3 = 1.0f / (1.0f + a2);
    m_biasRate = omega / a1;
    m_massScale = a2 * a3;
    m_impulseScale = a3;
    for (int i = 0; i < n; ++i) {
        addForces(1.0f / float(n));
        warmStart(i == 0);
        solveContacts(h, true);
        moveBodies(h);
        solveContacts(h, false); // relax: the push out's velocity is not kept
    }
    applyRestitution();
    projectDeepOverlaps();
    for (const SolverBody& b : m_bodies) {
        access.storeVelocity(b);
        if (movable(b)) access.storePose(b);
    }
    measureOverlap();
    storeImpulses();
}

void ContactSolver::prepare() {
    for (Manifold& m : m_manifolds) {
        const SolverBody &a = m_bodies[m.a], &b = m_bodies[m.b];
        for (int i = 0; i < m.count; ++i) {
            ContactPoint& p = m.points[i];
            float masses[3];
            for (int row = 0; row < 3; ++row) {
                const Vec3& d = row == 0 ? p.normal : p.tangent[row - 1];
                p.armA[row] = p.rA.cross(d);
                p.armB[row] = p.rB.cross(d);
                p.turnA[row] = a.invInertia * p.armA[row];
                p.turnB[row] = b.invInertia * p.armB[row];
                float k =
                    a.invMass + b.invMass + p.armA[row].dot(p.turnA[row]) + p.armB[row].dot(p.turnB[row]);
                masses[row] = k > 0.0f ? 1.0f / k : 0.0f;
            }
            p.normalMass = masses[0];
            p.tangentMass[0] = masses[1];
            p.tangentMass[1] = masses[2];
            p.approachSpeed = relativeSpeed<0>(a, b, p);
            p.maxNormalImpulse = 0;
        }
    }
}

// Movable bodies go back to where the step started, with the velocities they had before the forces acted.
void ContactSolver::startBodies() {
    for (SolverBody& b : m_bodies) {
        if (!movable(b)) continue;
        b.origin = b.startOrigin;
        b.rotation = b.startRotation;
        b.v -= b.dv;
        b.w -= b.dw;
    }
}

void ContactSolver::addForces(float share) {
    for (SolverBody& b : m_bodies) {
        if (!movable(b)) continue;
        b.v += share * b.dv;
        b.w += share * b.dw;
    }
}

// Every sub-step starts from the impulses the last one ended with (the first from last step's): a resting
// contact needs about the same each sub-step. An impact does not recur: a point that approached faster than
// the restitution threshold starts each later sub-step from nothing, or its impact impulse would be applied
// again and bound friction by it (a box landing at 4 m/s while sliding hopped 0.06 m/s and lost 7 % more
// slide than Coulomb's law allows).
void ContactSolver::warmStart(bool firstSubstep) {
    const float impact = -m_settings.restitutionThreshold;
    for (Manifold& m : m_manifolds) {
        SolverBody &a = m_bodies[m.a], &b = m_bodies[m.b];
        for (int i = 0; i < m.count; ++i) {
            ContactPoint& p = m.points[i];
            if (!firstSubstep && p.approachSpeed < impact) {
                p.normalImpulse = p.tangentImpulse[0] = p.tangentImpulse[1] = 0;
                continue;
            }
            applyImpulse<0>(a, b, p, p.normalImpulse);
            applyImpulse<1>(a, b, p, p.tangentImpulse[0]);
            applyImpulse<2>(a, b, p, p.tangentImpulse[1]);
        }
    }
}

// One sweep over the manifolds. Per manifold: the normal impulses twice, then friction bounded by mu times
// the normal impulses just found, then the normal impulses once more.
//  - Friction bounded by a stale normal impulse would take a warm-started impact's worth again in every
//    sub-step.
//  - Friction last would leave the stack's normal constraints unmet (at 4 sub-steps the 210-box pyramid never
//    came to rest, 0.5 J after 10 s; with a normal pass after friction it sleeps within 2 s).
//  - One normal pass before friction leaves a box that landed flat turning (its first corners are solved
//    first), and friction answers the turning: it bounced off sideways, 0.15 rad/s and 20 cm in 4 s. After
//    two passes, 0.001 rad/s and 1 cm.
// pushOut: overlap is pushed out softly; otherwise (relax) only approach is stopped.
void ContactSolver::solveContacts(float h, bool pushOut) {
    for (Manifold& m : m_manifolds) {
        // Positions do not change within a sweep: each point's target is worked out once.
        const SolverBody &a = m_bodies[m.a], &b = m_bodies[m.b];
        Target target[4];
        for (int i = 0; i < m.count; ++i) {
            const ContactPoint& p = m.points[i];
            float separation = p.normal.dot(worldPoint(b, p.anchorB) - worldPoint(a, p.anchorA));
            if (separation > 0.0f) {
                target[i].bias = separation / h; // apart: may close the gap within the sub-step, no more
            } else if (separation > -m_settings.touchOverlap &&
                       relativeSpeed<0>(a, b, p) < -m_settings.restitutionThreshold) {
                // An impact at a touch (where the continuous stage leaves a fast body) is stopped rigidly:
                // a soft stop lets a few % of the approach through, metres in a sub-step at 10^4 m/s.
            } else if (pushOut) {
                target[i] = {std::max(m_biasRate * separation, -m_settings.maxPushSpeed), m_massScale,
                             m_impulseScale};
            }
        }
        solveNormal(m, target);
        solveNormal(m, target);
        solveFriction(m);
        solveNormal(m, target);
    }
}

void ContactSolver::solveNormal(Manifold& m, const Target* target) {
    SolverBody &a = m_bodies[m.a], &b = m_bodies[m.b];
    for (int i = 0; i < m.count; ++i) {
        ContactPoint& p = m.points[i];
        const Target& t = target[i];
        float vn = relativeSpeed<0>(a, b, p);
        float change = -p.normalMass * t.massScale * (vn + t.bias) - t.impulseScale * p.normalImpulse;
        float total = std::max(0.0f, p.normalImpulse + change); // push only, never pull
        applyImpulse<0>(a, b, p, total - p.normalImpulse);
        p.normalImpulse = total;
        p.maxNormalImpulse = std::max(p.maxNormalImpulse, total);
    }
}

void ContactSolver::solveFriction(Manifold& m) {
    SolverBody &a = m_bodies[m.a], &b = m_bodies[m.b];
    for (int i = 0; i < m.count; ++i) {
        ContactPoint& p = m.points[i];
        const float limit = m.friction * p.normalImpulse; // Coulomb's cone as a box
        float total =
            std::clamp(p.tangentImpulse[0] - relativeSpeed<1>(a, b, p) * p.tangentMass[0], -limit, limit);
        applyImpulse<1>(a, b, p, total - p.tangentImpulse[0]);
        p.tangentImpulse[0] = total;
        total = std::clamp(p.tangentImpulse[1] - relativeSpeed<2>(a, b, p) * p.tangentMass[1], -limit, limit);
        applyImpulse<2>(a, b, p, total - p.tangentImpulse[1]);
        p.tangentImpulse[1] = total;
    }
}

// Semi-implicit Euler over h: the frame turns about the centre of mass.
void ContactSolver::moveBodies(float h) {
    for (SolverBody& b : m_bodies)
        if (movable(b)) turnAndMove(b, h * b.v, h * b.w);
}

// A point that approached faster than the threshold and pushed in some sub-step leaves at e times its
// approach speed (after the sub-steps, so a resting contact never bounces). The bouncing points are swept
// several times, alternately forward and backward: one sweep over a box's four corners spun a box that
// landed flat at 4.3 rad/s.
void ContactSolver::applyRestitution() {
    const float threshold = -m_settings.restitutionThreshold;
    m_bouncing.clear();
    for (size_t k = 0; k < m_manifolds.size(); ++k) {
        const Manifold& m = m_manifolds[k];
        for (int i = 0; m.restitution > 0.0f && i < m.count; ++i)
            if (m.points[i].approachSpeed < threshold && m.points[i].maxNormalImpulse > 0.0f)
                m_bouncing.push_back({k, i});
    }
    for (int sweep = 0; sweep < kRestitutionSweeps && !m_bouncing.empty(); ++sweep) {
        for (size_t j = 0; j < m_bouncing.size(); ++j) {
            const auto& [k, i] = m_bouncing[sweep % 2 ? m_bouncing.size() - 1 - j : j];
            Manifold& m = m_manifolds[k];
            ContactPoint& p = m.points[i];
            SolverBody &a = m_bodies[m.a], &b = m_bodies[m.b];
            float vn = relativeSpeed<0>(a, b, p);
            float total =
                std::max(0.0f, p.normalImpulse - p.normalMass * (vn + m.restitution * p.approachSpeed));
            applyImpulse<0>(a, b, p, total - p.normalImpulse);
            p.normalImpulse = total;
        }
    }
}

// Overlap deeper than deepOverlap (which resting contacts never reach) comes from a fast body found after it
// went in: pushed out at a capped speed it would bounce from deep inside and lose height, so it is projected
// out at once, moving positions only. Each manifold's two bodies are moved apart along the normal by the
// deepest point's excess, shared by inverse mass; translation alone cannot overshoot the way corner pushes
// that also turn the body do.
void ContactSolver::projectDeepOverlaps() {
    const float allowed = m_settings.deepOverlap;
    bool moved = true;
    for (int iteration = 0; moved && iteration < kProjectionIterations; ++iteration) {
        moved = false;
        for (Manifold& m : m_manifolds) {
            SolverBody &a = m_bodies[m.a], &b = m_bodies[m.b];
            float excess = 0;
            for (int i = 0; i < m.count; ++i) {
                const ContactPoint& p = m.points[i];
                Vec3 gap = worldPoint(b, p.anchorB) - worldPoint(a, p.anchorA);
                excess = std::max(excess, -p.normal.dot(gap) - allowed);
            }
            float invMass = a.invMass + b.invMass;
            if (excess <= 0.0f || invMass <= 0.0f) continue;
            moved = true;
            Vec3 push = m.points[0].normal * (excess / invMass);
            a.com -= a.invMass * push;
            a.origin -= a.invMass * push;
            b.com += b.invMass * push;
            b.origin += b.invMass * push;
        }
    }
}

void ContactSolver::measureOverlap() {
    m_maxDepthAfter = 0;
    for (const Manifold& m : m_manifolds)
        for (int i = 0; i < m.count; ++i) {
            const ContactPoint& p = m.points[i];
            Vec3 gap = worldPoint(m_bodies[m.b], p.anchorB) - worldPoint(m_bodies[m.a], p.anchorA);
            m_maxDepthAfter = std::max(m_maxDepthAfter, -p.normal.dot(gap));
        }
}

void ContactSolver::clear() {
    m_last.clear();
    m_lastIndex.clear();
    m_manifolds.clear();
    m_bodies.clear();
    m_bodyIndex.clear();
}

} // namespace physics
