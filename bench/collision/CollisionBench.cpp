// CollisionBench.cpp - what the collision detector costs: pair tests per second per shape pair (the
// sphere-sphere figure is the baseline the others are compared with) and populateContactList for 1,000 and
// 5,000 bodies in the simple space, sparse (few contacts) and dense (several contacts per body), at rest and
// moving (continuous sampling at work). Pair finding alone (sort-and-sweep against the persistent tree) and
// whole calls of the simple and octree spaces on 1,000 and 10,000 boxes are in BroadphaseBench.cpp.
#include "../PinnedBenchmarkMain.h"
#include "DefaultSpace.h"
#include "MathEigen.h"
#include "Narrowphase.h"
#include "UserBody.h"
#include "iCOBB.h"
#include "iCSphere.h"
#include "iCollisionSpace.h"
#include "iSimpleCollisionSpace.h"

#include <Eigen/Geometry>
#include <benchmark/benchmark.h>

#include <memory>
#include <random>
#include <vector>

using namespace gcol;

namespace {

std::mt19937 gen(42);
float uni(float a, float b) { return std::uniform_real_distribution<float>(a, b)(gen); }

WorldShape randomShape(ShapeKind k) {
    WorldShape s;
    s.kind = k;
    Vector c(uni(-1, 1), uni(-1, 1), uni(-1, 1));
    if (k == ShapeKind::Sphere) {
        s.sphere.centre = c;
        s.sphere.radius = uni(0.3f, 1.0f);
    } else if (k == ShapeKind::Box) {
        Eigen::Quaternionf q(uni(-1, 1), uni(-1, 1), uni(-1, 1), uni(-1, 1));
        q.normalize();
        Matrix r = gmath::fromBlock3(q.toRotationMatrix());
        s.box.centre = c;
        for (int i = 0; i < 3; ++i) s.box.axis[i] = r.direction(char('x' + i));
        s.box.halfExtents = Vector(uni(0.3f, 1), uni(0.3f, 1), uni(0.3f, 1));
    } else {
        s.plane.normal = Vector(uni(-0.3f, 0.3f), 1, uni(-0.3f, 0.3f)).normalize();
        s.plane.offset = uni(-0.5f, 0.5f);
    }
    return s;
}

// Pair tests per second for kinds (a, b); about half of the random pairs overlap.
void pairBench(benchmark::State& state, ShapeKind a, ShapeKind b) {
    std::vector<WorldShape> as, bs;
    for (int i = 0; i < 1024; ++i) {
        as.push_back(randomShape(a));
        bs.push_back(randomShape(b));
    }
    size_t i = 0, hits = 0;
    ContactManifold m;
    for (auto _ : state) {
        hits += size_t(collideShapes(as[i & 1023], bs[i & 1023], m));
        benchmark::DoNotOptimize(m);
        ++i;
    }
    state.SetItemsProcessed(int64_t(i));
    state.counters["contacts/test"] = double(hits) / double(i ? i : 1);
}

void BM_Pair_SphereSphere(benchmark::State& s) { pairBench(s, ShapeKind::Sphere, ShapeKind::Sphere); }
void BM_Pair_SphereBox(benchmark::State& s) { pairBench(s, ShapeKind::Sphere, ShapeKind::Box); }
void BM_Pair_BoxBox(benchmark::State& s) { pairBench(s, ShapeKind::Box, ShapeKind::Box); }
void BM_Pair_PlaneSphere(benchmark::State& s) { pairBench(s, ShapeKind::Plane, ShapeKind::Sphere); }
void BM_Pair_PlaneBox(benchmark::State& s) { pairBench(s, ShapeKind::Plane, ShapeKind::Box); }
BENCHMARK(BM_Pair_SphereSphere);
BENCHMARK(BM_Pair_SphereBox);
BENCHMARK(BM_Pair_BoxBox);
BENCHMARK(BM_Pair_PlaneSphere);
BENCHMARK(BM_Pair_PlaneBox);

// range(0): bodies; range(1): 0 sparse, 1 dense; range(2): 0 at rest, 1 moving 0.5 m per call (sampled).
void BM_SimpleSpacePopulate(benchmark::State& state) {
    const int n = int(state.range(0));
    const bool dense = state.range(1) != 0, moving = state.range(2) != 0;
    // Half spheres (r 0.5), half boxes (half 0.5): sparse spreads them so that few touch, dense packs them
    // so that each touches a few others.
    const float side = std::cbrt(float(n)) * (dense ? 0.9f : 4.0f);
    iCollisionSpace* space = CreateSimpleCollisionSpace(60);
    DefaultSpace joins(space); // new geometry joins it
    std::vector<std::unique_ptr<UserBody>> bodies;
    std::vector<iCollisionGeometry*> geoms;
    for (int i = 0; i < n; ++i) {
        bodies.emplace_back(new UserBody(Vector(uni(0, side), uni(0, side), uni(0, side))));
        iCollisionGeometry* g = i % 2 ? CreateCSphere(bodies.back().get(), 0.5f)
                                      : CreateCOBB(bodies.back().get(), Vector(0.5f, 0.5f, 0.5f));
        space->add(g);
        geoms.push_back(g);
    }
    space->populateContactList(1.0f / 60); // warm-up: storage sized, previous poses recorded
    float sign = 1.0f;
    for (auto _ : state) {
        if (moving) {
            state.PauseTiming();
            sign = -sign;
            for (size_t i = 0; i < bodies.size(); ++i) // neighbours move opposite ways: 1 m relative
                bodies[i]->getDynamics().position.x += (i % 2 ? 0.5f : -0.5f) * sign;
            state.ResumeTiming();
        }
        space->populateContactList(1.0f / 60);
        benchmark::DoNotOptimize(space->getContactList());
    }
    state.counters["contacts"] = double(space->getNumContacts());
    for (iCollisionGeometry* g : geoms) g->Delete();
    space->Delete();
}
BENCHMARK(BM_SimpleSpacePopulate)
    ->Args({1000, 0, 0})
    ->Args({1000, 1, 0})
    ->Args({5000, 0, 0})
    ->Args({5000, 1, 0})
    ->Args({1000, 0, 1})
    ->Args({1000, 1, 1})
    ->Unit(benchmark::kMillisecond);

} // namespace

GUARDIAN_PINNED_BENCHMARK_MAIN()
