// iFixedUpdater.h - game code called once at the start of every fixed physics step (seed 000's
// IFixedUpdater).
//
// Register with iPhysicsScene::addFixedUpdater. Use it for logic that must run at the physics rate
// (thrusters, AI steering, per-step forces). Removing or deleting bodies, and removing updaters, from inside
// fixedUpdate is safe: the scene defers the actual removal to the end of the step.
#pragma once

class iPhysicsScene;

class iFixedUpdater {
public:
    // dt: the fixed step in seconds.
    virtual void fixedUpdate(iPhysicsScene* scene, float dt) = 0;

protected:
    ~iFixedUpdater() = default; // the game owns its updaters; the scene never deletes them
};
