// PrecisionScenes.h - the scenes that measure what a double-precision simulator (GUARDIAN_DOUBLE) buys and
// costs, each run through scene->update(now) and measured against an independent truth: far from the origin
// a slow roll (distance against v t), a box at rest (height against the plane, its speed against zero) and a
// projectile (against the parabola); at extreme mass ratios a heavy box on a light one (overlap and drift
// against the resting stack); and the awake 210-box pyramid's step time. Shared by the double build's tests
// and by precision_report, built once against each library (scripts/precision.sh runs both).
#pragma once

#include "RBDynamics.h"
#include "Scenes.h"
#include "World.h"
#include "iPhysicsFrame.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneSettings.h"
#include "iRigidBody.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace precision {

// A scene at 60 Hz with a World; one fixed step per update (engine time in whole ms, the ceiling of n/60 s).
class Run {
public:
    explicit Run(int iterations = 4) {
        scene = CreatePhysicsScene(nullptr);
        settingsOf(scene)->setSolverIterations(iterations);
        settingsOf(scene)->setSleepingEnabled(false); // measure the motion, not the sleep threshold
        scene->update(0);
        world = new World(scene);
    }
    ~Run() {
        delete world;
        scene->Delete();
    }
    Run(const Run&) = delete;
    Run& operator=(const Run&) = delete;
    template <class F> void steps(long n, F afterEach) {
        for (long i = 0; i < n; ++i) {
            ++m_steps;
            scene->update(int(std::ceil(double(m_steps) * 1000.0 / 60.0)));
            afterEach();
        }
    }
    void steps(long n) {
        steps(n, [] {});
    }
    long stepCount() const { return m_steps; }
    iPhysicsScene* scene;
    World* world;

private:
    long m_steps = 0;
};

constexpr double kStep = double(1.0f / 60.0f); // the scene's fixed step, as the float it is

// A ball (r 0.5 m, 1 kg) set rolling without slipping at v along x on a plane, at x = offset (and, with
// everyAxis, at y = z = offset on the plane y = offset), for `seconds`: how far it went, over v t (1: exact;
// a rolling ball on a frictional plane keeps its speed, as no force acts along x while it does not slip).
inline double slowRoll(float offset, float v, double seconds, bool everyAxis = false) {
    Run r;
    const float far = everyAxis ? offset : 0.0f;
    r.world->ground(far);
    RBDynamics* d = r.world->sphere(Vector(offset, far + 0.5f, far), 0.5f, 1.0f)->getDynamics();
    d->velocity = Vector(v, 0, 0);
    d->angularVelocity = Vector(0, 0, -v / 0.5f); // rolling: w x (0, -r, 0) = -v along x at the contact
    const float x0 = d->position.x;
    const long n = long(std::lround(seconds * 60));
    r.steps(n);
    return (double(d->position.x) - double(x0)) / (double(v) * double(n) * kStep);
}

struct Rest {
    double heightError; // worst |centre height - (plane + half height)| over the last 2 s (m)
    double maxSpeed;    // fastest it moved over the last 2 s (m/s): jitter
};
// A unit box (1 kg) set on the plane y = offset at x = z = offset: 1 s to settle, 2 s measured.
inline Rest restingBox(float offset) {
    Run r;
    r.world->ground(offset);
    RBDynamics* d =
        r.world->box(Vector(offset, offset + 0.5f, offset), Vector(0.5f, 0.5f, 0.5f), 1.0f)->getDynamics();
    r.steps(60);
    Rest out{0, 0};
    const double rest = double(offset) + 0.5;
    r.steps(120, [&] {
        out.heightError = std::max(out.heightError, std::fabs(double(d->position.y) - rest));
        out.maxSpeed = std::max(out.maxSpeed, double(d->velocity.length()));
    });
    return out;
}

// A ball launched from (offset, offset, offset) at (10, 10, 0) m/s under g = 9.81 (velocity Verlet, exact
// for a parabola at every step): the worst distance from the parabola at the steps of its 2.04 s flight,
// up to where it comes back to its launch height (the landing point's error).
inline double projectile(float offset) {
    Run r;
    settingsOf(r.scene)->setIntegrator(INTEGRATOR_VelocityVerlet);
    RBDynamics* d = r.world->sphere(Vector(offset, offset, offset), 0.1f, 1.0f)->getDynamics();
    d->velocity = Vector(10, 10, 0);
    const double g = double(9.81f), flight = 2 * 10 / g;
    double worst = 0;
    r.steps(long(flight / kStep), [&] {
        const double t = double(r.stepCount()) * kStep;
        const double dx = double(d->position.x) - (double(offset) + 10 * t);
        const double dy = double(d->position.y) - (double(offset) + 10 * t - 0.5 * g * t * t);
        const double dz = double(d->position.z) - double(offset);
        worst = std::max(worst, std::sqrt(dx * dx + dy * dy + dz * dz));
    });
    return worst;
}

struct Stack {
    double sink;  // deepest the heavy box's centre sat below its resting height 1.5 m (m): overlap
    double drift; // farthest it moved sideways (m)
};
// A unit box of `ratio` kg on a 1 kg unit box on the plane y = 0 (tests/extremes' heavy-on-light stack):
// over `seconds` after the first half second.
inline Stack heavyOnLight(float ratio, int iterations, double seconds) {
    Run r(iterations);
    r.world->ground();
    r.world->box(Vector(0, 0.5f, 0), Vector(0.5f, 0.5f, 0.5f), 1.0f);
    RBDynamics* top = r.world->box(Vector(0, 1.5f, 0), Vector(0.5f, 0.5f, 0.5f), ratio)->getDynamics();
    r.steps(30);
    Stack out{0, 0};
    r.steps(long(seconds * 60), [&] {
        out.sink = std::max(out.sink, 1.5 - double(top->position.y));
        out.drift = std::max(out.drift, std::hypot(double(top->position.x), double(top->position.z)));
    });
    return out;
}

// The 210-box pyramid (bench/solver's scene) at 4 iterations with sleeping off, 600 steps: ms per step.
inline double awakePyramidStepMs() {
    Run r(4);
    buildPyramid(*r.world, 20);
    const auto start = std::chrono::steady_clock::now();
    r.steps(600);
    const std::chrono::duration<double, std::milli> took = std::chrono::steady_clock::now() - start;
    return took.count() / 600.0;
}

} // namespace precision
