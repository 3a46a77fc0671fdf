// ExtremesSupport.h - what every extremes test shares: the short (CI) or full (scripts/extremes.sh) range,
// a scene whose steps can be counted at any rate, a finite-state check that names the body, and a
// one-line report of each measured number (printed and kept as a gtest property for the XML output).
#pragma once

#include "ErrorRecorder.h"
#include "MathDefinitions.h"
#include "RBDynamics.h"
#include "World.h"
#include "iPhysicsFrame.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneSettings.h"
#include "iRigidBody.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace extremes {

// GUARDIAN_EXTREMES=full (scripts/extremes.sh) widens the ranges and lengthens the runs; anything else, or
// nothing, is the short CI version.
inline bool fullRun() {
    const char* v = std::getenv("GUARDIAN_EXTREMES");
    return v && std::strcmp(v, "full") == 0;
}

// A scene at hz with a World, stepped one fixed step per update (engine time in whole ms).
class Bench {
public:
    explicit Bench(int iterations = 4, int hz = 60) : m_hz(hz) {
        scene = CreatePhysicsScene(nullptr);
        settingsOf(scene)->setSolverIterations(iterations);
        settingsOf(scene)->setStepRate(hz);
        scene->update(0);
        world = new World(scene);
    }
    ~Bench() {
        delete world;
        scene->Delete();
    }
    Bench(const Bench&) = delete;
    Bench& operator=(const Bench&) = delete;

    // n fixed steps; afterEach (if any) runs after every one and may stop the run by returning false.
    template <class F> void steps(long n, F afterEach) {
        for (long i = 0; i < n; ++i) {
            ++m_steps;
            now = long(std::ceil(double(m_steps) * 1000.0 / m_hz));
            scene->update(int(now));
            if (!afterEach()) return;
        }
    }
    void steps(long n) {
        steps(n, [] { return true; });
    }
    float dt() const { return 1.0f / float(m_hz); }

    iPhysicsScene* scene;
    World* world;
    long now = 0;

private:
    int m_hz;
    long m_steps = 0;
};

// Every body's state is finite; on failure the message names the first body that is not.
inline ::testing::AssertionResult allFinite(const World& w) {
    for (size_t i = 0; i < w.bodies().size(); ++i) {
        const RBDynamics* d = w.bodies()[i]->getDynamics();
        if (!d->position.isFinite() || !d->velocity.isFinite() || !d->angularVelocity.isFinite() ||
            !d->angularMomentum.isFinite() || !d->orientation.isFinite())
            return ::testing::AssertionFailure()
                   << "body " << i << " of " << w.bodies().size() << " has a non-finite state";
    }
    return ::testing::AssertionSuccess();
}

// One measured number: printed ("extremes: <case>: <what> = <value>") and recorded as a test property.
inline void report(const std::string& what, double value) {
    std::printf("extremes: %s = %.4g\n", what.c_str(), value);
    std::string key;
    for (char c : what) key += (std::isalnum(static_cast<unsigned char>(c)) ? c : '_');
    ::testing::Test::RecordProperty(key, std::to_string(value));
}

} // namespace extremes
