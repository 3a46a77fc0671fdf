// iCollisionListener.h - a listener for collision events, attached to a rigid body.
//
// HitWall is called once per frame for each body a listened-to body is touching. The listener may detach
// itself, delete geometry or remove bodies during the call: those changes take effect safely.
#pragma once

#include "MathDeclarations.h"

class iRigidBody;

class iCollisionListener {
public:
    // other: the body this listener's body hit; hitNormal: unit, world space, points toward other;
    // hitLocation: world-space contact point.
    virtual void HitWall(iRigidBody* other, Vector hitNormal, Vector hitLocation) = 0;
};
