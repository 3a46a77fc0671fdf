// DeletionOrderTest.cpp - "release in any order": deletions the game makes in an order the engine did not
// expect, from inside callbacks or not, are handled or refused with error(), never a use-after-free. Each
// test reproduces a use-after-free (or a re-entrant update) found in af411e1: under ASan it failed before
// the fix (SceneLifetime.cpp, PhysicsFrame.cpp) and passes after it.
#include "Frame.h"
#include "PhysicsTestSupport.h"
#include "iFixedUpdater.h"
#include "iForceGenerator.h"
#include "iPhysicsFrame.h"
#include "iPhysicsSceneHooks.h"
#include "iPhysicsSceneStats.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <vector>

using physics_test::DestroyLog;
using physics_test::ErrorRecorder;
using physics_test::SceneHolder;

namespace {

// Runs a function once, from the first call of whichever callback it is registered as.
struct Once final : iFixedUpdater, iForceGenerator {
    std::function<void(iPhysicsScene*)> fn;
    int calls = 0;
    void fixedUpdate(iPhysicsScene* s, float) override { run(s); }
    void addForces(const iRigidBody*, const RigidBodyState&, Vector&, Vector&) override { run(nullptr); }
    void run(iPhysicsScene* s) {
        if (calls++ == 0) fn(s);
    }
};

} // namespace

// PhysicsScene.cpp:391 (af411e1): a root's force generator deleted an attached child that is in another
// scene; the child was freed at once (its scene was not busy) and the step then wrote its dynamics.
TEST(DeletionOrder, ForceGeneratorDeletesAnAttachedChildOfAnotherScene) {
    DestroyLog log;
    iPhysicsScene* other = CreatePhysicsScene(nullptr);
    iRigidBody* child = CreateRigidBody(nullptr); // in `other`
    SceneHolder h(60);
    iRigidBody* root = CreateRigidBody(nullptr);
    root->getDynamics().mass = 2.0f;
    child->getDynamics().position = Vector(1, 0, 0);
    child->getDynamics().attachTo(&root->getDynamics());
    ASSERT_FLOAT_EQ(root->getDynamics().getCompositeMass(), 3.0f);
    Once gen;
    gen.fn = [&](iPhysicsScene*) {
        child->Delete();
        EXPECT_FALSE(log.has(child)); // deferred: the step is still integrating the composite
    };
    ASSERT_TRUE(hooksOf(h.scene)->addForceGenerator(root, &gen));
    h.run(100); // six steps at 60 Hz
    EXPECT_TRUE(log.has(child));
    EXPECT_FLOAT_EQ(root->getDynamics().getCompositeMass(), 2.0f); // the child left the chain when deleted
    EXPECT_EQ(statsOf(other)->getBodyCount(), 0u);
    EXPECT_EQ(statsOf(h.scene)->getStepCount(), 6);
    other->Delete();
}

// RigidBody.cpp:115 (af411e1): a fixed updater deleted the scene, then the frame bound to one of its bodies
// (the scene deletes the body, so the frame is the game's to delete); the rest of the step read the frame.
TEST(DeletionOrder, FixedUpdaterDeletesTheSceneThenABoundFrame) {
    DestroyLog log;
    iPhysicsScene* scene = CreatePhysicsScene(nullptr);
    scene->update(0);
    iFrame* frame = CreateFrame();
    iRigidBody* body = CreateRigidBody(frame);
    Once updater;
    updater.fn = [&](iPhysicsScene* s) {
        s->Delete();
        frame->Delete();
        EXPECT_EQ(body->getFrame(), nullptr); // let go at once: the scene will delete it
    };
    ASSERT_TRUE(hooksOf(scene)->addFixedUpdater(&updater));
    ErrorRecorder errors;
    scene->update(100); // the scene and its body are gone when update returns
    EXPECT_EQ(updater.calls, 1);
    EXPECT_TRUE(log.has(body));
    EXPECT_EQ(errors.count(), 0u);
}

// An update() from inside a callback (of this scene or of another) is refused with error(); the outer update
// takes exactly its own steps.
TEST(DeletionOrder, UpdateFromACallbackIsRefused) {
    iPhysicsScene* other = CreatePhysicsScene(nullptr);
    other->update(0);
    SceneHolder h(60);
    iRigidBody* body = CreateRigidBody(nullptr);
    Once updater;
    ErrorRecorder errors;
    updater.fn = [&](iPhysicsScene* s) {
        s->update(10000);
        other->update(10000);
    };
    ASSERT_TRUE(hooksOf(h.scene)->addFixedUpdater(&updater));
    h.run(100, 100); // one update of 100 ms: six steps at 60 Hz
    EXPECT_EQ(errors.count(), 2u);
    EXPECT_NE(errors.last().find(L"inside a scene update"), std::wstring::npos);
    EXPECT_EQ(statsOf(h.scene)->getStepCount(), 6);
    EXPECT_EQ(statsOf(other)->getStepCount(), 0);
    // Six semi-implicit Euler steps of free fall: y = -g dt^2 (1 + ... + 6) = -21 g / 3600.
    EXPECT_NEAR(body->getDynamics().position.y, -21.0f * 9.81f / 3600.0f, 1e-5f);
    other->Delete();
}

// A scene deleted from a callback of another scene's update is deleted when that update ends: its body,
// attached to the updating scene's chain, is integrated until then and never freed mid-step.
TEST(DeletionOrder, SceneDeletedFromAnotherScenesCallbackWaitsForTheUpdate) {
    DestroyLog log;
    iPhysicsScene* other = CreatePhysicsScene(nullptr);
    iRigidBody* child = CreateRigidBody(nullptr);
    SceneHolder h(60);
    iRigidBody* root = CreateRigidBody(nullptr);
    child->getDynamics().attachTo(&root->getDynamics());
    Once gen;
    gen.fn = [&](iPhysicsScene*) {
        other->Delete();
        EXPECT_FALSE(log.has(child));
        iRigidBody* late = CreateRigidBody(nullptr); // joins the active scene: no longer `other`
        EXPECT_EQ(statsOf(h.scene)->getBodyCount(), 2u);
        late->Delete();
    };
    ASSERT_TRUE(hooksOf(h.scene)->addForceGenerator(root, &gen));
    h.run(100, 100);
    EXPECT_TRUE(log.has(child));
    EXPECT_EQ(root->getDynamics().firstAttached(), nullptr);
    EXPECT_EQ(statsOf(h.scene)->getBodyCount(), 1u);
}

// A PhysicsFrame deleted before the PhysicsFrames attached to it: they become root frames at their world
// pose instead of keeping a dangling parent; a body bound to it with attach() lets go of it.
TEST(DeletionOrder, PhysicsFrameDeletedBeforeItsChildrenAndBoundBodies) {
    SceneHolder h(60);
    iPhysicsFrame* parent = CreatePhysicsFrame();
    iPhysicsFrame* child = CreatePhysicsFrame();
    parent->translate(0, 5, 0);
    child->translate(1, 5, 0);
    child->attachTo(parent);
    iRigidBody* watcher = CreateRigidBody(nullptr);
    watcher->attach(parent); // two bodies drive one frame: allowed, and must not outlive it
    h.run(20);
    const Vector before = child->position();
    parent->Delete();
    EXPECT_EQ(child->parent(), nullptr);
    EXPECT_EQ(watcher->getFrame(), nullptr);
    EXPECT_NEAR((child->position() - before).length(), 0.0f, 1e-5f); // the same world pose
    h.run(100);                                                      // writes the child's frame
    EXPECT_LT(child->position().y, before.y);                        // and it keeps falling
    child->Delete();
    watcher->Delete();
}

// Deleting a PhysicsFrame (and a plain body) twice from callbacks, and a scene twice, is harmless.
TEST(DeletionOrder, RepeatedDeletesInsideAStepAreIgnored) {
    DestroyLog log;
    iPhysicsScene* scene = CreatePhysicsScene(nullptr);
    scene->update(0);
    iRigidBody* body = CreateRigidBody(nullptr);
    Once updater;
    updater.fn = [&](iPhysicsScene* s) {
        body->Delete();
        body->Delete();
        s->Delete();
        s->Delete();
    };
    ASSERT_TRUE(hooksOf(scene)->addFixedUpdater(&updater));
    scene->update(1000);
    EXPECT_EQ(std::count(log.dead.begin(), log.dead.end(), body), 1);
}
