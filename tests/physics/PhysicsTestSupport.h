// PhysicsTestSupport.h - shared helpers of the simulator tests: a scene that deletes itself, the shared error
// recorder, and running the scene for a given time in fixed-size frames.
#pragma once

#include <algorithm>

#include "ErrorRecorder.h"
#include "RBDynamics.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneSettings.h"
#include "iRigidBody.h"
#include "iUtilities.h"

namespace physics_test {

using guardian_test::ErrorRecorder; // tests/ErrorRecorder.h

constexpr float kG = 9.81f; // the scenes' default gravity (m/s^2)

// A scene for one test: created with the given rate and integrator, deleted (with its bodies) at the end.
struct SceneHolder {
    iPhysicsScene* scene;
    int now = 0;
    explicit SceneHolder(int hz = 60, Integrator integrator = INTEGRATOR_Default)
        : scene(CreatePhysicsScene(nullptr)) {
        settingsOf(scene)->setStepRate(hz);
        settingsOf(scene)->setIntegrator(integrator);
        scene->update(now); // sets the time base
    }
    ~SceneHolder() { scene->Delete(); }
    SceneHolder(const SceneHolder&) = delete;
    SceneHolder& operator=(const SceneHolder&) = delete;
    // Advances by ms in frames of frameMs (the last one shorter), like an engine loop.
    void run(int ms, int frameMs = 10) {
        int end = now + ms;
        while (now < end) {
            now = now + frameMs < end ? now + frameMs : end;
            scene->update(now);
        }
    }
};

// Records every rigidBodyDestroyed notification (what a collision space relies on).
struct DestroyLog {
    std::vector<const iRigidBody*> dead;
    static void note(const iRigidBody* b, void* self) { static_cast<DestroyLog*>(self)->dead.push_back(b); }
    DestroyLog() { watchRigidBodies(&note, this); }
    ~DestroyLog() { unwatchRigidBodies(&note, this); }
    bool has(const iRigidBody* b) const { return std::find(dead.begin(), dead.end(), b) != dead.end(); }
};

} // namespace physics_test
