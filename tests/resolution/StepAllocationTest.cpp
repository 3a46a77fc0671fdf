// StepAllocationTest.cpp - once a scene is warm, a step does not touch the heap: every working array (space,
// islands, solver, continuous stage, events) keeps its storage between steps. Counted by the counting
// operator new this test program links (tests/CountingNew.h; it only counts: other tests run as usual).
#include "CountingNew.h"
#include "SceneFixture.h"

#include "Scenes.h"
#include "iPhysicsSceneSettings.h"
#include "iSnapshots.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace resolution_test;

namespace {

// Allocations made by `steps` further steps of a scene that has already run `warm` steps.
long allocationsOfWarmSteps(SceneFixture& f, int warm, int steps) {
    f.steps(warm);
    const long before = guardian_test::allocationCount();
    f.steps(steps);
    return guardian_test::allocationCount() - before;
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
    // events). Its fourth shot leaves at frame 210; the 60 steps after it (without the next shot: making a
    // body allocates, of course) are run, then run again from a snapshot taken before them, and the second
    // run is counted. Warm means "has been this big before": a step may meet its arrays' largest size yet
    // (the longest continuous sweep, the most contacts) and grow them, and which steps do that depends on the
    // trajectory, so on the solver's rounding. The replay is bit-identical (iSnapshots.h), so every size it
    // meets was met on the first run: it must not allocate at all.
    SceneFixture f(4);
    const SceneSpec* spec = findScene("shooting");
    spec->build(*f.world);
    for (int frame = 0; frame < 212; ++frame) f.steps(1, [&] { spec->act(*f.world, frame); });
    iSnapshot* snapshot = snapshotsOf(f.scene)->takeSnapshot();
    ASSERT_NE(snapshot, nullptr);
    const long at = f.stepCount();
    const long first = allocationsOfWarmSteps(f, 0, 60);
    const unsigned long long state = f.stateHash();
    ASSERT_TRUE(snapshotsOf(f.scene)->restoreSnapshot(snapshot));
    f.rewindTo(at);
    const long replayed = allocationsOfWarmSteps(f, 0, 60);
    snapshot->Delete();
    std::printf("the gallery's 60 steps after the fourth shot: %ld allocations, replayed: %ld\n", first,
                replayed);
    ASSERT_EQ(f.stateHash(), state) << "the replay must be the same steps";
    EXPECT_EQ(replayed, 0);
}

TEST(StepAllocation, APyramidFallingAsleepDoesNotAllocate) {
    // The step a settled pyramid falls asleep sets aside every manifold it rests on at once (kept, unsolved,
    // until it wakes): a list that was empty until then. It had room since the contacts first grew.
    SceneFixture f(4);
    buildPyramid(*f.world, 10);
    const RBDynamics* top = f.world->bodies().back()->getDynamics();
    f.steps(30);
    ASSERT_FALSE(top->sleeping) << "the pyramid must fall asleep within the counted steps";
    const long before = guardian_test::allocationCount();
    int steps = 0;
    while (!top->sleeping && steps < 600) {
        f.steps(1);
        ++steps;
    }
    f.steps(10);
    const long made = guardian_test::allocationCount() - before;
    ASSERT_TRUE(top->sleeping) << "it did not fall asleep in 10 s";
    EXPECT_EQ(made, 0) << "asleep after " << steps << " more steps";
}

TEST(StepAllocation, AWaveWakingSixtyFourDominoesAllocatesLogarithmicallyOften) {
    // A row of 64 dominoes falls asleep; the first is pushed and the wave wakes them one after another over
    // 15 s, so the steps' working arrays (bodies swept, bodies and manifolds solved, contact pairs) reach a
    // new largest size again and again. Each grows geometrically, as push_back does (GrowingStorage.h): a
    // handful of allocations each over the wave, 87 in all. Before, vector::assign(n, value) and reserve(n)
    // reallocated to exactly n at every new size: 395 (the manifold list alone 126).
    SceneFixture f(4);
    buildDominoes(*f.world, 64);
    RBDynamics* first = f.world->bodies().front()->getDynamics();
    first->velocity = first->angularVelocity = first->angularMomentum = Vector();
    f.seconds(3.0f);
    const RBDynamics* last = f.world->bodies().back()->getDynamics();
    ASSERT_TRUE(first->sleeping && last->sleeping) << "the row must rest before the push";
    first->ApplyImpulse(Vector(0.6f, 0, 0), first->position + Vector(0, 0.45f, 0));
    const long before = guardian_test::allocationCount();
    f.seconds(15.0f);
    const long allocations = guardian_test::allocationCount() - before;
    std::printf("a wave through 64 dominoes: %ld allocations\n", allocations);
    EXPECT_LT(last->position.y, 0.4f) << "the wave must reach the last domino";
    EXPECT_LE(allocations, 150);
}
