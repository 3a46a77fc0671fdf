// StepBench.cpp - body-steps per second of 10^4 free, spinning, falling bodies with drag, for each
// integrator, and each integrator's throughput as a ratio to semi-implicit Euler measured in the same run.
//
// One benchmark iteration is one scene update of exactly one fixed step (100 Hz, now += 10 ms), so it
// includes everything a step does: validation before and after, composite setup, integration, and no
// frames (the bodies have none, to measure the simulator rather than the frames).
#include "iPhysicsScene.h"
#include "iPhysicsSceneSettings.h"
#include "iRigidBody.h"

#include "../PinnedBenchmarkMain.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace {

constexpr int BODIES = 10000;

void stepBodies(benchmark::State& state) {
    Integrator integrator = Integrator(state.range(0));
    iPhysicsScene* scene = CreatePhysicsScene(nullptr);
    settingsOf(scene)->setStepRate(100);
    settingsOf(scene)->setIntegrator(integrator);
    std::mt19937 rng(12345);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (int i = 0; i < BODIES; ++i) {
        RBDynamics& d = CreateRigidBody(nullptr)->getDynamics();
        d.position = Vector(u(rng) * 100, u(rng) * 100 + 200, u(rng) * 100);
        d.velocity = Vector(u(rng), u(rng), u(rng)) * 5.0f;
        d.angularVelocity = Vector(u(rng), u(rng), u(rng)) * 3.0f;
        d.dragCoefficient = 0.1f;
        d.setInertiaTensor(getBoxInertiaTensor(1.0f, Vector(0.5f, 1.0f, 1.5f)));
    }
    int now = 0;
    scene->update(now);
    for (auto _ : state) {
        now += 10;
        scene->update(now);
    }
    state.SetItemsProcessed(state.iterations() * BODIES);
    scene->Delete();
}

const char* name(long i) {
    switch (i) {
    case INTEGRATOR_SemiImplicitEuler:
        return "semi-implicit Euler";
    case INTEGRATOR_ExplicitEuler:
        return "explicit Euler";
    case INTEGRATOR_VelocityVerlet:
        return "velocity Verlet";
    default:
        return "RK4";
    }
}

// Keeps items_per_second of each run so that main can print the ratios after the usual table.
class RatioReporter final : public benchmark::ConsoleReporter {
public:
    std::map<std::string, double> rates;
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& r : runs) {
            auto it = r.counters.find("items_per_second");
            if (it != r.counters.end() && r.run_type == Run::RT_Iteration)
                rates[r.benchmark_name()] = it->second;
        }
        ConsoleReporter::ReportRuns(runs);
    }
};

} // namespace

BENCHMARK(stepBodies)
    ->Arg(INTEGRATOR_SemiImplicitEuler)
    ->Arg(INTEGRATOR_ExplicitEuler)
    ->Arg(INTEGRATOR_VelocityVerlet)
    ->Arg(INTEGRATOR_RK4)
    ->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) {
    stayOnThisCpuAndSayWhich(); // (PinnedBenchmarkMain.h)
    benchmark::Initialize(&argc, argv);
    RatioReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    auto base = reporter.rates.find("stepBodies/" + std::to_string(int(INTEGRATOR_SemiImplicitEuler)));
    if (base == reporter.rates.end() || base->second <= 0) return 0;
    std::printf("\n%-22s %16s %10s\n", "integrator", "body-steps/s", "ratio");
    for (long i : {long(INTEGRATOR_SemiImplicitEuler), long(INTEGRATOR_ExplicitEuler),
                   long(INTEGRATOR_VelocityVerlet), long(INTEGRATOR_RK4)}) {
        auto it = reporter.rates.find("stepBodies/" + std::to_string(i));
        if (it != reporter.rates.end())
            std::printf("%-22s %16.3e %10.3f\n", name(i), it->second, it->second / base->second);
    }
    benchmark::Shutdown();
    return 0;
}
