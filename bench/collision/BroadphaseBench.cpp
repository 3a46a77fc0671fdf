// BroadphaseBench.cpp - pair finding of the two broadphases and whole calls of the two spaces, measured in
// the same run so their ratio is a counter.
//
// BM_PairFinding: the candidate-pair stage alone (Broadphase::findPairs) on n boxes (half extents 0.5 m,
// turned at random), sort-and-sweep (the simple space's) against the persistent tree (the octree space's),
// given the same entries. range(0): boxes; range(1): 0 sparse (few touch), 1 dense (each touches several);
// range(2): what happened since the last call: 0 nothing, 1 every box drifted 0.02 m (a body at 1.2 m/s over
// a 60 Hz step: most stay inside their fat boxes), 2 every box jumped 0.5 m (every one leaves its fat box).
// BM_SpaceSimpleVsOctree: populateContactList of the simple and the octree space over twin geometry on the
// same bodies (range as above; continuous sampling on).
// BM_QueriesSimpleVsOctree: 100 ray casts (20 m) and 100 sphere overlaps (r 2 m) in each space (range(0):
// boxes; sparse); range(1): 0 the bodies as at the spaces' last call, 1 every body drifted 0.02 m since
// before each round of queries (a game querying after a step moved its bodies). Each space answers each
// round twice, in a batch (iCollisionQueries.h: its bodies read once for the round) and without.
#include "DefaultSpace.h"
#include "MathEigen.h"
#include "SimpleCollisionSpace.h"
#include "SweepAndPrune.h"
#include "TreeBroadphase.h"
#include "UserBody.h"
#include "iCOBB.h"
#include "iCollisionQueries.h"
#include "iOctreeCollisionSpace.h"
#include "iSimpleCollisionSpace.h"

#include <Eigen/Geometry>
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}

struct Boxes {
    std::mt19937 gen{42};
    std::vector<std::unique_ptr<UserBody>> bodies;
    std::vector<Vector> drift;
    float uni(float a, float b) { return std::uniform_real_distribution<float>(a, b)(gen); }
    Boxes(int n, bool dense) {
        const float side = std::cbrt(float(n)) * (dense ? 0.9f : 4.0f);
        for (int i = 0; i < n; ++i) {
            bodies.emplace_back(new UserBody(Vector(uni(0, side), uni(0, side), uni(0, side))));
            Eigen::Quaternionf q(uni(-1, 1), uni(-1, 1), uni(-1, 1), uni(-1, 1));
            bodies.back()->getDynamics().orientation = gmath::fromBlock3(q.normalized().toRotationMatrix());
            drift.push_back(Vector(uni(-1, 1), uni(-1, 1), uni(-1, 1)).normalize() * 0.02f);
        }
    }
    // What happens between two calls (range(2)); k counts the calls.
    void move(int how, int k) {
        for (size_t i = 0; i < bodies.size(); ++i) {
            Vector& p = bodies[i]->getDynamics().position;
            if (how == 1) p += (k / 200) % 2 ? -drift[i] : drift[i]; // to and fro, 4 m each way
            if (how == 2) p.x += (i % 2 ? 0.5f : -0.5f) * (k % 2 ? 1.0f : -1.0f);
        }
    }
};

// Entries as the space gathers them (current world boxes of the geometry), without the space's other work.
void gather(const std::vector<iCollisionGeometry*>& geoms, std::vector<SimpleCollisionSpace::Entry>& out,
            std::vector<gcol::WorldShape>& shapes) {
    out.resize(geoms.size());
    for (size_t i = 0; i < geoms.size(); ++i) {
        SimpleCollisionSpace::Entry& e = out[i];
        e.g = CollisionGeometry::from(geoms[i]);
        e.plane = false;
        e.g->currentPose(e.origin, e.rotation);
        shapes.clear();
        e.g->worldShapes(e.origin, e.rotation, shapes);
        gcol::shapeAabb(shapes[0], e.box);
    }
}

void BM_PairFinding(benchmark::State& state) {
    const int n = int(state.range(0)), how = int(state.range(2));
    Boxes boxes(n, state.range(1) != 0);
    iCollisionSpace* holder = CreateSimpleCollisionSpace(); // the geometry's space (never populated)
    std::vector<iCollisionGeometry*> geoms;
    {
        DefaultSpace joins(holder);
        for (auto& b : boxes.bodies) geoms.push_back(CreateCOBB(b.get(), Vector(0.5f, 0.5f, 0.5f)));
    }
    SweepAndPrune sap;
    TreeBroadphase tree;
    std::vector<SimpleCollisionSpace::Entry> entries;
    std::vector<gcol::WorldShape> shapes;
    gather(geoms, entries, shapes);
    tree.findPairs(entries, nullptr); // warm-up: proxies made
    double sapTime = 0, treeTime = 0;
    size_t sapPairs = 0, treePairs = 0;
    int k = 0;
    for (auto _ : state) {
        boxes.move(how, ++k);
        gather(geoms, entries, shapes);
        auto t0 = Clock::now();
        sapPairs = sap.findPairs(entries, nullptr).size(); // (any box may have changed)
        auto t1 = Clock::now();
        treePairs = tree.findPairs(entries, nullptr).size();
        auto t2 = Clock::now();
        sapTime += seconds(t0, t1);
        treeTime += seconds(t1, t2);
        state.SetIterationTime(seconds(t1, t2));
    }
    const double iterations = double(state.iterations());
    state.counters["sap_ms"] = 1e3 * sapTime / iterations;
    state.counters["tree_ms"] = 1e3 * treeTime / iterations;
    state.counters["sap_over_tree"] = sapTime / treeTime;
    state.counters["pairs"] = double(treePairs);
    if (sapPairs != treePairs) state.SkipWithError("the broadphases found different pairs");
    for (iCollisionGeometry* g : geoms) g->Delete();
    holder->Delete();
}
BENCHMARK(BM_PairFinding)
    ->ArgsProduct({{1000, 10000}, {0, 1}, {0, 1, 2}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

void BM_SpaceSimpleVsOctree(benchmark::State& state) {
    const int n = int(state.range(0)), how = int(state.range(2));
    Boxes boxes(n, state.range(1) != 0);
    iCollisionSpace* simple = CreateSimpleCollisionSpace(60);
    iCollisionSpace* octree = CreateOctreeCollisionSpace(60);
    std::vector<iCollisionGeometry*> geoms;
    for (iCollisionSpace* space : {simple, octree}) {
        DefaultSpace joins(space);
        for (auto& b : boxes.bodies) geoms.push_back(CreateCOBB(b.get(), Vector(0.5f, 0.5f, 0.5f)));
        space->populateContactList(1.0f / 60); // warm-up
    }
    double simpleTime = 0, octreeTime = 0;
    int k = 0;
    for (auto _ : state) {
        boxes.move(how, ++k);
        auto t0 = Clock::now();
        simple->populateContactList(1.0f / 60);
        auto t1 = Clock::now();
        octree->populateContactList(1.0f / 60);
        auto t2 = Clock::now();
        simpleTime += seconds(t0, t1);
        octreeTime += seconds(t1, t2);
        state.SetIterationTime(seconds(t1, t2));
    }
    const double iterations = double(state.iterations());
    state.counters["simple_ms"] = 1e3 * simpleTime / iterations;
    state.counters["octree_ms"] = 1e3 * octreeTime / iterations;
    state.counters["simple_over_octree"] = simpleTime / octreeTime;
    state.counters["contacts"] = double(octree->getNumContacts());
    if (simple->getNumContacts() != octree->getNumContacts()) state.SkipWithError("different contact counts");
    for (iCollisionGeometry* g : geoms) g->Delete();
    simple->Delete();
    octree->Delete();
}
BENCHMARK(BM_SpaceSimpleVsOctree)
    ->ArgsProduct({{1000, 10000}, {0, 1}, {0, 1, 2}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

void BM_QueriesSimpleVsOctree(benchmark::State& state) {
    const int n = int(state.range(0));
    const bool drifting = state.range(1) != 0;
    int round = 0;
    Boxes boxes(n, false);
    iCollisionSpace* simple = CreateSimpleCollisionSpace(60);
    iCollisionSpace* octree = CreateOctreeCollisionSpace(60);
    std::vector<iCollisionGeometry*> geoms;
    for (iCollisionSpace* space : {simple, octree}) {
        DefaultSpace joins(space);
        for (auto& b : boxes.bodies) geoms.push_back(CreateCOBB(b.get(), Vector(0.5f, 0.5f, 0.5f)));
        space->populateContactList(1.0f / 60);
    }
    const float side = std::cbrt(float(n)) * 4.0f;
    std::vector<Vector> origins, dirs;
    for (int i = 0; i < 100; ++i) {
        origins.push_back(Vector(boxes.uni(0, side), boxes.uni(0, side), boxes.uni(0, side)));
        dirs.push_back(Vector(boxes.uni(-1, 1), boxes.uni(-1, 1), boxes.uni(-1, 1)));
    }
    std::vector<iCollisionGeometry*> found;
    size_t hits[4] = {0, 0, 0, 0};
    auto run = [&](iCollisionSpace* space, size_t& h, bool batched = false) {
        iCollisionQueries* q = queriesOf(space);
        QueryBatch batch(batched ? q : nullptr); // the bodies read once for the 200 queries, not once each
        for (int i = 0; i < 100; ++i) {
            RayHit hit;
            h += q->rayCast(origins[size_t(i)], dirs[size_t(i)], 20.0f, hit) ? 1 : 0;
            h += q->overlapSphere(origins[size_t(i)], 2.0f, found);
        }
    };
    // Each space answers batched first after a move (it pays for bringing the moved boxes up to date), then
    // one query at a time.
    double simpleTime = 0, octreeTime = 0, batchedTime = 0, simpleBatchedTime = 0;
    for (auto _ : state) {
        if (drifting) boxes.move(1, round++);
        auto t0 = Clock::now();
        run(octree, hits[2], true);
        auto t1 = Clock::now();
        run(octree, hits[1]);
        auto t2 = Clock::now();
        run(simple, hits[3], true);
        auto t3 = Clock::now();
        run(simple, hits[0]);
        auto t4 = Clock::now();
        batchedTime += seconds(t0, t1);
        octreeTime += seconds(t1, t2);
        simpleBatchedTime += seconds(t2, t3);
        simpleTime += seconds(t3, t4);
        state.SetIterationTime(seconds(t1, t2));
    }
    const double iterations = double(state.iterations());
    state.counters["simple_ms"] = 1e3 * simpleTime / iterations;
    state.counters["simple_batched_ms"] = 1e3 * simpleBatchedTime / iterations;
    state.counters["octree_ms"] = 1e3 * octreeTime / iterations;
    state.counters["octree_batched_ms"] = 1e3 * batchedTime / iterations;
    state.counters["simple_over_octree"] = simpleTime / octreeTime;
    state.counters["octree_over_batched"] = octreeTime / batchedTime;
    state.counters["simple_over_batched"] = simpleTime / simpleBatchedTime;
    if (hits[0] != hits[1] || hits[1] != hits[2] || hits[2] != hits[3])
        state.SkipWithError("the spaces answered differently");
    for (iCollisionGeometry* g : geoms) g->Delete();
    simple->Delete();
    octree->Delete();
}
BENCHMARK(BM_QueriesSimpleVsOctree)
    ->ArgsProduct({{1000, 10000}, {0, 1}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

} // namespace
