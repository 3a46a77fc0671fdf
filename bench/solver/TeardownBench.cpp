// TeardownBench.cpp - what deleting a scene's contents costs against its size: N unit boxes resting in a
// pile (so the space holds contacts and touching pairs), then every geometry, body frame and the space
// deleted in creation order (World's destructor: what a game does at a level change or on quitting).
// Counter: ns per body; main() prints the 10,000-box figure as a ratio to the 1,000-box one measured in the
// same run. Linear teardown keeps it near 1; a cost per body that grows with the count (a linear search
// per deletion) shows here as a ratio near 10. The second argument attaches a contact observer
// (iContactEvents.h) to the space: the pairs it was told of are kept, and each body's death must not walk
// them all.
#include "MathDeclarations.h"
#include "World.h"
#include "iContactEvents.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneSettings.h"

#include "../PinnedBenchmarkMain.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>

namespace {

std::map<std::pair<int, int>, double>& nsPerBody() { // (boxes, observed) -> ns
    static std::map<std::pair<int, int>, double> figures;
    return figures;
}

struct CountingObserver final : ContactObserver {
    long calls = 0;
    void onBegin(const ContactPair&) override { ++calls; }
    void onPersist(const ContactPair&) override { ++calls; }
    void onEnd(const ContactPair&) override { ++calls; }
};

void BM_Teardown(benchmark::State& state) {
    const int boxes = int(state.range(0));
    const bool observed = state.range(1) != 0;
    double total = 0;
    for (auto _ : state) {
        iPhysicsScene* scene = CreatePhysicsScene(nullptr);
        settingsOf(scene)->setSleepingEnabled(false);
        scene->update(0);
        auto* world = new World(scene);
        world->ground();
        CountingObserver observer;
        if (observed) contactEventsOf(world->space())->addObserver(&observer);
        const int side = int(std::ceil(std::sqrt(boxes / 4.0)));
        for (int i = 0; i < boxes; ++i) { // four layers touching: contacts with the ground and between boxes
            const int layer = i / (side * side), ix = i % side, iz = (i / side) % side;
            world->box(Vector(1.2f * ix, 0.5f + 0.99f * layer, 1.2f * iz), Vector(0.5f, 0.5f, 0.5f), 1.0f);
        }
        scene->update(17); // one step: contacts and touching pairs exist
        const auto t0 = std::chrono::steady_clock::now();
        delete world; // (the space detaches its observer as it goes)
        scene->Delete();
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        state.SetIterationTime(seconds);
        total += seconds;
    }
    const double ns = 1e9 * total / double(state.iterations()) / boxes;
    state.counters["ns_per_body"] = ns;
    nsPerBody()[{boxes, int(observed)}] = ns;
}
BENCHMARK(BM_Teardown)
    ->Args({1000, 0})
    ->Args({10000, 0})
    ->Args({1000, 1})
    ->Args({10000, 1})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

} // namespace

int main(int argc, char** argv) {
    stayOnThisCpuAndSayWhich(); // (PinnedBenchmarkMain.h)
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    const auto& f = nsPerBody();
    for (int observed = 0; observed < 2; ++observed)
        if (f.count({1000, observed}) && f.count({10000, observed}))
            std::printf("teardown per body%s, 10,000 boxes / 1,000 boxes: %.2fx (linear: about 1)\n",
                        observed ? " with a contact observer" : "",
                        f.at({10000, observed}) / f.at({1000, observed}));
    return 0;
}
