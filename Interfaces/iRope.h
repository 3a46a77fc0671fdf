// iRope.h - a rope (seed 000's Rope): a chain of small bodies (its segments) on distance joints that go
// slack but do not stretch, optionally pinned at either end to a body or to the world.
//
// The segments have no collision geometry: the game gives them shapes if the rope is to touch things.
// Delete() deletes the joints and the segments it made. A segment deleted by someone else (its scene's
// Delete(), or the game's) reads as nullptr from then on and is not deleted again.
#pragma once

#include "iRigidBody.h"

class iPhysicsScene;
class iDistanceJoint;

class iRope {
public:
    virtual int getSegmentCount() const = 0;
    virtual iRigidBody* const* getSegments() const = 0; // getSegmentCount() of them, start to end
    virtual iDistanceJoint* getLink(int i) const = 0;   // between segment i and i + 1 (nullptr otherwise)
    // Pins the first (atStart) or last segment to body (nullptr: the world) where that segment is now;
    // a second pin at the same end replaces the first. False with error() when body is one of the rope's.
    virtual bool pin(bool atStart, iRigidBody* body) = 0;
    virtual bool addToScene(iPhysicsScene* scene) = 0;
    virtual void killAll() = 0;
    virtual void Delete() const = 0;

protected:
    virtual ~iRope() = default; // Delete() it
};

// segments bodies of segmentMass kg each, evenly from start to end (world; segments >= 2), each joined to
// the next at their distance apart, not yet in a scene (addToScene). nullptr on bad input, with error().
extern "C" iRope* CreateRope(const Vector& start, const Vector& end, int segments, float segmentMass);
