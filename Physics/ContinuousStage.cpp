// ContinuousStage.cpp - the continuous collision stage of the step (ContinuousStage.h).
#include "ContinuousStage.h"

#include "ContactSolver.h"
#include "Joint.h"
#include "JointClosing.h"
#include "MathBridge.h"
#include "RigidBody.h"
#include "iCollisionGeometry.h"

namespace physics {

namespace {
bool joinedWithoutContact(const RigidBody* body, const iRigidBody* other) {
    for (const Joint* j : body->joints)
        if (j->acting() && !j->collideConnected && (j->bodyA() == other || j->bodyB() == other)) return true;
    return false;
}
} // namespace

size_t ContinuousStage::run(const std::vector<RigidBody*>& bodies, iShapeCast* cast, JointClosing& closing) {
    if (!cast) return 0;
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
        BodySweep& s = m_sweeps.emplace_back(); // in place (a copy from the stack stalled on its stores)
        s.body = b;
        // A projection out of an overlap is a correction, not part of the path: the path starts from the
        // start pose moved by it (swept from the start itself, a ball a paddle had overtaken was cast back
        // into the paddle).
        s.startPosition = b->previousPosition() + b->projectedBy;
        s.startOrientation = toOrientation(b->previousRotation());
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
        closing.add(b, true);
        ++moved;
    }
    return moved;
}

} // namespace physics
