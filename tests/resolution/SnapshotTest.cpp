// SnapshotTest.cpp - iSnapshots: a snapshot taken in the middle of a falling pile, restored after the pile
// ran on, re-simulates the same steps bit for bit (with the simple and the octree space, sleeping and the
// continuous stage on); restoring is refused, with nothing changed, when the scene is not the same any more.
#include "ErrorRecorder.h"
#include "SceneFixture.h"
#include "Scenes.h"
#include "iCollisionListener.h"
#include "iFixedUpdater.h"
#include "iOctreeCollisionSpace.h"
#include "iPhysicsSceneHooks.h"
#include "iSimpleCollisionSpace.h"
#include "iSnapshots.h"

#include <gtest/gtest.h>

#include <cmath>

using guardian_test::ErrorRecorder;
using resolution_test::SceneFixture;

namespace {

// Steps from..to-1 of a 60 Hz scene, by update(now) as a game calls it.
void runSteps(iPhysicsScene* scene, int from, int to) {
    for (int i = from + 1; i <= to; ++i) scene->update(int(std::ceil(i * 1000.0 / 60.0)));
}

struct Counting final : iCollisionListener {
    long calls = 0;
    void HitWall(iRigidBody*, Vector, Vector) override { ++calls; }
};

// The frames the game draws, as bits (interpolation included).
unsigned long long frameHash(const World& world) {
    unsigned long long h = 1469598103934665603ull;
    for (const iPhysicsFrame* f : world.bodies()) {
        const Matrix& m = const_cast<iPhysicsFrame*>(f)->world();
        const unsigned char* b = reinterpret_cast<const unsigned char*>(m.data());
        for (size_t i = 0; i < 16 * sizeof(float); ++i) h = (h ^ b[i]) * 1099511628211ull;
    }
    return h;
}

void expectReplayIsBitIdentical(iCollisionSpace* space) {
    SceneFixture s(4, space);
    buildBoxPile(*s.world, 60, 7u);
    Counting listener;
    for (const iPhysicsFrame* f : s.world->bodies())
        const_cast<iPhysicsFrame*>(f)->getRB()->attachListener(&listener);
    runSteps(s.scene, 0, 90); // mid-fall: some boxes landed, some in the air
    iSnapshot* snap = snapshotsOf(s.scene)->takeSnapshot();
    ASSERT_NE(snap, nullptr);
    const long callsAtSnapshot = listener.calls;
    runSteps(s.scene, 90, 300); // lands, piles up, partly sleeps
    const unsigned long long state = s.stateHash(), frames = frameHash(*s.world);
    const long calls = listener.calls - callsAtSnapshot;

    ASSERT_TRUE(snapshotsOf(s.scene)->restoreSnapshot(snap));
    listener.calls = callsAtSnapshot;
    runSteps(s.scene, 90, 300);
    EXPECT_EQ(s.stateHash(), state);
    EXPECT_EQ(frameHash(*s.world), frames);
    EXPECT_EQ(listener.calls - callsAtSnapshot, calls);
    // And once more from the same snapshot.
    ASSERT_TRUE(snapshotsOf(s.scene)->restoreSnapshot(snap));
    runSteps(s.scene, 90, 300);
    EXPECT_EQ(s.stateHash(), state);
    snap->Delete();
    for (const iPhysicsFrame* f : s.world->bodies())
        const_cast<iPhysicsFrame*>(f)->getRB()->detachListener(&listener);
}

} // namespace

TEST(Snapshot, AFallingPileReplaysBitIdenticallyInTheSimpleSpace) { expectReplayIsBitIdentical(nullptr); }

// A sampling space sweeps each geometry from its previous pose: that pose is part of the space's snapshot.
TEST(Snapshot, AFallingPileReplaysBitIdenticallyInASamplingSpace) {
    expectReplayIsBitIdentical(CreateSimpleCollisionSpace(240));
}

TEST(Snapshot, AFallingPileReplaysBitIdenticallyInTheOctreeSpace) {
    expectReplayIsBitIdentical(CreateOctreeCollisionSpace());
}

// A snapshot is not a copy of the scene's structure: with a body added since, or of another scene, or during
// an update, it is refused with an error and the scene goes on as if nothing was asked.
TEST(Snapshot, RefusedWhenTheSceneChangedOrIsUpdating) {
    SceneFixture s(4);
    buildBoxPile(*s.world, 10, 3u);
    runSteps(s.scene, 0, 30);
    iSnapshot* snap = snapshotsOf(s.scene)->takeSnapshot();
    ASSERT_NE(snap, nullptr);
    {
        ErrorRecorder errors;
        iPhysicsScene* other = CreatePhysicsScene(nullptr);
        EXPECT_FALSE(snapshotsOf(other)->restoreSnapshot(snap));
        other->Delete(); // s is the active scene again: new bodies go there
        EXPECT_FALSE(snapshotsOf(s.scene)->restoreSnapshot(nullptr));
        EXPECT_EQ(errors.count(), 2u);
    }
    s.world->sphere(Vector(0, 20, 0), 0.5f, 1.0f);
    runSteps(s.scene, 30, 40);
    const unsigned long long before = s.stateHash();
    {
        ErrorRecorder errors;
        EXPECT_FALSE(snapshotsOf(s.scene)->restoreSnapshot(snap));
        EXPECT_EQ(errors.count(), 1u);
    }
    EXPECT_EQ(s.stateHash(), before);

    struct RestoreInStep final : iFixedUpdater {
        const iSnapshot* snap = nullptr;
        bool result = true;
        void fixedUpdate(iPhysicsScene* scene, float) override {
            result = snapshotsOf(scene)->restoreSnapshot(snap) || snapshotsOf(scene)->takeSnapshot();
        }
    } updater;
    iSnapshot* fresh = snapshotsOf(s.scene)->takeSnapshot();
    updater.snap = fresh;
    ASSERT_TRUE(hooksOf(s.scene)->addFixedUpdater(&updater));
    {
        ErrorRecorder errors;
        runSteps(s.scene, 40, 41);
        EXPECT_FALSE(updater.result);
        EXPECT_EQ(errors.count(), 2u);
    }
    hooksOf(s.scene)->removeFixedUpdater(&updater);
    fresh->Delete();
    snap->Delete();
}
