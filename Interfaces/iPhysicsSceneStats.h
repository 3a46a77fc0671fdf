// iPhysicsSceneStats.h - what a scene can tell about itself: counts of bodies and steps, penetration.
//
// Not part of the seed's iPhysicsScene (a game's stand-in scene need not implement it); the scene made by
// CreatePhysicsScene does, reached with statsOf(scene). For HUDs, tests and tuning.
#pragma once

#include <cstddef>

#include "iPhysicsScene.h"

class iPhysicsSceneStats {
public:
    // Bodies simulated (removals and deletions requested during a step count until the step ends).
    virtual size_t getBodyCount() const = 0;
    // Moving bodies that are not asleep (fixed ones excluded).
    virtual size_t getAwakeBodyCount() const = 0;
    // Fixed steps taken since creation, and backlog steps dropped by the catch-up cap.
    virtual long long getStepCount() const = 0;
    virtual long long getDroppedStepCount() const = 0;
    // The deepest contact of the last step, before and after the solver's position correction (m).
    virtual float getMaxPenetration() const = 0;
    virtual float getRemainingPenetration() const = 0;

protected:
    ~iPhysicsSceneStats() = default; // part of a scene: Delete() the scene
};

// The counters of a scene made by CreatePhysicsScene; nullptr for a scene that has none.
inline const iPhysicsSceneStats* statsOf(const iPhysicsScene* scene) {
    return dynamic_cast<const iPhysicsSceneStats*>(scene);
}
