// ChainBench.cpp - the cost of one scene update of an attachment chain, by depth: an update must be linear in
// the depth (a 1,000-deep chain once took 2.4 s an update: each world pose was recomputed recursively).
//
// One iteration is one update of exactly one fixed step (100 Hz, now += 10 ms) of a falling chain whose every
// link is bound to a plain frame (so the frame writes are measured too). main prints the time per link at
// each depth and the ratio of the 1,000-deep update to the 100-deep one: ~10 when linear, ~100 when
// quadratic.
#include "Frame.h"
#include "iPhysicsFrame.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneSettings.h"
#include "iRigidBody.h"

#include "../PinnedBenchmarkMain.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace {

void stepChain(benchmark::State& state) {
    const int depth = int(state.range(0));
    iPhysicsScene* scene = CreatePhysicsScene(nullptr);
    settingsOf(scene)->setStepRate(100);
    std::vector<iFrame*> frames;
    RBDynamics* parent = nullptr;
    for (int i = 0; i < depth; ++i) {
        iFrame* f = CreateFrame();
        f->translate(0.5f * float(i), 100.0f, 0.0f);
        f->rotatez(0.01f * float(i));
        frames.push_back(f);
        RBDynamics& d = CreateRigidBody(f)->getDynamics();
        d.attachTo(parent); // keeps its world pose: a bent rod of links 0.5 m apart
        parent = &d;
    }
    int now = 0;
    scene->update(now);
    for (auto _ : state) {
        now += 10;
        scene->update(now);
    }
    state.SetItemsProcessed(state.iterations() * depth);
    scene->Delete();
    for (iFrame* f : frames) f->Delete();
}

// The same chain built the seed's way: PhysicsFrames attached to each other. The course framework's Frame
// computes world() by walking its parents, so writing each frame costs O(depth) in the framework itself.
void stepPhysicsFrameChain(benchmark::State& state) {
    const int depth = int(state.range(0));
    iPhysicsScene* scene = CreatePhysicsScene(nullptr);
    settingsOf(scene)->setStepRate(100);
    std::vector<iPhysicsFrame*> frames;
    for (int i = 0; i < depth; ++i) {
        iPhysicsFrame* f = CreatePhysicsFrame();
        f->translate(0.5f * float(i), 100.0f, 0.0f);
        f->rotatez(0.01f * float(i));
        if (!frames.empty()) f->attachTo(frames.back());
        frames.push_back(f);
    }
    int now = 0;
    scene->update(now);
    for (auto _ : state) {
        now += 10;
        scene->update(now);
    }
    state.SetItemsProcessed(state.iterations() * depth);
    for (size_t i = frames.size(); i-- > 0;) frames[i]->Delete(); // children first
    scene->Delete();
}

class TimeReporter final : public benchmark::ConsoleReporter {
public:
    std::map<std::string, double> seconds; // per update, by benchmark name ("stepChain/1000")
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& r : runs)
            if (r.run_type == Run::RT_Iteration && r.iterations > 0)
                seconds[r.benchmark_name()] =
                    r.GetAdjustedRealTime() / benchmark::GetTimeUnitMultiplier(r.time_unit);
        ConsoleReporter::ReportRuns(runs);
    }
};

} // namespace

BENCHMARK(stepChain)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(stepPhysicsFrameChain)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) {
    stayOnThisCpuAndSayWhich(); // (PinnedBenchmarkMain.h)
    benchmark::Initialize(&argc, argv);
    TimeReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    for (const char* name : {"stepChain", "stepPhysicsFrameChain"}) {
        const std::string base = name;
        auto shallow = reporter.seconds.find(base + "/100"), deep = reporter.seconds.find(base + "/1000");
        if (shallow == reporter.seconds.end() || deep == reporter.seconds.end() || shallow->second <= 0)
            continue;
        std::printf("%-22s depth 100: %9.3f ms, depth 1000: %9.3f ms an update; ratio %.1f (linear: 10, "
                    "quadratic: 100)\n",
                    name, shallow->second * 1e3, deep->second * 1e3, deep->second / shallow->second);
    }
    benchmark::Shutdown();
    return 0;
}
