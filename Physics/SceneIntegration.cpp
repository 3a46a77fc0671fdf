// SceneIntegration.cpp - step 6 of a step (PhysicsScene::step): the forces on an awake root and what rides on
// it (its composite), integrated by the game's chosen integrator. A body the contact solver moves takes only
// what the forces did to its velocities (the solver moves it through the sub-steps); a free body is moved
// here.
#include "PhysicsScene.h"

#include "Integrators.h"
#include "MathEigen.h"
#include "RigidBody.h"

#include <cmath>

namespace physics {

void PhysicsScene::integrateComposite(RigidBody* body, float dt) {
    RBDynamics& d = body->getDynamics();
    d.lastVelocity = d.velocity;
    Composite& c = m_composite;
    buildComposite(body, m_byDynamics, m_gravityOn ? toEigen(m_gravity) : Vec3::Zero(), m_lengthUnit,
                   m_dragOn, c);
    if (d.physicsType != PHYS_FixedInSpace) {
        // The cached quaternion is exact; the matrix is only re-read when the game replaced it.
        Quat q = body->ownRotation();
        // Angular velocity and momentum are one state: take the one the game changed (w wins if both); if
        // neither changed but the mass distribution did (attach, detach, new tensor), keep w.
        // The body's own state (its Real values, or the fields the game wrote: RigidBody::OwnState).
        bool reshaped =
            !body->hasComposite || body->compositeMass != c.mass || body->compositeInertia != c.inertia;
        Vec3 omega = body->stateOmega(), momentum = body->stateMomentum();
        if (d.angularVelocity != body->writtenOmega || c.kinematic)
            d.angularMomentum = toVector(momentum = worldInertia(c, q) * omega);
        else if (d.angularMomentum != body->writtenMomentum)
            d.angularVelocity = toVector(omega = worldInverseInertia(c, q) * momentum);
        else if (reshaped)
            d.angularMomentum = toVector(momentum = worldInertia(c, q) * omega);

        // Root fields -> the composite's state about its centre of mass C, integrate, and back.
        Vec3 arm = q * c.rootOffset; // root COM - C, world
        MotionState s{body->statePosition() - arm, body->stateVelocity() - omega.cross(arm), momentum, q};
        const Vec3 v0 = s.v;
        // A body the contact solver moves takes only the change of its velocities from here; when its
        // rotation changes neither, it is not turned here at all (the solver turns it).
        const bool solverMoves = body->solverSlot >= 0 && !c.kinematic;
        integrate(m_integrator, c, s, dt, omega, !(solverMoves && rotationIrrelevant(c)));
        if (c.angularDrag > 0 && !c.kinematic) s.L *= std::exp(-c.angularDrag * dt); // exact decay, any value
        Vec3 omega1 = c.kinematic ? omega : Vec3(worldInverseInertia(c, s.q) * s.L);
        body->forceDv = s.v - v0;
        body->forceDw = omega1 - omega;
        if (solverMoves) {
            m_bodyAccess.setMotion(m_solver.body(body->solverSlot), body, c, s.v, omega1, body->forceDv,
                                   body->forceDw);
        } else {
            Vec3 arm1 = s.q * c.rootOffset;
            body->writePosition(s.x + arm1);
            body->writeVelocity(s.v + omega1.cross(arm1));
            d.angularVelocity = toVector(omega = omega1);
            momentum = c.kinematic ? Vec3(worldInertia(c, s.q) * omega) : s.L;
            d.angularMomentum = toVector(momentum);
            if (!c.rotationLocked) d.orientation = toOrientation(s.q); // locked: the matrix is kept exactly
            body->rotation = s.q;
        }
        body->own.omega = omega;
        body->own.momentum = momentum;
        body->writtenOmega = d.angularVelocity;
        body->writtenMomentum = d.angularMomentum;
        body->writtenOrientation = d.orientation;
        body->hasComposite = true;
        body->compositeMass = c.mass;
        body->compositeInertia = c.inertia;
    }
    // temporalForce and temporalTorque act for one step, on every part.
    for (CompositePart& p : c.parts) p.dyn->temporalForce = p.dyn->temporalTorque = Vector();
}

} // namespace physics
