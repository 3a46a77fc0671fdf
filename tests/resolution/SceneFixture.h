// SceneFixture.h - a physics scene with a World, advanced by whole 60 Hz steps through update(now).
#pragma once

#include "MathDefinitions.h"
#include "RBDynamics.h"
#include "World.h"
#include "iPhysicsFrame.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneSettings.h"
#include "iRigidBody.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <random>
#include <vector>

namespace resolution_test {

constexpr float kG = 9.81f;
constexpr float kDt = 1.0f / 60.0f;

class SceneFixture {
public:
    // space: the collision space the world uses (owned by it; default a simple space).
    explicit SceneFixture(int iterations = 10, iCollisionSpace* space = nullptr) {
        scene = CreatePhysicsScene(nullptr);
        settingsOf(scene)->setSolverIterations(iterations);
        scene->update(0); // the first update sets the time base
        world = new World(scene, space);
    }
    ~SceneFixture() {
        delete world;
        scene->Delete();
    }
    SceneFixture(const SceneFixture&) = delete;
    SceneFixture& operator=(const SceneFixture&) = delete;

    // Advances exactly n fixed steps (engine time in whole milliseconds, rounded up past each step).
    void steps(int n, const std::function<void()>& afterEach = nullptr) {
        for (int i = 0; i < n; ++i) {
            ++m_steps;
            scene->update(int(std::ceil(m_steps * 1000.0 / 60.0)));
            if (afterEach) afterEach();
        }
    }
    // Steps taken so far; after restoring a snapshot taken at step n (iSnapshots.h), rewindTo(n) puts the
    // fixture's clock back with the scene's, so that the steps replayed are given the same times.
    long stepCount() const { return m_steps; }
    void rewindTo(long step) { m_steps = step; }
    void seconds(float s, const std::function<void()>& afterEach = nullptr) {
        steps(int(s * 60 + 0.5f), afterEach);
    }

    // FNV-1a over the bits of every body's position, orientation, velocity, angular velocity and sleep flag.
    unsigned long long stateHash() const {
        unsigned long long h = 1469598103934665603ull;
        auto mix = [&h](const void* p, size_t n) {
            const unsigned char* b = static_cast<const unsigned char*>(p);
            for (size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
        };
        for (const iPhysicsFrame* f : world->bodies()) {
            const RBDynamics* d = f->getDynamics();
            mix(&d->position, sizeof(Vector));
            mix(d->orientation.data(), 16 * sizeof(float));
            mix(&d->velocity, sizeof(Vector));
            mix(&d->angularVelocity, sizeof(Vector));
            const unsigned char asleep = d->sleeping ? 1 : 0;
            mix(&asleep, 1);
        }
        return h;
    }

    iPhysicsScene* scene;
    World* world;

private:
    long m_steps = 0;
};

// Moves every body of the world up to 1 um in x and z (a start just apart from the built one): drift, sink
// and overlap of a stack are chaotic, so a test asserts them over several such starts.
inline void jitterStart(World& world, unsigned seed) {
    std::mt19937 rng{seed};
    std::uniform_real_distribution<float> offset(-1e-6f, 1e-6f);
    for (const iPhysicsFrame* frame : world.bodies()) {
        RBDynamics* d = const_cast<iPhysicsFrame*>(frame)->getDynamics();
        d->position.x += offset(rng);
        d->position.z += offset(rng);
    }
}

inline float medianOfStarts(std::vector<float> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

} // namespace resolution_test
