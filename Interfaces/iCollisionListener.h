// iCollisionListener.h - a listener for collision events, attached to a rigid body.
//
// HitWall is called for each body a listened-to body is touching: once per frame when a physics scene uses
// the space (after the steps of each update(), iCollisionEvents.h), otherwise once per populateContactList
// call after the contact list is built. Two bodies that rest against each other (asleep or fixed) go on
// being reported from their last contact. The listener may detach itself or other listeners, remove or delete
// geometry, or delete bodies during the call: those changes take effect safely (a body deleted during the
// calls gets no further calls; contacts of removed/deleted geometry or dead bodies are dropped from the
// contact list).
#pragma once

#include "MathDeclarations.h"

class iRigidBody;

class iCollisionListener {
public:
    // other: the body this listener's body hit (nullptr for a plane that has no body); hitNormal: unit,
    // world space, points toward other; hitLocation: world-space contact point (for several contact points,
    // their average: the centre of the overlap area).
    virtual void HitWall(iRigidBody* other, Vector hitNormal, Vector hitLocation) = 0;

protected:
    ~iCollisionListener() = default; // the game owns its listeners; bodies never delete them
};
