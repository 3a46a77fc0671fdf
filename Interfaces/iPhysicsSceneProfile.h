// iPhysicsSceneProfile.h - where a scene's time went in its last update(), phase by phase, with the counts
// that explain it (bodies, awake bodies, contacts, touching pairs, solver rows).
//
// Not part of the seed's iPhysicsScene (a game's stand-in scene need not implement it); the scene made by
// CreatePhysicsScene does, reached with profileOf(scene). Times are wall-clock seconds summed over the
// update's steps: the update timed by std::chrono's steady clock, its phases by the CPU's time-stamp counter
// where it has one (x86), each phase its share of the update's time. Reading them costs nothing; taking them
// costs about 0.15 us a step (a two-body step measured 0.18 us faster than with the steady clock read for
// every phase, which took 0.3 us).
#pragma once

#include <cstddef>

#include "iPhysicsScene.h"

struct PhysicsProfile {
    // Seconds in each phase of the steps of the last update() that stepped, in step order.
    double updaters = 0;    // fixed updaters (game code)
    double edits = 0;       // taking in the game's edits, validating them, recording the start poses
    double collision = 0;   // the collision space finding contacts (and its listeners, if not held)
    double islands = 0;     // islands of touching bodies, waking
    double integration = 0; // forces and free bodies' motion (force generators run here)
    double solver = 0;      // collecting manifolds and the sub-stepped contact solve
    double continuous = 0;  // the continuous collision stage (sweeps)
    double sleeping = 0;    // validation after the step, sleeping, deferred removals
    double events = 0;      // HitWall delivery after the steps (listeners: game code)
    double total = 0;       // the whole update() call
    int steps = 0;          // fixed steps the update took
    // Counts at the end of the update's last step.
    size_t bodies = 0, awakeBodies = 0;
    size_t contacts = 0;      // contact points the space reported
    size_t touchingPairs = 0; // geometry pairs in the solver (manifolds, kept ones included)
    size_t solverRows = 0;    // constraint rows solved (3 per contact point: normal and two friction)
};

class iPhysicsSceneProfile {
public:
    // The last update() that took at least one step (an update between two steps leaves it as it was).
    virtual const PhysicsProfile& getProfile() const = 0;

protected:
    ~iPhysicsSceneProfile() = default; // part of a scene: Delete() the scene
};

// The profile of a scene made by CreatePhysicsScene; nullptr for a scene that has none.
inline const iPhysicsSceneProfile* profileOf(const iPhysicsScene* scene) {
    return dynamic_cast<const iPhysicsSceneProfile*>(scene);
}
