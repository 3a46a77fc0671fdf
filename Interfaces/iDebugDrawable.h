// iDebugDrawable.h - something of the engine that can draw itself through a game's iDebugDraw: the
// collision space (its geometry, bounds and contacts) and the physics scene (body centres and axes,
// sleeping, islands; it hands the shapes to its space).
//
// Not part of the seed's iCollisionSpace or iPhysicsScene (a game's own space or scene need not implement
// it); the simple and octree spaces and the scene made by CreatePhysicsScene do, reached with
// debugDrawOf(space) or debugDrawOf(scene). Drawing reads the current state and changes nothing: call it
// after physicsScene->update(now), once a frame or when a key is held.
#pragma once

#include "iDebugDraw.h"

class iDebugDrawable {
public:
    // Draws what flags (DebugDrawFlag values or'ed together) ask for into out.
    virtual void debugDraw(iDebugDraw& out, unsigned flags = DEBUGDRAW_Default) const = 0;

protected:
    ~iDebugDrawable() = default; // part of a space or scene: Delete() that
};

// The drawing of a space or scene (an iCollisionSpace* or iPhysicsScene*) that can draw itself; nullptr for
// one that cannot. A cross-cast to this public interface, not to the engine's classes, so that neither
// module needs the other's; a template so that this header includes neither the space's header nor the
// scene's (the collision-only and sim-only packages carry only their own).
template <class SpaceOrScene> const iDebugDrawable* debugDrawOf(const SpaceOrScene* spaceOrScene) {
    return dynamic_cast<const iDebugDrawable*>(spaceOrScene);
}
