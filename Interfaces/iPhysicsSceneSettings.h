// iPhysicsSceneSettings.h - the simulator's knobs: gravity, step rate, integrator, solver, sleeping,
// continuous collision.
//
// Not part of the seed's iPhysicsScene, so that a game's own stand-in scene need not implement them. The
// scene made by CreatePhysicsScene implements this interface too; settingsOf(scene) reaches it (nullptr for
// any other scene). Setters refuse invalid values with error(), keep the old value and return false.
#pragma once

#include "MathDeclarations.h"
#include "iContactSettings.h"
#include "iPhysicsScene.h"
#include "iPhysicsSettings.h"

class iPhysicsSceneSettings {
public:
    // Default (0, -9.81, 0); GF_PHYS_GRAVITY. A change wakes every sleeping body: asleep under the old
    // gravity, it would hang where it lay.
    virtual bool setGravity(const Vector& g) = 0;
    virtual Vector getGravity() const = 0;
    // Fixed steps per second, 1..10000 (default 60; GF_PHYS_STEP_RATE).
    virtual bool setStepRate(int hz) = 0;
    virtual int getStepRate() const = 0;
    // Most steps one update may take, >= 1 (default 8; GF_PHYS_MAX_STEPS).
    virtual bool setMaxStepsPerUpdate(int n) = 0;
    virtual int getMaxStepsPerUpdate() const = 0;
    virtual bool setIntegrator(Integrator i) = 0; // GF_PHYS_INTEGRATOR
    virtual Integrator getIntegrator() const = 0;
    // Contact resolution, when a collision space is set: solver iterations a step, 1..1000 (default 4;
    // GF_PHYS_SOLVER_ITERATIONS). Each iteration is a sub-step of the contact solve (a sweep that pushes
    // overlap out, a move, a relaxing sweep): more of them, stiffer stacks at proportionally more cost.
    virtual bool setSolverIterations(int n) = 0;
    virtual int getSolverIterations() const = 0;
    // How two bodies' friction and restitution combine (iContactSettings.h; defaults COMBINE_Sum,
    // COMBINE_Max).
    virtual bool setFrictionRule(CombineRule r) = 0;
    virtual bool setRestitutionRule(CombineRule r) = 0;
    // Sleeping (default on): an island of touching bodies that stayed under 0.05 m/s and 0.05 rad/s for
    // 0.5 s stops being integrated and solved until a contact with an awake body, a force, a torque, a new
    // velocity or a new pose wakes it.
    virtual void setSleepingEnabled(bool on) = 0;
    // Continuous collision (default on, needs a space with iShapeCast.h such as the simple space): a body
    // that moved more than a quarter of a shape's smallest dimension in a step is swept along that motion
    // and put back where it first touched another body or a plane, keeping its velocity, so that no sphere,
    // box or compound passes through anything at any speed; the next step resolves the contact there.
    virtual void setContinuousCollisionEnabled(bool on) = 0;
    virtual bool getContinuousCollisionEnabled() const = 0;
    // The world's length unit: how many of its length units make a metre (default 1; 100 for a game in
    // centimetres, 0.001 for one in kilometres; 1e-3..1e3, iCollisionSpaceScale.h). Every tolerance that is
    // a length or a speed is a metre figure times this unit, so that a scene built in centimetres behaves as
    // the same scene in metres: the contact solver's push-out speed cap (3 m/s), bounce threshold (1 m/s),
    // deep and touch overlaps (1 cm, 1 mm), warm-start match and keep distances (5 cm, 1 cm) and bounce gap
    // (0.1 mm), the sleep speed (0.05 m/s; 0.05 rad/s is no length), and the drag law's air density and
    // reference area (RBDynamics.h). The scene forwards the unit to its collision space (scaleOf(space),
    // when it has one) on setNewGlobalCollisionSpace and on every change. Gravity is not scaled: it is the
    // game's to set in its own unit (-981 in centimetres). What follows a body's own size instead: the
    // resting overlap of a contact (within 0.5 % of the smaller shape's bounding radius for shapes down to
    // about 0.5 mm at the default step; see README). Refused with error() when out of range or not finite.
    virtual bool setLengthUnitsPerMetre(float unitsPerMetre) = 0;
    virtual float getLengthUnitsPerMetre() const = 0;

protected:
    ~iPhysicsSceneSettings() = default; // part of a scene: Delete() the scene
};

// The settings of a scene made by CreatePhysicsScene; nullptr for a scene that has none (a game's own).
// A cross-cast to this public interface, not to the simulator's class: any implementation may provide it.
inline iPhysicsSceneSettings* settingsOf(iPhysicsScene* scene) {
    return dynamic_cast<iPhysicsSceneSettings*>(scene);
}
inline const iPhysicsSceneSettings* settingsOf(const iPhysicsScene* scene) {
    return dynamic_cast<const iPhysicsSceneSettings*>(scene);
}
