// iPhysicsSceneHooks.h - where game code plugs into the fixed step: fixed updaters and force generators.
//
// Not part of the seed's iPhysicsScene (a game's stand-in scene need not implement it); the scene made by
// CreatePhysicsScene does, reached with hooksOf(scene). The scene never owns what is registered here.
#pragma once

#include "iPhysicsScene.h"

class iRigidBody;
class iFixedUpdater;
class iForceGenerator;

class iPhysicsSceneHooks {
public:
    // Game code run at the start of every step (iFixedUpdater.h). nullptr or a repeat is refused (false).
    virtual bool addFixedUpdater(iFixedUpdater* u) = 0;
    virtual void removeFixedUpdater(const iFixedUpdater* u) = 0;
    // A state-dependent force on body, evaluated at every integrator stage (iForceGenerator.h). Adding or
    // removing one wakes the body; a sleeping body's generators are not evaluated (a force that changes over
    // time: wake the body, or iRigidBodySwitches::setSleepAllowed(false)).
    virtual bool addForceGenerator(iRigidBody* body, iForceGenerator* g) = 0;
    virtual void removeForceGenerator(const iRigidBody* body, const iForceGenerator* g) = 0;

protected:
    ~iPhysicsSceneHooks() = default; // part of a scene: Delete() the scene
};

// The hooks of a scene made by CreatePhysicsScene; nullptr for a scene that has none.
inline iPhysicsSceneHooks* hooksOf(iPhysicsScene* scene) { return dynamic_cast<iPhysicsSceneHooks*>(scene); }
