// iPhysicsFrame.h - a Frame that owns a rigid body: move it like any frame, and it simulates.
//
// The frame's T follows its body after each scene update; moving the frame yourself (translate, rotate...)
// teleports the body there at the next update (velocities kept). Ownership: the PhysicsFrame owns its body.
// The scene deletes bodies on shutdown but not physics frames' bodies: deleting the scene first only takes
// the body out of the scene (the PhysicsFrame keeps working, unsimulated); Delete() on getRB() is refused.
// The game deletes its PhysicsFrames, which deletes their bodies (safe inside update: deferred).
// clone() makes a new frame at the body's pose owning a copy of the body (dynamics, listeners) in the same
// scene. attachTo(another PhysicsFrame) also attaches the bodies (one composite); any other parent detaches.
#pragma once

#include "Frame.h"

class iRigidBody;
struct RBDynamics;

class iPhysicsFrame : public Frame {
public:
    virtual iRigidBody* getRB() const = 0;
    virtual RBDynamics* getDynamics() const = 0;
    virtual iPhysicsFrame* clone() const = 0;
    // termination functions
    virtual void suspend() const = 0;
    virtual void release() const = 0;
    virtual void Delete() const = 0;

protected:
    // Not deleted through the interface: call Delete() (it deletes the body too).
    ~iPhysicsFrame() = default;
};

extern "C" iPhysicsFrame* CreatePhysicsFrame();
