// ContinuousBench.cpp - what the continuous stage costs: each scene is built twice, stage on and stage off,
// and the two are stepped alternately (so contention on a shared machine hits both alike); the counters
// are ms per step of each and their ratio (on / off). Scenes:
//  * Pyramid210Awake: the 210-box pyramid with sleeping off, 600 steps: nothing is fast (the goal: < 5 %);
//  * SpherePile1000: 1,000 0.5 m spheres dropped into a pile (buildSpherePile), 600 steps: some are fast;
//  * Bullets100: 100 spheres at 1,000 m/s at a fixed 1 m wall, 60 steps: every one is swept and hits (off,
//    they pass through: the ratio is the price of being right, not a like-for-like cost).
#include "RBDynamics.h"
#include "Scenes.h"
#include "World.h"
#include "iPhysicsFrame.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneSettings.h"

#include "../TimedScene.h"

#include "../PinnedBenchmarkMain.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <functional>
#include <memory>

namespace {

// A scene with the continuous stage on or off.
struct Run : TimedScene {
    Run(bool continuous, const Build& build) : TimedScene(build) {
        settingsOf(scene)->setContinuousCollisionEnabled(continuous);
    }
};

void compare(benchmark::State& state, int steps, bool sleeping, const std::function<void(World&)>& build) {
    double on = 0, off = 0;
    for (auto _ : state) {
        state.PauseTiming();
        auto pa = std::make_unique<Run>(true, build), pb = std::make_unique<Run>(false, build);
        Run &a = *pa, &b = *pb;
        settingsOf(a.scene)->setSleepingEnabled(sleeping);
        settingsOf(b.scene)->setSleepingEnabled(sleeping);
        state.ResumeTiming();
        for (int i = 1; i <= steps; ++i) {
            if (i % 2) { // alternate which goes first
                on += a.step(i);
                off += b.step(i);
            } else {
                off += b.step(i);
                on += a.step(i);
            }
        }
        state.PauseTiming(); // the destructors are not measured
        pa.reset();
        pb.reset();
        state.ResumeTiming();
    }
    const double n = double(steps) * double(state.iterations());
    state.counters["ms_per_step_on"] = 1000.0 * on / n;
    state.counters["ms_per_step_off"] = 1000.0 * off / n;
    state.counters["ratio_on_off"] = off > 0 ? on / off : 0.0;
}

void BM_Pyramid210Awake(benchmark::State& state) {
    compare(state, 600, false, [](World& w) { buildPyramid(w, 20); });
}

void BM_SpherePile1000(benchmark::State& state) {
    compare(state, 600, true, [](World& w) { buildSpherePile(w, 1000, 5); });
}

void BM_Bullets100(benchmark::State& state) {
    compare(state, 60, true, [](World& w) {
        settingsOf(w.scene())->setGravity(Vector(0, 0, 0));
        w.fixedBox(Vector(0.5f, 0, 0), Vector(0.5f, 6.0f, 6.0f));
        for (int i = 0; i < 100; ++i) {
            RBDynamics* d =
                w.sphere(Vector(-5.0f - 0.37f * float(i % 7), float(i / 10) - 4.5f, float(i % 10) - 4.5f),
                         0.05f, 1.0f)
                    ->getDynamics();
            d->velocity = Vector(1000.0f, 0, 0);
        }
    });
}

} // namespace

BENCHMARK(BM_Pyramid210Awake)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_SpherePile1000)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Bullets100)->Unit(benchmark::kMillisecond)->Iterations(20);

GUARDIAN_PINNED_BENCHMARK_MAIN()
