// iPhysicsScene.h - the interface to the physics coordinator that advances every rigid body each frame.
//
// The Engine creates it (CreatePhysicsScene) and calls update(now) once a frame, before design->update(now).
// `now` is engine time in milliseconds (UNITS_PER_SEC). The scene advances in fixed steps and interpolates
// the drawn frames between the last two steps.
#pragma once

class iRigidBody;
class iContext;
class iCollisionSpace;

class iPhysicsScene {
public:
    // initialization functions
    virtual bool add(iRigidBody* o) = 0;
    // Sets the default collision space for geometries created from now on, and the space this scene
    // collides its bodies in.
    virtual void setNewGlobalCollisionSpace(iCollisionSpace* cs) = 0;
    virtual void restore(int now) = 0;
    // execution functions
    virtual void update(int now) = 0;
    // termination functions
    virtual void reset(int now) = 0;
    virtual void suspend() const = 0;
    virtual void release() const = 0;
    virtual void remove(const iRigidBody* o) = 0;
    // Deletes this scene and every rigid body still in it.
    virtual void Delete() const = 0;
};

// Creates a scene and makes it the active one (the one CreateRigidBody adds to). c may be nullptr.
extern "C" iPhysicsScene* CreatePhysicsScene(iContext* c);
