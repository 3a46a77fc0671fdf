// SetupTrapsTest.cpp - setup mistakes the simulator reports instead of letting them pass silently: a body
// made before any scene exists (never simulated unless added), and a stall whose dropped backlog adds up to a
// second of simulated time (reported once).
#include "PhysicsTestSupport.h"
#include "iPhysicsFrame.h"
#include "iPhysicsSceneSettings.h"
#include "iPhysicsSceneStats.h"

#include <gtest/gtest.h>

using physics_test::ErrorRecorder;
using physics_test::kG;
using physics_test::SceneHolder;

// The seed's order is scene first. A body made before it joins no scene: each factory says so at once, and
// the body still works once add()ed. Then it falls as semi-implicit Euler predicts: after n steps of dt the
// drop is g dt^2 n (n + 1) / 2 = g t^2 / 2 + g t dt / 2 (60 steps: 4.905 + 0.082 = 4.987 m).
TEST(SetupTraps, BodiesMadeBeforeAnySceneAreReportedAndCanBeAddedLater) {
    ErrorRecorder errors;
    iRigidBody* body = CreateRigidBody(nullptr);
    EXPECT_EQ(errors.count(), 1u);
    iPhysicsFrame* frame = CreatePhysicsFrame();
    EXPECT_EQ(errors.count(), 2u);
    body->getDynamics().position = Vector(0, 10, 0);
    frame->getDynamics()->position = Vector(5, 10, 0);
    {
        SceneHolder h(60);
        EXPECT_EQ(statsOf(h.scene)->getBodyCount(), 0u); // neither joined the scene made after them
        EXPECT_TRUE(h.scene->add(body));
        EXPECT_TRUE(h.scene->add(frame->getRB()));
        iRigidBody* later = CreateRigidBody(nullptr); // with a scene: joins it, nothing to report
        EXPECT_EQ(statsOf(h.scene)->getBodyCount(), 3u);
        EXPECT_EQ(errors.count(), 2u);
        h.run(1000);
        const float t = 1.0f, dt = 1.0f / 60.0f;
        const float euler = 0.5f * kG * t * t + 0.5f * kG * t * dt;
        EXPECT_NEAR(10.0f - body->getDynamics().position.y, euler, 1e-3f);
        EXPECT_NEAR(10.0f - frame->getDynamics()->position.y, euler, 1e-3f);
        EXPECT_NEAR(10.0f - frame->getDynamics()->position.y, 0.5f * kG * t * t, 0.5f * kG * t * dt + 1e-3f);
        EXPECT_NEAR(frame->position().y, frame->getDynamics()->position.y, 0.2f); // drawn one step behind
        (void)later; // the scene deletes it, and body, with itself
        h.scene->remove(frame->getRB());
    }
    frame->Delete();
    EXPECT_EQ(errors.count(), 2u);
}

// 60 Hz, at most 8 steps an update. Each update drops the backlog beyond 8 steps; the drops add up, and the
// first time they reach one second of simulated time (60 steps) the scene reports it, once.
TEST(SetupTraps, DroppedBacklogIsReportedOnceWhenItReachesOneSecond) {
    SceneHolder h(60);
    ASSERT_EQ(settingsOf(h.scene)->getMaxStepsPerUpdate(), 8);
    ErrorRecorder errors;
    h.scene->update(100); // 6 steps, nothing dropped
    EXPECT_EQ(statsOf(h.scene)->getStepCount(), 6);
    EXPECT_EQ(statsOf(h.scene)->getDroppedStepCount(), 0);
    h.scene->update(1100); // 60 steps due: 8 taken, 52 dropped
    EXPECT_EQ(statsOf(h.scene)->getDroppedStepCount(), 52);
    EXPECT_EQ(errors.count(), 0u);
    h.scene->update(1300); // 12 due: 8 taken, 4 dropped (56 in all, under a second)
    EXPECT_EQ(statsOf(h.scene)->getDroppedStepCount(), 56);
    EXPECT_EQ(errors.count(), 0u);
    h.scene->update(1500); // 4 more: 60 dropped, a second lost
    EXPECT_EQ(statsOf(h.scene)->getDroppedStepCount(), 60);
    EXPECT_EQ(errors.count(), 1u);
    h.scene->update(3500); // 120 due: 112 dropped, not reported again
    h.scene->update(3600);
    EXPECT_EQ(statsOf(h.scene)->getDroppedStepCount(), 172);
    EXPECT_EQ(statsOf(h.scene)->getStepCount(), 6 + 4 * 8 + 6);
    EXPECT_EQ(errors.count(), 1u);
}
