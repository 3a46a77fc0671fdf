// iPhysicsScene.h - the interface to the physics coordinator that advances every rigid body each frame.
//
// The Engine creates it (CreatePhysicsScene) and calls update(now) once a frame, before design->update(now).
// `now` is engine time in milliseconds (UNITS_PER_SEC). The scene advances in fixed steps and interpolates
// the drawn frames between the last two steps.
//
// Time (update): the first update after creation, restore(now) or reset(now) only sets the time base. Each
// later update adds (now - last now) to an accumulator and takes as many fixed steps (1/stepRate s) as it
// holds, at most maxStepsPerUpdate; when that cap is hit the rest of the backlog is dropped, so after a long
// stall the game slows down instead of spiralling into ever longer frames. A `now` equal to the last one
// integrates nothing; a `now` smaller than the last one integrates nothing and becomes the new time base (the
// clock was reset). Between updates while suspended nothing is integrated; restore(now) resumes from `now`
// with no jump. After stepping, each body's frame gets T interpolated between the previous and the current
// step (alpha = leftover time / step): drawing is smooth and one step behind the simulation. The first time
// the dropped steps add up to a second of simulated time (stepRate steps), error() reports it, once.
//
// The interface is exactly the seed's, so a game's own stand-in scene implements only these. What the
// simulator adds (knobs, game hooks, counters) lives on interfaces of its own that the scene made by
// CreatePhysicsScene also implements: iPhysicsSceneSettings.h, iPhysicsSceneHooks.h, iPhysicsSceneStats.h.
#pragma once

class iRigidBody;
class iContext;
class iCollisionSpace;

class iPhysicsScene {
public:
    // initialization functions
    // Adds a body made by CreateRigidBody (or a PhysicsFrame's). nullptr, a body already in a scene and a
    // foreign iRigidBody implementation are refused with error() and return false. A foreign body (a game's
    // own iRigidBody) whose geometry is in this scene's space is an immovable obstacle: bodies bounce off it.
    virtual bool add(iRigidBody* o) = 0;
    // Sets the default collision space for geometries created from now on, and the space this scene
    // collides its bodies in. Deleting that space later is safe: the scene forgets it
    // (collisionSpaceDestroyed, iCollisionSpace.h).
    virtual void setNewGlobalCollisionSpace(iCollisionSpace* cs) = 0;
    // Resumes after suspend(): `now` becomes the time base, nothing is integrated for the time in between.
    virtual void restore(int now) = 0;
    // execution functions
    // Called from inside an update (a fixed updater, force generator or listener of any scene): refused
    // with error(). Deletions made from those callbacks wait for the end of the step (bodies) or the update
    // (scenes), whichever scene they belong to.
    virtual void update(int now) = 0;
    // termination functions
    // Re-bases time at `now` (as restore) and drops the accumulated partial step; bodies are kept.
    virtual void reset(int now) = 0;
    // Stops integrating until restore(now).
    virtual void suspend() const = 0;
    // Releases device resources: the simulator has none, so it does nothing.
    virtual void release() const = 0;
    // Stops simulating o (deferred to the end of the step when called during update). o is not deleted.
    virtual void remove(const iRigidBody* o) = 0;
    // Deletes this scene and every rigid body still in it, except bodies owned by a PhysicsFrame: those are
    // only removed (the game deletes its PhysicsFrames, which delete their bodies).
    virtual void Delete() const = 0;

protected:
    // Not deleted through the interface: call Delete().
    ~iPhysicsScene() = default;
};

// Creates a scene and makes it the active one (the one CreateRigidBody adds to). c is the engine's context,
// accepted for the seed's signature and not read (a course framework's iContext has its own keys): set the
// scene's knobs through settingsOf(scene). c may be nullptr.
extern "C" iPhysicsScene* CreatePhysicsScene(iContext* c);
