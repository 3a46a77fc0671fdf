// SolverBench.cpp - ms per step of whole scenes (collision + solver + integration), the first speed/accuracy
// table: 1,000 spheres and 1,000 boxes falling into a pile (600 steps) and the 210-box pyramid, each at 4, 10
// and 20 solver iterations (sub-steps; the pyramid also at 16, what a 1:10^4 mass ratio needs), the
// pyramid's top box drift after 10 s as a counter, and the pyramid again with sleeping off (the cost of a
// step while everything is awake).
#include "RBDynamics.h"
#include "Scenes.h"
#include "World.h"
#include "iPhysicsFrame.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneSettings.h"

#include "../PinnedBenchmarkMain.h"

#include <benchmark/benchmark.h>

#include <cmath>

namespace {

void runSteps(iPhysicsScene* scene, int steps) {
    for (int i = 1; i <= steps; ++i) scene->update(int(std::ceil(i * 1000.0 / 60.0)));
}

template <class Build> void pile(benchmark::State& state, Build build) {
    for (auto _ : state) {
        state.PauseTiming();
        iPhysicsScene* scene = CreatePhysicsScene(nullptr);
        settingsOf(scene)->setSolverIterations(int(state.range(0)));
        scene->update(0);
        World* world = new World(scene);
        build(*world);
        state.ResumeTiming();
        runSteps(scene, 600);
        state.PauseTiming();
        delete world;
        scene->Delete();
        state.ResumeTiming();
    }
    state.counters["ms_per_step"] = benchmark::Counter(
        600.0 * state.iterations() / 1000.0, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_SpherePile1000(benchmark::State& state) {
    pile(state, [](World& w) { buildSpherePile(w, 1000, 5); });
}
void BM_BoxPile1000(benchmark::State& state) {
    pile(state, [](World& w) { buildBoxPile(w, 1000, 5); });
}

// range(1) = 0 keeps the pyramid awake all along: what a step costs before it falls asleep.
void BM_Pyramid210(benchmark::State& state) {
    float drift = 0;
    for (auto _ : state) {
        state.PauseTiming();
        iPhysicsScene* scene = CreatePhysicsScene(nullptr);
        settingsOf(scene)->setSolverIterations(int(state.range(0)));
        settingsOf(scene)->setSleepingEnabled(state.range(1) != 0);
        scene->update(0);
        World* world = new World(scene);
        buildPyramid(*world, 20);
        RBDynamics* top = world->bodies().back()->getDynamics();
        Vector start = top->position;
        state.ResumeTiming();
        runSteps(scene, 600);
        state.PauseTiming();
        drift = (top->position - start).length();
        delete world;
        scene->Delete();
        state.ResumeTiming();
    }
    state.counters["ms_per_step"] = benchmark::Counter(
        600.0 * state.iterations() / 1000.0, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["top_drift_m"] = drift;
}

} // namespace

BENCHMARK(BM_SpherePile1000)->Arg(4)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_BoxPile1000)->Arg(4)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Pyramid210)
    ->ArgNames({"iterations", "sleeping"})
    ->ArgsProduct({{4, 10, 16, 20}, {1, 0}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
GUARDIAN_PINNED_BENCHMARK_MAIN()
