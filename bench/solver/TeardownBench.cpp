// TeardownBench.cpp - what deleting a scene's contents costs against its size: N unit boxes resting in a
// pile (so the space holds contacts and touching pairs), then every geometry, body frame and the space
// deleted in creation order (World's destructor: what a game does at a level change or on quitting).
// Counter: ns per body; main() prints the 10,000-box figure as a ratio to the 1,000-box one measured in the
// same run. Linear teardown keeps it near 1; a cost per body that grows with the count (a linear search
// per deletion) shows here as a ratio near 10.
#include "MathDeclarations.h"
#include "World.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneSettings.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>

namespace {

std::map<int, double>& nsPerBody() {
    static std::map<int, double> figures;
    return figures;
}

void BM_Teardown(benchmark::State& state) {
    const int boxes = int(state.range(0));
    double total = 0;
    for (auto _ : state) {
        iPhysicsScene* scene = CreatePhysicsScene(nullptr);
        settingsOf(scene)->setSleepingEnabled(false);
        scene->update(0);
        auto* world = new World(scene);
        world->ground();
        const int side = int(std::ceil(std::sqrt(boxes / 4.0)));
        for (int i = 0; i < boxes; ++i) { // four layers touching: contacts with the ground and between boxes
            const int layer = i / (side * side), ix = i % side, iz = (i / side) % side;
            world->box(Vector(1.2f * ix, 0.5f + 0.99f * layer, 1.2f * iz), Vector(0.5f, 0.5f, 0.5f), 1.0f);
        }
        scene->update(17); // one step: contacts and touching pairs exist
        const auto t0 = std::chrono::steady_clock::now();
        delete world;
        scene->Delete();
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        state.SetIterationTime(seconds);
        total += seconds;
    }
    const double ns = 1e9 * total / double(state.iterations()) / boxes;
    state.counters["ns_per_body"] = ns;
    nsPerBody()[boxes] = ns;
}
BENCHMARK(BM_Teardown)->Arg(1000)->Arg(10000)->UseManualTime()->Unit(benchmark::kMillisecond);

} // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    const auto& f = nsPerBody();
    if (f.count(1000) && f.count(10000))
        std::printf("teardown per body, 10,000 boxes / 1,000 boxes: %.2fx (linear: about 1)\n",
                    f.at(10000) / f.at(1000));
    return 0;
}
