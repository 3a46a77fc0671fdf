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
#pragma once

#include "MathDeclarations.h"
#include "iContactSettings.h"
#include "iPhysicsSettings.h"

#include <cstddef>

class iRigidBody;
class iContext;
class iCollisionSpace;
class iFixedUpdater;
class iForceGenerator;

class iPhysicsScene {
public:
    // initialization functions
    // Adds a body made by CreateRigidBody (or a PhysicsFrame's). nullptr, a body already in a scene and a
    // foreign iRigidBody implementation are refused with error() and return false. A foreign body (a game's
    // own iRigidBody) whose geometry is in this scene's space is an immovable obstacle: bodies bounce off it.
    virtual bool add(iRigidBody* o) = 0;
    // Sets the default collision space for geometries created from now on, and the space this scene
    // collides its bodies in.
    virtual void setNewGlobalCollisionSpace(iCollisionSpace* cs) = 0;
    // Resumes after suspend(): `now` becomes the time base, nothing is integrated for the time in between.
    virtual void restore(int now) = 0;
    // execution functions
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

    // --- settings and extensions (not in the seed). Non-pure so that a game's own stand-in scenes need not
    // implement them; the simulator's scene overrides every one. Setters refuse invalid values with error()
    // and return false (the stand-in defaults support nothing and return false). ---
    virtual bool setGravity(const Vector&) { return false; } // default (0, -9.81, 0); GF_PHYS_GRAVITY
    virtual Vector getGravity() const { return Vector(0, -9.81f, 0); }
    // Fixed steps per second, 1..10000 (default 60; GF_PHYS_STEP_RATE).
    virtual bool setStepRate(int) { return false; }
    virtual int getStepRate() const { return 60; }
    // Most steps one update may take, >= 1 (default 8; GF_PHYS_MAX_STEPS).
    virtual bool setMaxStepsPerUpdate(int) { return false; }
    virtual int getMaxStepsPerUpdate() const { return 8; }
    virtual bool setIntegrator(Integrator) { return false; }
    virtual Integrator getIntegrator() const { return INTEGRATOR_SemiImplicitEuler; }
    // Bodies simulated (removals and deletions requested during a step count until the step ends).
    virtual size_t getBodyCount() const { return 0; }
    // Fixed steps taken since creation, and backlog steps dropped by the catch-up cap.
    virtual long long getStepCount() const { return 0; }
    virtual long long getDroppedStepCount() const { return 0; }
    // Game code run at the start of every step (iFixedUpdater.h); the scene does not own it.
    virtual bool addFixedUpdater(iFixedUpdater*) { return false; }
    virtual void removeFixedUpdater(const iFixedUpdater*) {}
    // A state-dependent force on body, evaluated at every integrator stage (iForceGenerator.h).
    virtual bool addForceGenerator(iRigidBody*, iForceGenerator*) { return false; }
    virtual void removeForceGenerator(const iRigidBody*, const iForceGenerator*) {}

    // Contact resolution, when a collision space is set: solver iterations a step, 1..1000 (default 4;
    // GF_PHYS_SOLVER_ITERATIONS). Each iteration is a sub-step of the contact solve (a sweep that pushes
    // overlap out, a move, a relaxing sweep): more of them, stiffer stacks at proportionally more cost.
    virtual bool setSolverIterations(int) { return false; }
    virtual int getSolverIterations() const { return 4; }
    // How two bodies' friction and restitution combine (iContactSettings.h; defaults COMBINE_Sum,
    // COMBINE_Max).
    virtual bool setFrictionRule(CombineRule) { return false; }
    virtual bool setRestitutionRule(CombineRule) { return false; }
    // Sleeping (default on): an island of touching bodies that stayed under 0.05 m/s and 0.05 rad/s for
    // 0.5 s stops being integrated and solved until a contact with an awake body, a force, a torque, a new
    // velocity or a new pose wakes it.
    virtual void setSleepingEnabled(bool) {}
    virtual size_t getAwakeBodyCount() const { return 0; } // moving bodies not asleep (fixed ones excluded)
    // The deepest contact of the last step, before and after the solver's position correction (m).
    virtual float getMaxPenetration() const { return 0; }
    virtual float getRemainingPenetration() const { return 0; }
};

// Creates a scene and makes it the active one (the one CreateRigidBody adds to). c may be nullptr; the scene
// reads GF_PHYS_STEP_RATE, GF_PHYS_MAX_STEPS, GF_PHYS_INTEGRATOR and GF_PHYS_GRAVITY from it when set.
extern "C" iPhysicsScene* CreatePhysicsScene(iContext* c);
