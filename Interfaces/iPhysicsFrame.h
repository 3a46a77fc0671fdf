// iPhysicsFrame.h - a Frame that owns a rigid body: move it like any frame, and it simulates.
//
// The frame's T follows its body after each scene update. The scene deletes bodies on shutdown but not
// physics frames: the game deletes its PhysicsFrames (which deletes their bodies).
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
};

extern "C" iPhysicsFrame* CreatePhysicsFrame();
