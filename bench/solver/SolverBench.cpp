// SolverBench.cpp - ms per step of whole scenes (collision + solver + integration), the first speed/accuracy
// table: 1,000 spheres and 1,000 boxes falling into a pile (600 steps), and the 210-box pyramid at 4, 10 and
// 20 solver iterations with its top box's drift after 10 s as a counter.
#include "RBDynamics.h"
#include "Scenes.h"
#include "World.h"
#include "iPhysicsFrame.h"
#include "iPhysicsScene.h"

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

void BM_Pyramid210(benchmark::State& state) {
    float drift = 0;
    for (auto _ : state) {
        state.PauseTiming();
        iPhysicsScene* scene = CreatePhysicsScene(nullptr);
        scene->setSolverIterations(int(state.range(0)));
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

BENCHMARK(BM_SpherePile1000)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_BoxPile1000)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Pyramid210)->Arg(4)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_MAIN();
