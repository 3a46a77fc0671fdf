// iCollisionEvents.h - when a collision space calls HitWall: per populateContactList call, or held and
// delivered once per frame.
//
// Not part of the seed's iCollisionSpace (a game's own space need not implement it); the simple space does,
// reached with eventsOf(space). By default a space calls HitWall at the end of every populateContactList
// (the collision-only route: the game calls it once a frame). A physics scene steps several times a frame,
// or none, and the seed promises HitWall "every frame that two objects are colliding": the scene holds the
// events, and after the steps of an update() delivers them, once per touching body pair.
//
// Either way a pair of bodies that stopped being tested because both rest (sleeping or fixed, and not moved)
// keeps being reported from its last contact for as long as both rest: sleeping never hides a contact.
#pragma once

#include "iCollisionSpace.h"

class iCollisionEvents {
public:
    // hold = true: populateContactList gathers touching pairs instead of calling HitWall.
    virtual void holdEvents(bool hold) = 0;
    // Calls HitWall once per body pair (on each side) that touched in any populateContactList since the
    // last delivery or still touches now. Listeners may do here what they may do in populateContactList.
    virtual void deliverEvents() = 0;

protected:
    ~iCollisionEvents() = default;
};

inline iCollisionEvents* eventsOf(iCollisionSpace* space) { return dynamic_cast<iCollisionEvents*>(space); }
