// SwitchesBench.cpp - what leaving a feature out saves: each scene is built twice, once with everything on
// (the baseline) and once with one switch changed, and the two are stepped alternately (so contention on a
// shared machine hits both alike). Counters: ms per step of each, and their ratio (switched / all on: 0.8
// is a 20 % saving). Scenes:
//  * SpherePile1000: 1,000 0.5 m spheres dropped into a pile (buildSpherePile), the first 300 steps (5 s,
//    while they fall and pile up, before much sleeps); switched: rotation locked on every sphere, or
//    validation, interpolation, listeners (a counting listener on every sphere), continuous collision,
//    friction or restitution off;
//  * NinetyPercentAsleep: 1,000 unit boxes resting apart on the floor, a counting listener on each, 100 of
//    them not allowed to sleep, 600 steps after a 60-step warm-up; switched: sleeping off (all 1,000 awake;
//    the ratio is what sleeping saves, the other way round), or listeners, interpolation or validation off
//    (in a scene this cheap, the per-frame work is a larger share).
#include "RBDynamics.h"
#include "Scenes.h"
#include "World.h"
#include "iCollisionListener.h"
#include "iPhysicsFrame.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneStats.h"
#include "iRigidBodySwitches.h"
#include "iSceneSwitches.h"

#include "../TimedScene.h"

#include "../PinnedBenchmarkMain.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <functional>
#include <memory>

namespace {

struct Counter final : iCollisionListener {
    long calls = 0;
    void HitWall(iRigidBody*, Vector, Vector) override { ++calls; }
};

using Build = TimedScene::Build;
using Run = TimedScene;

// Baseline: build; switched: build, then change(world). warmup steps untimed, then steps timed.
void compare(benchmark::State& state, int warmup, int steps, const Build& build, const Build& change) {
    double base = 0, switched = 0;
    size_t awakeBase = 0, awakeSwitched = 0, bodies = 0;
    for (auto _ : state) {
        state.PauseTiming();
        auto pa = std::make_unique<Run>(build), pb = std::make_unique<Run>(build);
        Run &a = *pa, &b = *pb;
        change(*b.world);
        for (int i = 1; i <= warmup; ++i) {
            a.step(i);
            b.step(i);
        }
        state.ResumeTiming();
        for (int i = warmup + 1; i <= warmup + steps; ++i) {
            if (i % 2) { // alternate which goes first
                base += a.step(i);
                switched += b.step(i);
            } else {
                switched += b.step(i);
                base += a.step(i);
            }
        }
        state.PauseTiming(); // the destructors are not measured
        awakeBase = statsOf(a.scene)->getAwakeBodyCount();
        awakeSwitched = statsOf(b.scene)->getAwakeBodyCount();
        bodies = statsOf(a.scene)->getBodyCount();
        pa.reset();
        pb.reset();
        state.ResumeTiming();
    }
    const double n = double(steps) * double(state.iterations());
    state.counters["ms_all_on"] = 1000.0 * base / n;
    state.counters["ms_switched"] = 1000.0 * switched / n;
    state.counters["ratio"] = base > 0 ? switched / base : 0.0;
    state.counters["awake_all_on"] = double(awakeBase) / double(bodies ? bodies : 1);
    state.counters["awake_switched"] = double(awakeSwitched) / double(bodies ? bodies : 1);
}

const Build kPile = [](World& w) { buildSpherePile(w, 1000, 5); };

void pile(benchmark::State& state, const Build& change) { compare(state, 0, 300, kPile, change); }

void sceneOff(World& w, SceneFeature f) { switchesOf(w.scene())->setFeatureEnabled(f, false); }

void BM_Pile_RotationLocked(benchmark::State& state) {
    pile(state, [](World& w) {
        for (iPhysicsFrame* f : w.bodies()) switchesOf(f->getRB())->setRotationLocked(true);
    });
}
void BM_Pile_ValidationOff(benchmark::State& state) {
    pile(state, [](World& w) { sceneOff(w, FEATURE_Validation); });
}
void BM_Pile_InterpolationOff(benchmark::State& state) {
    pile(state, [](World& w) { sceneOff(w, FEATURE_Interpolation); });
}
void BM_Pile_ContinuousOff(benchmark::State& state) {
    pile(state, [](World& w) { sceneOff(w, FEATURE_ContinuousCollision); });
}
void BM_Pile_FrictionOff(benchmark::State& state) {
    pile(state, [](World& w) { sceneOff(w, FEATURE_Friction); });
}
void BM_Pile_RestitutionOff(benchmark::State& state) {
    pile(state, [](World& w) { sceneOff(w, FEATURE_Restitution); });
}

// Listeners: both scenes have a counting listener on every sphere; the switched one delivers nothing.
Counter g_listener;
void BM_Pile_ListenersOff(benchmark::State& state) {
    const Build withListeners = [](World& w) {
        buildSpherePile(w, 1000, 5);
        for (iPhysicsFrame* f : w.bodies()) f->getRB()->attachListener(&g_listener);
    };
    compare(state, 0, 300, withListeners, [](World& w) { sceneOff(w, FEATURE_Listeners); });
}

// 1,000 unit boxes resting 2 m apart on the floor, each with a counting listener; every tenth may not sleep.
const Build kResting = [](World& w) {
    w.ground();
    for (int i = 0; i < 1000; ++i) {
        iPhysicsFrame* f =
            w.box(Vector(2.0f * float(i % 40), 0.5f, 2.0f * float(i / 40)), Vector(0.5f, 0.5f, 0.5f), 1.0f);
        f->getRB()->attachListener(&g_listener);
        if (i % 10 == 0) switchesOf(f->getRB())->setSleepAllowed(false);
    }
};
void resting(benchmark::State& state, SceneFeature off) {
    compare(state, 60, 600, kResting, [off](World& w) { sceneOff(w, off); });
}
void BM_NinetyPercentAsleep_SleepingOff(benchmark::State& state) { resting(state, FEATURE_Sleeping); }
void BM_NinetyPercentAsleep_ListenersOff(benchmark::State& state) { resting(state, FEATURE_Listeners); }
void BM_NinetyPercentAsleep_InterpolationOff(benchmark::State& state) {
    resting(state, FEATURE_Interpolation);
}
void BM_NinetyPercentAsleep_ValidationOff(benchmark::State& state) { resting(state, FEATURE_Validation); }

} // namespace

BENCHMARK(BM_Pile_RotationLocked)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Pile_ValidationOff)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Pile_InterpolationOff)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Pile_ListenersOff)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Pile_ContinuousOff)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Pile_FrictionOff)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Pile_RestitutionOff)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_NinetyPercentAsleep_SleepingOff)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_NinetyPercentAsleep_ListenersOff)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_NinetyPercentAsleep_InterpolationOff)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_NinetyPercentAsleep_ValidationOff)->Unit(benchmark::kMillisecond)->Iterations(1);

GUARDIAN_PINNED_BENCHMARK_MAIN()
