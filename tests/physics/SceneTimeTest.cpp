// SceneTimeTest.cpp - the fixed-step clock: interpolated drawing one step behind, repeated and backwards
// time, a long stall, suspend/restore, settings from the context.
#include "Frame.h"
#include "PhysicsTestSupport.h"
#include "iCollisionSpace.h"
#include "iContext.h"
#include "iPhysicsSceneSettings.h"
#include "iPhysicsSceneStats.h"

#include <gtest/gtest.h>

#include <cmath>

using physics_test::ErrorRecorder;
using physics_test::SceneHolder;

namespace {
// A floating body moving at 1 m/s along x and spinning at 1 rad/s about y, drawn by `frame`.
iRigidBody* mover(iFrame* frame) {
    iRigidBody* b = CreateRigidBody(frame);
    b->getDynamics().physicsType = PHYS_Floating;
    b->getDynamics().velocity = Vector(1, 0, 0);
    b->getDynamics().angularVelocity = Vector(0, 1, 0);
    return b;
}
} // namespace

// Steps land at k/60 s; at t = 1.008 s, 60 steps are done and 0.48 of a step is left over. The frame is
// drawn one step behind: at the pose of time t - dt (position lerp, orientation slerp between the last two
// step poses), here x = 1.008 - 1/60 and a turn of the same angle about y.
TEST(SceneTime, FramesAreInterpolatedOneStepBehind) {
    SceneHolder h(60);
    iFrame* f = CreateFrame();
    iRigidBody* b = mover(f);
    h.run(1008, 16);
    EXPECT_EQ(statsOf(h.scene)->getStepCount(), 60);
    EXPECT_NEAR(b->getDynamics().position.x, 1.0f, 1e-5f);
    float drawn = 1.008f - 1.0f / 60.0f;
    EXPECT_NEAR(f->position().x, drawn, 1e-5f);
    Matrix expected = rotate(Vector(0, 1, 0), drawn);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(f->rotation()(r, c), expected(r, c), 1e-5f);
    // Between the two step poses: the previous step (59/60) and the current one (60/60).
    EXPECT_GT(f->position().x, 59.0f / 60.0f);
    EXPECT_LT(f->position().x, 1.0f);
    b->Delete();
    f->Delete();
}

// The frame's origin is the COM minus the com offset turned by the orientation.
TEST(SceneTime, FrameOriginAccountsForTheComOffset) {
    SceneHolder h(60);
    iFrame* f = CreateFrame();
    iRigidBody* b = mover(f);
    b->getDynamics().com = Vector(0.5f, 0, 0);
    h.run(1000, 10);
    Matrix w = f->world();
    Vector comDrawn = w.position() + w.direction(Vector(0.5f, 0, 0));
    // Exactly on a step (alpha = 0): drawn at the previous step, t = 59/60 s.
    EXPECT_NEAR(comDrawn.x, 59.0f / 60.0f, 1e-5f);
    EXPECT_NEAR(comDrawn.z, 0.0f, 1e-5f);
    b->Delete();
    f->Delete();
}

// now equal to the last now integrates nothing; now earlier than it integrates nothing and becomes the time
// base (documented in iPhysicsScene.h), so time then runs on from there.
TEST(SceneTime, RepeatedAndBackwardsTimeIntegrateNothing) {
    SceneHolder h(60);
    iRigidBody* b = mover(nullptr);
    h.run(500);
    EXPECT_EQ(statsOf(h.scene)->getStepCount(), 30);
    Vector at = b->getDynamics().position;
    h.scene->update(500);
    h.scene->update(400); // backwards: re-based at 400
    EXPECT_EQ(statsOf(h.scene)->getStepCount(), 30);
    EXPECT_EQ(b->getDynamics().position, at);
    h.scene->update(416); // 16 ms: under a step (16.7 ms)
    EXPECT_EQ(statsOf(h.scene)->getStepCount(), 30);
    h.scene->update(417); // 17 ms since the re-base: one step
    EXPECT_EQ(statsOf(h.scene)->getStepCount(), 31);
}

// A 10 s stall takes at most maxStepsPerUpdate steps (8) and drops the rest: the game slows down instead of
// spiralling; the next frame is an ordinary one.
TEST(SceneTime, ALongStallIsBoundedAndTheBacklogDropped) {
    SceneHolder h(60);
    iRigidBody* b = mover(nullptr);
    h.scene->update(10000);
    EXPECT_EQ(statsOf(h.scene)->getStepCount(), 8);
    EXPECT_EQ(statsOf(h.scene)->getDroppedStepCount(), 600 - 8);
    EXPECT_NEAR(b->getDynamics().position.x, 8.0f / 60.0f, 1e-6f);
    h.scene->update(10017);
    EXPECT_EQ(statsOf(h.scene)->getStepCount(), 9);
}

// suspend(), a long pause, restore(now): the pause is not simulated.
TEST(SceneTime, SuspendAndRestoreResumeWithoutAJump) {
    SceneHolder h(60);
    iRigidBody* b = mover(nullptr);
    h.run(100); // 6 steps
    h.scene->suspend();
    h.scene->update(3000); // ignored while suspended
    EXPECT_EQ(statsOf(h.scene)->getStepCount(), 6);
    h.scene->restore(5000);
    h.scene->update(5017);
    EXPECT_EQ(statsOf(h.scene)->getStepCount(), 7);
    EXPECT_NEAR(b->getDynamics().position.x, 7.0f / 60.0f, 1e-6f);
}

// The scene's knobs are set through settingsOf(scene); invalid settings are refused and leave the old value.
TEST(SceneTime, SettingsAreSetThroughTheSettingsInterfaceAndInvalidOnesAreRefused) {
    iContext* c = CreateContext();
    iPhysicsScene* s = CreatePhysicsScene(c);
    ASSERT_TRUE(settingsOf(s)->setStepRate(240));
    ASSERT_TRUE(settingsOf(s)->setMaxStepsPerUpdate(3));
    ASSERT_TRUE(settingsOf(s)->setIntegrator(INTEGRATOR_RK4));
    ASSERT_TRUE(settingsOf(s)->setGravity(Vector(0, -1.62f, 0)));
    EXPECT_EQ(settingsOf(s)->getStepRate(), 240);
    EXPECT_EQ(settingsOf(s)->getMaxStepsPerUpdate(), 3);
    EXPECT_EQ(settingsOf(s)->getIntegrator(), INTEGRATOR_RK4);
    EXPECT_EQ(settingsOf(s)->getGravity(), Vector(0, -1.62f, 0));
    {
        ErrorRecorder errors;
        EXPECT_FALSE(settingsOf(s)->setStepRate(0));
        EXPECT_FALSE(settingsOf(s)->setMaxStepsPerUpdate(0));
        EXPECT_FALSE(settingsOf(s)->setIntegrator(Integrator(42)));
        EXPECT_FALSE(settingsOf(s)->setGravity(Vector(0, NAN, 0)));
        EXPECT_EQ(errors.count(), 4u);
    }
    EXPECT_EQ(settingsOf(s)->getStepRate(), 240);
    EXPECT_EQ(settingsOf(s)->getIntegrator(), INTEGRATOR_RK4);
    EXPECT_TRUE(settingsOf(s)->setIntegrator(INTEGRATOR_Default));
    EXPECT_EQ(settingsOf(s)->getIntegrator(), INTEGRATOR_SemiImplicitEuler);
    s->Delete();
    c->Delete();
}

namespace {
// Counts populateContactList calls, as the scene's collision space.
struct CountingSpace final : iCollisionSpace {
    int calls = 0;
    float lastDelta = 0;
    std::list<iCollisionGeometry*> none;
    bool add(iCollisionGeometry*) override { return false; }
    void remove(iCollisionGeometry*) override {}
    const std::list<iCollisionGeometry*>& getAttachedGeometry() override { return none; }
    void populateContactList(float delta) override {
        ++calls;
        lastDelta = delta;
    }
    const CollisionContact* getContactList() const override { return nullptr; }
    size_t getNumContacts() const override { return 0; }
    void suspend() const override {}
    void release() const override {}
    void Delete() const override {}
};
} // namespace

// The scene's collision space is asked for contacts once a step, with the step as delta, and becomes the
// default space for new geometries.
TEST(SceneTime, TheCollisionSpaceIsCollidedOnceAStep) {
    SceneHolder h(120);
    CountingSpace space;
    h.scene->setNewGlobalCollisionSpace(&space);
    EXPECT_EQ(getDefaultCollisionSpace(), &space);
    h.run(500);
    EXPECT_EQ(space.calls, 60);
    EXPECT_FLOAT_EQ(space.lastDelta, 1.0f / 120.0f);
    h.scene->setNewGlobalCollisionSpace(nullptr);
    EXPECT_EQ(getDefaultCollisionSpace(), nullptr);
    h.run(100);
    EXPECT_EQ(space.calls, 60);
}
