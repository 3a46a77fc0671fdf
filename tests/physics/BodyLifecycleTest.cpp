// BodyLifecycleTest.cpp - who owns what: the active scene, deferred removal and deletion from callbacks,
// scene deletion, PhysicsFrame ownership, clone, and refused add/remove calls.
#include "Frame.h"
#include "PhysicsTestSupport.h"
#include "iCollisionListener.h"
#include "iFixedUpdater.h"
#include "iPhysicsFrame.h"
#include "iPhysicsSceneHooks.h"
#include "iPhysicsSceneStats.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

using physics_test::DestroyLog;
using physics_test::ErrorRecorder;
using physics_test::SceneHolder;

namespace {

struct NullListener final : iCollisionListener {
    void HitWall(iRigidBody*, Vector, Vector) override {}
};

} // namespace

TEST(BodyLifecycle, BodiesJoinTheLastCreatedSceneOrNone) {
    iRigidBody* loose = CreateRigidBody(nullptr); // no scene yet: standalone
    iPhysicsScene* first = CreatePhysicsScene(nullptr);
    iPhysicsScene* second = CreatePhysicsScene(nullptr);
    iRigidBody* inSecond = CreateRigidBody(nullptr);
    EXPECT_EQ(statsOf(first)->getBodyCount(), 0u);
    EXPECT_EQ(statsOf(second)->getBodyCount(), 1u);
    second->Delete(); // deletes inSecond; the first scene is active again
    iRigidBody* inFirst = CreateRigidBody(nullptr);
    EXPECT_EQ(statsOf(first)->getBodyCount(), 1u);
    EXPECT_TRUE(first->add(loose));
    EXPECT_EQ(statsOf(first)->getBodyCount(), 2u);
    first->Delete();
    (void)inSecond;
    (void)inFirst;
}

namespace {
// Deletes a body, its frame and a PhysicsFrame, removes another body and itself, from inside a step.
struct Killer final : iFixedUpdater {
    iRigidBody* victim;
    iFrame* victimFrame;
    iPhysicsFrame* victimPF;
    iRigidBody* removed;
    DestroyLog* log;
    size_t deadDuringCall = 99;
    void fixedUpdate(iPhysicsScene* scene, float) override {
        victim->Delete();
        victimFrame->Delete(); // right after: the body must no longer touch it
        victimPF->Delete();
        scene->remove(removed);
        hooksOf(scene)->removeFixedUpdater(this);
        victim->Delete(); // a second Delete of a queued body is ignored
        deadDuringCall = log->dead.size();
    }
};
} // namespace

TEST(BodyLifecycle, DeletingAndRemovingInsideAFixedUpdaterIsDeferredAndSafe) {
    DestroyLog log;
    SceneHolder h(60);
    iFrame* frame = CreateFrame();
    iRigidBody* victim = CreateRigidBody(frame);
    iPhysicsFrame* pf = CreatePhysicsFrame();
    iRigidBody* pfBody = pf->getRB();
    iRigidBody* removed = CreateRigidBody(nullptr);
    iRigidBody* survivor = CreateRigidBody(nullptr);
    EXPECT_EQ(statsOf(h.scene)->getBodyCount(), 4u);
    Killer k;
    k.victim = victim;
    k.victimFrame = frame;
    k.victimPF = pf;
    k.removed = removed;
    k.log = &log;
    ASSERT_TRUE(hooksOf(h.scene)->addFixedUpdater(&k));
    h.run(100);                      // six steps; the updater runs once and removes itself
    EXPECT_EQ(k.deadDuringCall, 0u); // nothing was destroyed while the step was running
    EXPECT_TRUE(log.has(victim));
    EXPECT_TRUE(log.has(pfBody));
    EXPECT_FALSE(log.has(removed));
    EXPECT_EQ(log.dead.size(), 2u);
    EXPECT_EQ(statsOf(h.scene)->getBodyCount(), 1u);
    EXPECT_LT(survivor->getDynamics().position.y, 0.0f); // the step went on for the others
    Vector still = removed->getDynamics().position;
    h.run(100);
    EXPECT_EQ(removed->getDynamics().position, still); // removed: no longer simulated
    removed->Delete();
    EXPECT_TRUE(log.has(removed));
}

TEST(BodyLifecycle, SceneDeleteDeletesItsBodiesButNotPhysicsFrameBodies) {
    DestroyLog log;
    iPhysicsScene* scene = CreatePhysicsScene(nullptr);
    iFrame* frame = CreateFrame();
    iRigidBody* body = CreateRigidBody(frame);
    iPhysicsFrame* pf = CreatePhysicsFrame();
    scene->Delete();
    EXPECT_TRUE(log.has(body));
    EXPECT_FALSE(log.has(pf->getRB()));
    frame->Delete(); // the scene never deletes frames
    // The PhysicsFrame still works, unsimulated, and deleting it deletes its body exactly once.
    pf->getDynamics()->velocity = Vector(1, 0, 0);
    pf->translate(1, 2, 3);
    iRigidBody* pfBody = pf->getRB();
    pf->Delete();
    EXPECT_TRUE(log.has(pfBody));
    EXPECT_EQ(log.dead.size(), 2u);
}

TEST(BodyLifecycle, PhysicsFrameSimulatesAndClones) {
    SceneHolder h(60);
    iPhysicsFrame* pf = CreatePhysicsFrame();
    EXPECT_EQ(pf->getDynamics(), &pf->getRB()->getDynamics());
    EXPECT_EQ(pf->getRB()->getFrame(), pf);
    pf->translate(0, 10, 0); // moving the frame moves the body (a teleport)
    h.run(1000);
    // Free fall from y = 10 for 1 s (semi-implicit Euler: + g t dt / 2).
    EXPECT_NEAR(pf->getDynamics()->position.y, 10.0f - 9.81f / 2 - 9.81f / 120, 1e-4f);
    // Drawn one step behind.
    EXPECT_NEAR(pf->position().y, 10.0f - 9.81f * (59.0f * 60.0f / 2.0f) / 3600.0f, 1e-4f);
    {
        ErrorRecorder errors;
        pf->getRB()->Delete(); // the frame owns it: refused
        EXPECT_EQ(errors.count(), 1u);
    }
    iPhysicsFrame* copy = pf->clone();
    EXPECT_NE(copy->getRB(), pf->getRB());
    EXPECT_EQ(copy->getDynamics()->position, pf->getDynamics()->position);
    EXPECT_EQ(copy->getDynamics()->velocity, pf->getDynamics()->velocity);
    EXPECT_EQ(statsOf(h.scene)->getBodyCount(), 2u);
    h.run(100);
    EXPECT_EQ(copy->getDynamics()->position, pf->getDynamics()->position); // same motion from the same state
    copy->Delete();
    pf->Delete();
    EXPECT_EQ(statsOf(h.scene)->getBodyCount(), 0u);
}

TEST(BodyLifecycle, RigidBodyCloneCopiesDynamicsAndListenersButNotTheFrame) {
    SceneHolder h(60);
    iFrame* f = CreateFrame();
    iRigidBody* b = CreateRigidBody(f);
    NullListener l;
    b->attachListener(&l);
    b->attachListener(&l); // once only
    b->getDynamics().velocity = Vector(1, 2, 3);
    b->getDynamics().mass = 5.0f;
    iRigidBody* c = b->clone();
    EXPECT_EQ(c->getFrame(), nullptr);
    EXPECT_EQ(c->getListeners().size(), 1u);
    EXPECT_EQ(c->getDynamics().velocity, Vector(1, 2, 3));
    EXPECT_EQ(c->getDynamics().mass, 5.0f);
    EXPECT_EQ(statsOf(h.scene)->getBodyCount(), 2u);
    c->detachListener(&l);
    EXPECT_TRUE(c->getListeners().empty());
    c->attach(f); // binds and moves the frame to the body at once
    b->attach(nullptr);
    EXPECT_EQ(b->getFrame(), nullptr);
    c->Delete();
    b->Delete();
    f->Delete();
}

TEST(BodyLifecycle, InvalidAddAndRemoveAreRefused) {
    SceneHolder h(60);
    ErrorRecorder errors;
    iRigidBody* b = CreateRigidBody(nullptr);
    EXPECT_FALSE(h.scene->add(nullptr));
    EXPECT_FALSE(h.scene->add(b)); // already in
    h.scene->remove(nullptr);
    iRigidBody* loose = CreateRigidBody(nullptr);
    h.scene->remove(loose);
    h.scene->remove(loose); // not in the scene any more
    EXPECT_EQ(errors.count(), 4u);
    EXPECT_EQ(statsOf(h.scene)->getBodyCount(), 1u);
    loose->Delete();
}
