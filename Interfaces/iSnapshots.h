// iSnapshots.h - saving a scene's or a collision space's whole state and putting it back, so that a bug can
// be reproduced from a given frame: after restoreSnapshot the next steps are bit-identical to the ones that
// followed takeSnapshot.
//
// Not part of the seed's interfaces (a game's stand-in objects need not implement it); the scene made by
// CreatePhysicsScene and the spaces made by CreateSimpleCollisionSpace and CreateOctreeCollisionSpace do,
// reached with snapshotsOf(scene) / snapshotsOf(space).
//
// What is saved is state, not structure: every body's RBDynamics and the simulator's bookkeeping (start and
// interpolation poses, last valid state, sleep timers), the solver's warm-start impulses and kept contact
// points, the islands' memory of moving outsiders, the fixed-step clock (time base and accumulator), and, in
// a scene's snapshot, its collision space's (each geometry's previous pose, the pairs touching at the last
// call, events held). Settings (gravity, step rate, iterations...) and the game's own objects (listeners,
// updaters, generators) are not. A snapshot restores into the object that took it, and only while that
// object has the same members: a body or geometry added, removed, deleted or rebound since makes
// restoreSnapshot refuse (error() says why; nothing changes). Restoring during an update is refused too.
#pragma once

#include "iCollisionSpace.h"
#include "iPhysicsScene.h"

// A saved state; opaque. The game deletes it with Delete() (before or after the object that took it).
class iSnapshot {
public:
    virtual void Delete() const = 0;

protected:
    ~iSnapshot() = default;
};

class iSnapshots {
public:
    // A new snapshot of the current state (taken between updates; nullptr, with error(), during one).
    virtual iSnapshot* takeSnapshot() const = 0;
    // Puts the state of s back; false (with error(), nothing changed) if s is not this object's or its
    // members changed since.
    virtual bool restoreSnapshot(const iSnapshot* s) = 0;

protected:
    ~iSnapshots() = default; // part of a scene or space: Delete() that
};

inline iSnapshots* snapshotsOf(iPhysicsScene* scene) { return dynamic_cast<iSnapshots*>(scene); }
inline iSnapshots* snapshotsOf(iCollisionSpace* space) { return dynamic_cast<iSnapshots*>(space); }
