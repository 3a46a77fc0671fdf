// iSceneSwitches.h - scene-wide switches for what a scene can leave out, so that it pays only for what it
// uses: each feature switched off is skipped, not computed and thrown away.
//
// Not part of the seed's iPhysicsScene (a game's own scene need not implement it); the scene made by
// CreatePhysicsScene does, reached with switchesOf(scene) (nullptr for any other scene). Every feature is on
// by default. Per-body switches are in iRigidBodySwitches.h.
#pragma once

#include "iPhysicsScene.h"

enum SceneFeature : int { // a fixed type: any int is a value, so a bad one is refused, not undefined
    // Gravity (the setting's vector is kept; off, no body feels it). A body of its own: PHYS_Floating or
    // iRigidBodySwitches::setGravityScale.
    FEATURE_Gravity,
    // Quadratic drag (RBDynamics::dragCoefficient): off, no body's drag is evaluated.
    FEATURE_Drag,
    // Contact friction: off, every contact is frictionless and the solver's friction rows are not solved.
    FEATURE_Friction,
    // Bounces: off, every contact is perfectly inelastic (restitution 0) and no bounce pass runs.
    FEATURE_Restitution,
    // Continuous collision, as iPhysicsSceneSettings::setContinuousCollisionEnabled.
    FEATURE_ContinuousCollision,
    // Sleeping, as iPhysicsSceneSettings::setSleepingEnabled: off, every body is integrated and solved.
    FEATURE_Sleeping,
    // HitWall (iCollisionListener): off, the scene delivers no collision events and no listener is called.
    // A space that can hold its events (iCollisionEvents.h) holds them meanwhile, a few notices per touching
    // pair at most; switched on again, the first delivery also reports, once per pair, what touched while
    // off. (A space without iCollisionEvents calls its listeners itself: this switch cannot stop it.)
    FEATURE_Listeners,
    // The per-step check of every body's state before and after each step (RBDynamics.h, "Validation"):
    // off, a state the game writes directly (a NaN velocity, a scaled orientation) is neither reported nor
    // undone but simulated as it is, and a NaN spreads through the contact solver to the bodies resting on
    // the same ground: for a game that never writes such state. The API's own refusals (setters,
    // ApplyImpulse, setDynamics) stay. On again, the next step puts every invalid body back to its last
    // state checked valid (from before the switch went off).
    FEATURE_Validation,
    // Frame interpolation between the last two steps: off, each frame shows the last step's pose.
    FEATURE_Interpolation,
    FEATURE_Count
};

class iSceneSwitches {
public:
    // Turns a feature on or off, effective from the next step (or frame write). A value that is not a
    // SceneFeature is refused with error() and false.
    virtual bool setFeatureEnabled(SceneFeature f, bool on) = 0;
    // Whether the feature is on (false for a value that is not a SceneFeature).
    virtual bool isFeatureEnabled(SceneFeature f) const = 0;

protected:
    ~iSceneSwitches() = default; // part of a scene: Delete() the scene
};

inline iSceneSwitches* switchesOf(iPhysicsScene* scene) { return dynamic_cast<iSceneSwitches*>(scene); }
inline const iSceneSwitches* switchesOf(const iPhysicsScene* scene) {
    return dynamic_cast<const iSceneSwitches*>(scene);
}
