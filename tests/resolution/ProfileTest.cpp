// ProfileTest.cpp - iPhysicsSceneProfile: the phases of the last update() add up to its time, game code's
// time lands in the phase that runs it, and the counts are those of the scene (a box resting on a plane
// touches it at its four bottom corners: 4 contacts, 1 pair, 12 rows).
#include "SceneFixture.h"
#include "iFixedUpdater.h"
#include "iForceGenerator.h"
#include "iPhysicsSceneHooks.h"
#include "iPhysicsSceneProfile.h"

#include <gtest/gtest.h>

#include <chrono>

using resolution_test::SceneFixture;

namespace {

// Busy for `seconds` of wall time (a sleep could overshoot by a scheduler tick; a spin cannot undershoot).
void spin(double seconds) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < until) {
    }
}

struct SlowUpdater final : iFixedUpdater {
    void fixedUpdate(iPhysicsScene*, float) override { spin(0.002); }
};
struct SlowGenerator final : iForceGenerator {
    void addForces(const iRigidBody*, const RigidBodyState&, Vector&, Vector&) override { spin(0.003); }
};

double phaseSum(const PhysicsProfile& p) {
    return p.updaters + p.edits + p.collision + p.islands + p.integration + p.solver + p.continuous +
           p.sleeping + p.events;
}

} // namespace

TEST(Profile, CountsOfABoxRestingOnAPlane) {
    SceneFixture s;
    s.world->ground();
    s.world->box(Vector(0, 0.5f, 0), Vector(0.5f, 0.5f, 0.5f), 1.0f);
    settingsOf(s.scene)->setSleepingEnabled(false);
    s.steps(30);
    const PhysicsProfile& p = profileOf(s.scene)->getProfile();
    EXPECT_EQ(p.steps, 1);
    EXPECT_EQ(p.bodies, 1u);
    EXPECT_EQ(p.awakeBodies, 1u);
    EXPECT_EQ(p.contacts, 4u);
    EXPECT_EQ(p.touchingPairs, 1u);
    EXPECT_EQ(p.solverRows, 12u);
}

// 100 ms at 60 Hz is 6 steps: a 2 ms updater and a 3 ms generator (semi-implicit Euler calls it once a step)
// put at least 12 ms and 18 ms into their phases, and the phases never add up to more than the update.
TEST(Profile, GameCodeTimeLandsInItsPhaseAndPhasesAddUpToTheUpdate) {
    SceneFixture s;
    iPhysicsFrame* ball = s.world->sphere(Vector(0, 10, 0), 0.5f, 1.0f);
    SlowUpdater updater;
    SlowGenerator generator;
    ASSERT_TRUE(hooksOf(s.scene)->addFixedUpdater(&updater));
    ASSERT_TRUE(hooksOf(s.scene)->addForceGenerator(ball->getRB(), &generator));
    s.scene->update(100);
    const PhysicsProfile& p = profileOf(s.scene)->getProfile();
    EXPECT_EQ(p.steps, 6);
    EXPECT_GE(p.updaters, 6 * 0.002);
    EXPECT_GE(p.integration, 6 * 0.003);
    EXPECT_LE(phaseSum(p), p.total);
    EXPECT_GE(phaseSum(p), 0.9 * p.total); // nothing of the update is left out
    EXPECT_EQ(p.contacts, 0u);
    hooksOf(s.scene)->removeFixedUpdater(&updater);
    hooksOf(s.scene)->removeForceGenerator(ball->getRB(), &generator);
}

// An update that takes no step (two frames within one step) leaves the last profile as it was.
TEST(Profile, AnUpdateWithoutAStepKeepsTheLastProfile) {
    SceneFixture s;
    s.world->sphere(Vector(0, 10, 0), 0.5f, 1.0f);
    s.scene->update(50); // 3 steps
    ASSERT_EQ(profileOf(s.scene)->getProfile().steps, 3);
    s.scene->update(51); // none
    EXPECT_EQ(profileOf(s.scene)->getProfile().steps, 3);
}
