// CrowdBench.cpp - the robustness scenes of issue 11, timed: a crowd of spheres spawned at one point (ms per
// step, the peak resident memory of the process, contacts reported against the budget), and a heavy box on a
// light one at mass ratios 10^2..10^4 and 4..64 solver iterations (ms per step, how far the top box strayed
// from its resting height in 5 s). Run one benchmark per process to read peak_rss_MB for that scene alone
// (--benchmark_filter).
#include "RBDynamics.h"
#include "World.h"
#include "iContactBudget.h"
#include "iPhysicsFrame.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneSettings.h"

#include "../PinnedBenchmarkMain.h"

#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace {

void runSteps(iPhysicsScene* scene, int from, int steps) {
    for (int i = from + 1; i <= from + steps; ++i) scene->update(int(std::ceil(i * 1000.0 / 60.0)));
}

double peakRssMB() {
    rusage r{};
    getrusage(RUSAGE_SELF, &r);
    return double(r.ru_maxrss) / 1024.0; // Linux: kilobytes
}

// range(0) spheres (radius 0.25 m) at one point 3 m above the floor, 10 steps at the default settings.
void BM_CrowdAtOnePoint(benchmark::State& state) {
    const int steps = 10;
    size_t contacts = 0;
    for (auto _ : state) {
        state.PauseTiming();
        iPhysicsScene* scene = CreatePhysicsScene(nullptr);
        scene->update(0);
        World* world = new World(scene);
        world->ground();
        for (int i = 0; i < state.range(0); ++i) world->sphere(Vector(0, 3, 0), 0.25f, 1.0f);
        state.ResumeTiming();
        runSteps(scene, 0, steps);
        state.PauseTiming();
        contacts = world->space()->getNumContacts();
        delete world;
        scene->Delete();
        state.ResumeTiming();
    }
    state.counters["ms_per_step"] = benchmark::Counter(
        steps * state.iterations() / 1000.0, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["peak_rss_MB"] = peakRssMB();
    state.counters["last_contacts"] = double(contacts);
    state.counters["budget"] = double(iContactBudget::kDefaultContactBudget);
}

// A 1 kg unit box on the floor and one of range(0) kg on it, range(1) solver iterations, 5 s.
void BM_HeavyOnLight(benchmark::State& state) {
    const int steps = 300;
    float strayed = 0;
    for (auto _ : state) {
        state.PauseTiming();
        iPhysicsScene* scene = CreatePhysicsScene(nullptr);
        settingsOf(scene)->setSolverIterations(int(state.range(1)));
        scene->update(0);
        World* world = new World(scene);
        world->ground();
        world->box(Vector(0, 0.5f, 0), Vector(0.5f, 0.5f, 0.5f), 1.0f);
        RBDynamics* heavy =
            world->box(Vector(0, 1.5f, 0), Vector(0.5f, 0.5f, 0.5f), float(state.range(0)))->getDynamics();
        strayed = 0;
        state.ResumeTiming();
        for (int i = 0; i < steps; ++i) {
            runSteps(scene, i, 1);
            strayed = std::max(strayed, (heavy->position - Vector(0, 1.5f, 0)).length());
        }
        state.PauseTiming();
        delete world;
        scene->Delete();
        state.ResumeTiming();
    }
    state.counters["us_per_step"] = benchmark::Counter(
        steps * state.iterations() / 1e6, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["strayed_m"] = strayed;
}

} // namespace

BENCHMARK(BM_CrowdAtOnePoint)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_HeavyOnLight)
    ->ArgNames({"ratio", "iterations"})
    ->ArgsProduct({{100, 1000, 10000}, {4, 8, 16, 32, 64}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
GUARDIAN_PINNED_BENCHMARK_MAIN()
