// ContinuousStage.cpp - the continuous collision stage of the step (ContinuousStage.h).
#include "ContinuousStage.h"

#include "ContactSolver.h"
#include "Joint.h"
#include "MathBridge.h"
#include "RigidBody.h"
#include "iCollisionGeometry.h"

#include <algorithm>
#include <cmath>

namespace physics {

namespace {
bool joinedWithoutContact(const RigidBody* body, const iRigidBody* other) {
    for (const Joint* j : body->joints)
        if (j->acting() && !j->collideConnected && (j->bodyA() == other || j->bodyB() == other)) return true;
    return false;
}
} // namespace

size_t ContinuousStage::run(const std::vector<RigidBody*>& bodies, iShapeCast* cast) {
    if (!cast) return 0;
    m_putBack.clear();
    m_sweeps.clear();
    m_owners.clear();
    for (RigidBody* b : bodies) {
        const RBDynamics& d = b->getDynamics();
        if (b->dying() || b->pendingRemoval || b->asleep() || d.attachedTo() || immovable(d) ||
            !b->getContinuousCollisionEnabled())
            continue;
        // An unmoved body (a resting one the solver held still) needs no sweep: a shorter batch.
        if (d.position == b->previousPosition() && b->rotation.coeffs() == b->previousRotation().coeffs())
            continue;
        BodySweep s;
        s.body = b;
        // A projection out of an overlap is a correction, not part of the path: the path starts from the
        // start pose moved by it (swept from the start itself, a ball a paddle had overtaken was cast back
        // into the paddle).
        s.startPosition = b->previousPosition() + b->projectedBy;
        s.startOrientation = toOrientation(b->previousRotation());
        m_sweeps.push_back(s);
        m_owners.push_back(b);
    }
    if (m_sweeps.empty() || cast->sweepBodies(m_sweeps.data(), m_sweeps.size()) == 0) return 0;
    size_t moved = 0;
    for (size_t i = 0; i < m_sweeps.size(); ++i) {
        // A body a joint joins without contact is no obstacle (the space does not know joints): a limb swept
        // into the next limb of its ragdoll was put back, parting its joints by the distance.
        BodySweep& s = m_sweeps[i];
        if (s.hit && joinedWithoutContact(m_owners[i], s.hit->getRigidBody())) s.hit = nullptr;
    }
    for (size_t i = 0; i < m_sweeps.size(); ++i) {
        const BodySweep& s = m_sweeps[i];
        if (!s.hit || !(s.fraction < 1.0f)) continue;
        RigidBody* b = m_owners[i];
        RBDynamics& d = b->getDynamics();
        const Vec3 p0 = toEigen(s.startPosition), p1 = toEigen(d.position);
        const Quat q = b->previousRotation().slerp(s.fraction, b->rotation).normalized();
        // At the touch, carried along by what it hit as far as that moved on: put back where the obstacle
        // was at the touch, a ball landing on a sliding box was apart from it again at the next step's
        // detection, so nothing stopped its fall, and it was put back every step, hovering at 11 m/s.
        d.position = toVector(p0 + (p1 - p0) * s.fraction) + s.carried;
        // The velocity it had at that moment: what the forces (gravity) add over the time it loses is not
        // kept, or a body put back every step (turning while it leans on something) gains energy.
        const float lost = 1.0f - s.fraction;
        d.velocity = toVector(toEigen(d.velocity) - lost * b->forceDv);
        d.angularVelocity = toVector(toEigen(d.angularVelocity) - lost * b->forceDw);
        d.orientation = toOrientation(q);
        b->rotation = q;
        b->writtenOrientation = d.orientation;
        // The angular velocity is kept; the next step derives the momentum from it at this orientation.
        b->hasComposite = false;
        m_putBack.push_back(b);
        ++moved;
    }
    closeJoints();
    return moved;
}

namespace {

// A body the joints' closing may move: awake, movable, a root without attachments.
bool projectable(const RigidBody* b) {
    const RBDynamics& d = b->getDynamics();
    return !b->dying() && !b->pendingRemoval && !b->asleep() && !immovable(d) && !d.attachedTo() &&
           !d.firstAttached();
}

// Moves b by the positional impulse `push` (kg m) at world point p, about its centre of mass.
void shove(RigidBody* b, const Vec3& push, const Vec3& p) {
    RBDynamics& d = b->getDynamics();
    const Vec3 com = toEigen(d.position);
    d.position = toVector(com + push / Real(d.mass));
    const Vec3 turn = tensor(d.getWorldInverseInertiaTensor()) * (p - com).cross(push);
    Quat q = b->rotation;
    q.coeffs() += (Quat(0, turn.x(), turn.y(), turn.z()) * q).coeffs() * Real(0.5);
    q.normalize();
    b->rotation = q;
    d.orientation = toOrientation(q);
    b->writtenOrientation = d.orientation;
    b->hasComposite = false;
}

} // namespace

// A body put back leaves the bodies jointed to it where the step took them: a ragdoll's hand put back where
// it touched the floor, its arm went on, and the wrist parted by the rest of the step's motion (5.2 cm as
// the reference game's ragdoll landed; 8.6 cm at the median of twelve thrown ragdolls, 13.7 cm at worst).
// The joints that hold a point together (ball, hinge, fixed; a distance joint beyond its length) are closed
// again by moving positions only: kJointSweeps Gauss-Seidel sweeps of mass-weighted corrections, turning
// bodies as their inertia allows, the put-back bodies held where they were put, so that the limbs above fold
// toward them as they would have had they stopped there (thrown: 1.7 cm at the median, 3.7 at worst; 4
// sweeps 2.6 and 4.6). Velocities are kept, as the put-back bodies keep theirs; the next step's joint rows
// take over from there.
void ContinuousStage::closeJoints() {
    m_closing.clear();
    for (RigidBody* b : m_putBack) b->ccdHeld = true;
    // The joints reachable from a put-back body through movable bodies, each once (from the end walked
    // first), in the order they are reached.
    for (size_t k = 0; k < m_putBack.size(); ++k) {
        RigidBody* body = m_putBack[k];
        body->ccdWalked = true;
        for (Joint* j : body->joints) {
            RigidBody* other = j->bodyA() == body ? j->bodyB() : j->bodyA();
            if (!j->acting() || !std::isfinite(j->reach()) || (other && other->ccdWalked)) continue;
            m_closing.push_back(j);
            if (other && projectable(other) && !other->ccdHeld && !other->ccdQueued) {
                other->ccdQueued = true;
                m_putBack.push_back(other); // walked for its joints, not held
            }
        }
    }
    for (int sweep = 0; sweep < kJointSweeps && !m_closing.empty(); ++sweep)
        for (Joint* j : m_closing) {
            RigidBody *a = j->bodyA(), *b = j->bodyB();
            JointFrame fa, fb;
            j->worldFrames(fa, fb); // at the poses now
            const Vec3 pa = fa.point, pb = fb.point, e = pb - pa;
            const Real length = e.norm(), error = length - Real(j->reach());
            if (!(error > kJointSlop)) continue;
            const Vec3 n = e / length;
            // A put-back body stays where it was put, unless the joint joins two (each put back to its own
            // touch: the ragdoll's forearm and upper arm, 2.2 cm apart after 16 sweeps when both held).
            const bool bothHeld = a && b && a->ccdHeld && b->ccdHeld;
            auto weight = [&](RigidBody* x, const Vec3& p) -> Real {
                if (!x || !projectable(x) || (x->ccdHeld && !bothHeld)) return 0;
                const RBDynamics& d = x->getDynamics();
                const Vec3 arm = (p - toEigen(d.position)).cross(n);
                return Real(1) / Real(d.mass) + arm.dot(tensor(d.getWorldInverseInertiaTensor()) * arm);
            };
            const Real wa = weight(a, pa), wb = weight(b, pb);
            if (!(wa + wb > 0)) continue;
            const Vec3 push = n * (error / (wa + wb));
            if (wa > 0) shove(a, push, pa);
            if (wb > 0) shove(b, -push, pb);
        }
    for (RigidBody* b : m_putBack) b->ccdHeld = b->ccdWalked = b->ccdQueued = false;
    m_putBack.clear();
}

} // namespace physics
