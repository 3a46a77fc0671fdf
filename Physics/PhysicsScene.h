// PhysicsScene.h - the simulator's iPhysicsScene: the body list, the fixed-step clock, the settings, and
// the one step function (PhysicsScene::step) that reads top to bottom.
//
// The active scene (the one CreateRigidBody adds to) is the most recently created scene not yet deleted.
// Lifetimes (SceneLifetime.cpp): one scene update runs at a time; while it steps, every deletion of a body or
// a scene (whichever scene it belongs to) waits for the end of the step or the update, so nothing the step
// is walking is freed under it.
#pragma once

#include "Composite.h"
#include "ContactResolution.h"
#include "ContactSolver.h"
#include "ContinuousStage.h"
#include "Islands.h"
#include "JointClosing.h"
#include "StepProfiler.h"
#include "iDebugDrawable.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneHooks.h"
#include "iPhysicsSceneProfile.h"
#include "iPhysicsSceneSettings.h"
#include "iPhysicsSceneStats.h"
#include "iSceneSwitches.h"
#include "iSnapshots.h"

#include <cstdint>
#include <vector>

class iCollisionEvents;

namespace physics {

class RigidBody;
class Joint;

class PhysicsScene final : public iPhysicsScene,
                           public iPhysicsSceneSettings,
                           public iPhysicsSceneHooks,
                           public iPhysicsSceneStats,
                           public iPhysicsSceneProfile,
                           public iSnapshots,
                           public iDebugDrawable,
                           public iSceneSwitches {
public:
    PhysicsScene();
    PhysicsScene(const PhysicsScene&) = delete;
    PhysicsScene& operator=(const PhysicsScene&) = delete;
    static PhysicsScene* active();
    // The scene whose update is taking steps now (callbacks may be running), or nullptr.
    static PhysicsScene* updating();

    // --- iPhysicsScene ---
    bool add(iRigidBody* o) override;
    void setNewGlobalCollisionSpace(iCollisionSpace* cs) override;
    void restore(int now) override;
    void update(int now) override;
    void reset(int now) override;
    void suspend() const override { m_suspended = true; }
    void release() const override {}
    void remove(const iRigidBody* o) override;
    void Delete() const override;

    // --- iPhysicsSceneSettings, iPhysicsSceneHooks, iPhysicsSceneStats, iPhysicsSceneProfile ---
    bool setGravity(const Vector& g) override;
    Vector getGravity() const override { return m_gravity; }
    bool setStepRate(int hz) override;
    int getStepRate() const override { return m_stepRate; }
    bool setMaxStepsPerUpdate(int n) override;
    int getMaxStepsPerUpdate() const override { return m_maxSteps; }
    bool setIntegrator(Integrator i) override;
    Integrator getIntegrator() const override { return m_integrator; }
    size_t getBodyCount() const override { return bodies().size(); }
    long long getStepCount() const override { return m_steps; }
    long long getDroppedStepCount() const override { return m_dropped; }
    bool addFixedUpdater(iFixedUpdater* u) override;
    void removeFixedUpdater(const iFixedUpdater* u) override;
    bool addForceGenerator(iRigidBody* body, iForceGenerator* g) override;
    void removeForceGenerator(const iRigidBody* body, const iForceGenerator* g) override;
    bool setSolverIterations(int n) override;
    int getSolverIterations() const override { return m_solver.settings().substeps; }
    bool setFrictionRule(CombineRule r) override;
    bool setRestitutionRule(CombineRule r) override;
    void setSleepingEnabled(bool on) override;
    void setContinuousCollisionEnabled(bool on) override { m_continuousOn = on; }
    bool getContinuousCollisionEnabled() const override { return m_continuousOn; }
    bool setLengthUnitsPerMetre(float unitsPerMetre) override; // PhysicsSceneContacts.cpp
    float getLengthUnitsPerMetre() const override { return m_lengthUnit; }
    size_t getAwakeBodyCount() const override;
    float getMaxPenetration() const override { return m_solver.maxPenetrationBefore(); }
    float getRemainingPenetration() const override { return m_solver.maxPenetrationAfter(); }
    const PhysicsProfile& getProfile() const override { return m_profiler.profile(); }
    // --- iSceneSwitches (SceneSwitches.cpp) ---
    bool setFeatureEnabled(SceneFeature f, bool on) override;
    bool isFeatureEnabled(SceneFeature f) const override;
    // --- iSnapshots (SceneSnapshot.cpp) ---
    iSnapshot* takeSnapshot() const override;
    bool restoreSnapshot(const iSnapshot* s) override;

    // --- iDebugDrawable (SceneDebugDraw.cpp): the space's drawing, then the bodies' ---
    void debugDraw(iDebugDraw& out, unsigned flags) const override;

    // --- the bodies' side ---
    bool busy() const { return m_busy; } // inside update(): removals and deletions are deferred
    // b (of any scene, or of none) is deleted at the end of this scene's current step.
    void deferDelete(RigidBody* b) { m_leaving.push_back({b, Leave::Delete}); }
    // b, one of this scene's bodies, is skipped from now on and leaves the scene at the end of the current
    // step (of the next one between steps): remove() during a step, kill().
    void deferRemove(RigidBody* b);
    void forget(RigidBody* b); // b is being destroyed now: drop every reference to it
    // The body of this scene whose dynamics d is, or nullptr.
    RigidBody* bodyOf(const RBDynamics* d) const {
        RigidBody* const* body = m_byDynamics.find(d);
        return body ? *body : nullptr;
    }

private:
    ~PhysicsScene();
    void step(float dt);
    void wakeAll(); // every sleeping body wakes (sleeping switched off, gravity changed)
    void setSpace(iCollisionSpace* space); // the space, its roles looked up, its version bumped
    void runFixedUpdaters(float dt);
    // The space's contacts at the current poses (none when it was replaced since spaceVersion).
    void findContacts(float dt, unsigned spaceVersion, const CollisionContact*& contacts, size_t& count);
    void countProfile(); // the profile's counts after an update's steps
    // Forces on a composite over dt: moves it, or (one the contact solver moves) hands the solver its
    // velocities.
    void integrateComposite(RigidBody* root, float dt);
    void flushDeferred();
    // HitWall once a frame (iCollisionEvents): the space holds its events while the scene steps, and the
    // scene delivers them after the steps (PhysicsSceneContacts.cpp).
    void holdCollisionEvents();
    void deliverCollisionEvents();
    void beginSteps();
    void endSteps();
    void leaveRegistry(); // no longer the active scene or a candidate for it
    static void onSpaceDestroyed(const iCollisionSpace* dying, void* self);
    void writeFrames(float alpha);
    // Joints (SceneJoints.cpp): this step's, their islands, their reactions and breaks, letting go.
    void gatherJoints();
    void joinJointIslands();
    void finishJoints();
    void deliverJointBreaks();
    void letJointsGo(RigidBody* b);
    RigidBody* sceneBody(const iRigidBody* o) const; // o if it is one of this scene's bodies, else nullptr

    // The scene's bodies in the order they joined. A body leaving is only cleared from its slot (O(1), so
    // that deleting N bodies costs O(N)); the list closes up at the next read, through bodies().
    std::vector<RigidBody*>& bodies() {
        if (m_bodyHoles > 0) closeUpBodies();
        return m_bodies;
    }
    const std::vector<RigidBody*>& bodies() const { return const_cast<PhysicsScene*>(this)->bodies(); }
    void closeUpBodies();
    std::vector<RigidBody*> m_bodies; // read through bodies(): it may hold nullptr where a body left
    size_t m_bodyHoles = 0;
    SceneBodyAccess::BodyMap m_byDynamics;
    // What the end of the step does, last queued first: every deferred removal and deletion
    // (SceneLifetime.cpp).
    enum class Leave { Remove, Delete };
    std::vector<std::pair<RigidBody*, Leave>> m_leaving;
    std::vector<Joint*> m_joints, m_brokenJoints; // this step's joints; those that broke in it
    std::vector<iFixedUpdater*> m_updaters;       // nullptr: removed during a step, compacted after it
    std::vector<PhysicsScene*> m_deferredScenes;  // deleted from callbacks of this scene's update
    // The collision space, and the two of its optional roles every step uses (looked up once, in setSpace).
    iCollisionSpace* m_space = nullptr;
    iCollisionEvents* m_spaceEvents = nullptr;
    iShapeCast* m_spaceCast = nullptr;
    unsigned m_spaceVersion = 0;         // changes whenever m_space does (its contact list is then gone)
    unsigned long long m_membership = 0; // changes whenever a body joins or leaves (snapshots)

    Vector m_gravity = Vector(0, -9.81f, 0);
    float m_lengthUnit = 1.0f; // length units per metre
    int m_stepRate = 60;
    int m_maxSteps = 8;
    Integrator m_integrator = INTEGRATOR_SemiImplicitEuler;

    // Time in exact integer units of 1/(1000 * stepRate) s: update adds elapsed ms * stepRate, a step takes
    // 1000. No float drift, and 1000 ms at 60 Hz is exactly 60 steps.
    std::int64_t m_accumulator = 0;
    int m_lastNow = 0;
    bool m_hasTimeBase = false;
    mutable bool m_suspended = false;
    bool m_busy = false;
    mutable bool m_deleteRequested = false;
    long long m_steps = 0, m_dropped = 0;
    // The dropped backlog reached stepRate steps (1 s) and was reported.
    bool m_reportedDrops = false;
    Composite m_composite; // scratch, reused so that stepping allocates nothing
    ContactSolver m_solver;
    SceneBodyAccess m_bodyAccess{m_byDynamics}; // the solver's view of the bodies (after m_byDynamics)
    Islands m_islands;
    bool m_sleeping = true;
    ContinuousStage m_continuous;
    JointClosing m_jointClosing;
    bool m_continuousOn = true;
    StepProfiler m_profiler;
    bool m_lastStepSolved = false; // the solver ran in the last step (its manifolds are that step's)
    // iSceneSwitches: gravity, drag, listeners, validation, interpolation (the solver keeps friction and
    // restitution; sleeping and continuous collision are m_sleeping and m_continuousOn).
    bool m_gravityOn = true, m_dragOn = true, m_listenersOn = true, m_validationOn = true;
    bool m_interpolationOn = true;
};

} // namespace physics
