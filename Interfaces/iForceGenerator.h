// iForceGenerator.h - a state-dependent force (spring, thruster, field) the integrator evaluates per stage.
//
// A force written into RBDynamics::force is constant over a step. A force that depends on where the body is
// or how fast it moves must be re-evaluated at every stage of the integrator (four times a step for RK4,
// twice for velocity Verlet), or the integrator degrades to first order. Register one with
// iPhysicsScene::addForceGenerator(body, generator); the scene calls addForces with the body's trial state.
#pragma once

#include "MathDeclarations.h"

class iRigidBody;

// A trial state of one body during a step, all in world space.
struct RigidBodyState {
    Vector position;        // centre of mass (m)
    Vector velocity;        // velocity of the centre of mass (m/s)
    Matrix orientation;     // body local -> world rotation, orthonormal
    Vector angularVelocity; // rad/s
    float time;             // seconds since the start of the step (0 <= time <= dt)
};

class iForceGenerator {
public:
    // Adds this generator's force (N, through the body's centre of mass) and torque (N m, about it) for body
    // in state s. Must not change s or the body: it may be called several times a step with trial states.
    virtual void addForces(const iRigidBody* body, const RigidBodyState& s, Vector& force,
                           Vector& torque) = 0;

protected:
    ~iForceGenerator() = default; // the game owns its generators; the scene never deletes them
};
