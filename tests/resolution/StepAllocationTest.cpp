// StepAllocationTest.cpp - once a scene is warm, a step does not touch the heap: every working array (space,
// islands, solver, continuous stage, events) keeps its storage between steps. Counted by replacing the
// global operator new in this test program (it only counts: every other test here runs as usual).
#include "SceneFixture.h"

#include "Scenes.h"
#include "iPhysicsSceneSettings.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

using namespace resolution_test;

namespace {
std::atomic<long> g_allocations{0};
}

// The replacement pairs malloc with free on purpose; GCC cannot see that and warns.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void* operator new(std::size_t n) {
    ++g_allocations;
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t n) {
    ++g_allocations;
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace {

// Allocations made by `steps` further steps of a scene that has already run `warm` steps.
long allocationsOfWarmSteps(SceneFixture& f, int warm, int steps) {
    f.steps(warm);
    const long before = g_allocations.load();
    f.steps(steps);
    return g_allocations.load() - before;
}

} // namespace

TEST(StepAllocation, AnAwakePyramidStepsWithoutAllocating) {
    SceneFixture f(4);
    settingsOf(f.scene)->setSleepingEnabled(false);
    buildPyramid(*f.world, 10);
    EXPECT_EQ(allocationsOfWarmSteps(f, 120, 60), 0);
}

TEST(StepAllocation, AFallingPileWithListenersStepsWithoutAllocating) {
    // The shooting gallery: spheres shot fast (the continuous stage) knock boxes about (new pairs, HitWall
    // events). Its fourth shot leaves at frame 210; the steps after it are counted, without the next shot
    // (making a body allocates, of course).
    SceneFixture f(4);
    const SceneSpec* spec = findScene("shooting");
    spec->build(*f.world);
    for (int frame = 0; frame < 212; ++frame) f.steps(1, [&] { spec->act(*f.world, frame); });
    EXPECT_EQ(allocationsOfWarmSteps(f, 0, 60), 0);
}
