// iRigidBodyMotion.h - explicit ways to move a simulated body: teleport it, drive it, wake it.
//
// Not part of the seed's iRigidBody (games implement that one); the simulator's bodies provide it, reached
// with motionOf(body) (nullptr for a game's own body class).
//
// Teleport and driven motion are two different things:
//  * a teleport puts the body there: it arrives exactly, nothing between the old and the new place is pushed
//    or hears HitWall (no sweep), velocities are kept, and an overlap where it lands is separated by the
//    ordinary contact resolution at no more than the solver's push-out speed. Writing RBDynamics::position
//    or orientation, or moving the body's frame, is a teleport too (the simulator notices it).
//  * driven motion moves a kinematic body (mass INFINITE_MASS) with a velocity: it sweeps, so it pushes and
//    carries what is in its way and wakes what it touches. moveTo computes that velocity for a target pose.
#pragma once

#include "MathDeclarations.h"
#include "iRigidBody.h"

class iRigidBodyMotion {
public:
    // Puts the body's centre of mass at position with the given orientation (a rotation) at once, and wakes
    // it. Non-finite values or a matrix that is not a rotation are refused with error(); returns false then.
    virtual bool teleport(const Vector& position, const Matrix& orientation) = 0;
    // Drives a kinematic body (INFINITE_MASS) toward a target pose: sets its velocity and angular velocity
    // so that it reaches position (of its centre of mass) and orientation after `seconds` of simulation,
    // and wakes it. It keeps that velocity afterwards: call moveTo every frame to follow a path, or set the
    // velocity to zero to stop. Refused with error() (false) for a body with finite mass, one fixed in space,
    // an attached body, seconds <= 0, or non-finite or non-rotation input.
    virtual bool moveTo(const Vector& position, const Matrix& orientation, float seconds) = 0;
    // Wakes the body (and, at the next step, the bodies resting on it if it moves).
    virtual void wake() = 0;

protected:
    ~iRigidBodyMotion() = default;
};

inline iRigidBodyMotion* motionOf(iRigidBody* body) { return dynamic_cast<iRigidBodyMotion*>(body); }
