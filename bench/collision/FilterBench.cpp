// FilterBench.cpp - what collision filters and contact events cost, measured in one run as ratios against
// the same space without them.
//
// BM_FilterCost: populateContactList (sampling on) of three octree spaces over twin geometry on the same n
// boxes (dense: each touches several; every box drifts 0.02 m a call): "base" (default filters: every pair
// passes the layer test, no observer), "layered" (half the boxes are debris, a layer whose mask leaves out
// its own layer: debris-debris pairs are filtered before their exact test), "observed" (default filters, one
// ContactObserver attached: begin/persist/end computed and delivered every call). range(0): boxes.
#include "DefaultSpace.h"
#include "MathEigen.h"
#include "UserBody.h"
#include "iCOBB.h"
#include "iCollisionFilter.h"
#include "iContactEvents.h"
#include "iOctreeCollisionSpace.h"

#include <Eigen/Geometry>
#include <benchmark/benchmark.h>

#include <cmath>
#include <ctime>
#include <memory>
#include <random>
#include <vector>

namespace {

// Thread CPU time: the machine is shared, and the three spaces are compared in the same run.
double cpuSeconds() {
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

struct Counter final : ContactObserver {
    long calls = 0;
    void onBegin(const ContactPair&) override { ++calls; }
    void onPersist(const ContactPair&) override { ++calls; }
    void onEnd(const ContactPair&) override { ++calls; }
};

void BM_FilterCost(benchmark::State& state) {
    const int n = int(state.range(0));
    std::mt19937 gen(42);
    auto uni = [&](float a, float b) { return std::uniform_real_distribution<float>(a, b)(gen); };
    std::vector<std::unique_ptr<UserBody>> bodies;
    std::vector<Vector> drift;
    const float side = std::cbrt(float(n)) * 1.5f;
    for (int i = 0; i < n; ++i) {
        bodies.emplace_back(new UserBody(Vector(uni(0, side), uni(0, side), uni(0, side))));
        Eigen::Quaternionf q(uni(-1, 1), uni(-1, 1), uni(-1, 1), uni(-1, 1));
        bodies.back()->getDynamics().orientation = gmath::fromBlock3(q.normalized().toRotationMatrix());
        drift.push_back(Vector(uni(-1, 1), uni(-1, 1), uni(-1, 1)).normalize() * 0.02f);
    }
    iCollisionSpace* spaces[3] = {CreateOctreeCollisionSpace(60), CreateOctreeCollisionSpace(60),
                                  CreateOctreeCollisionSpace(60)};
    std::vector<iCollisionGeometry*> geoms;
    const std::uint32_t kDebris = 2;
    for (int s = 0; s < 3; ++s) {
        DefaultSpace joins(spaces[s]);
        for (size_t i = 0; i < bodies.size(); ++i) {
            geoms.push_back(CreateCOBB(bodies[i].get(), Vector(0.5f, 0.5f, 0.5f)));
            if (s == 1 && i % 2 == 0) {
                filterOf(geoms.back())->setLayer(kDebris);
                filterOf(geoms.back())->setMask(~kDebris);
            }
        }
    }
    Counter counter;
    contactEventsOf(spaces[2])->addObserver(&counter);
    for (iCollisionSpace* s : spaces) s->populateContactList(1.0f / 60); // warm-up
    double time[3] = {0, 0, 0};
    int k = 0;
    for (auto _ : state) {
        ++k;
        for (size_t i = 0; i < bodies.size(); ++i)
            bodies[i]->getDynamics().position += (k / 200) % 2 ? -drift[i] : drift[i];
        for (int s = 0; s < 3; ++s) {
            const double t0 = cpuSeconds();
            spaces[s]->populateContactList(1.0f / 60);
            time[s] += cpuSeconds() - t0;
        }
        state.SetIterationTime(time[0] / k);
    }
    state.counters["base_ms"] = 1e3 * time[0] / k;
    state.counters["layered_over_base"] = time[1] / time[0];
    state.counters["observed_over_base"] = time[2] / time[0];
    state.counters["contacts_base"] = double(spaces[0]->getNumContacts());
    state.counters["contacts_layered"] = double(spaces[1]->getNumContacts());
    benchmark::DoNotOptimize(counter.calls);
    for (iCollisionGeometry* g : geoms) g->Delete();
    for (iCollisionSpace* s : spaces) s->Delete();
}
BENCHMARK(BM_FilterCost)->Arg(1000)->Arg(5000)->UseManualTime()->Unit(benchmark::kMillisecond);

} // namespace
