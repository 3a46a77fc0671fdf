// LifetimeTest.cpp - seed 000's kill()/isAlive()/resetAlive() (iLifetime.h) and the game's pointer on bodies
// and geometries (iUserPointer.h), through whole scenes: a killed body stops being simulated and leaves its
// scene when the step ends, from any callback, while pointers held elsewhere stay valid (run under ASan in
// CI); a dead body put back without resetAlive() leaves again.
#include "SceneFixture.h"
#include "iCSphere.h"
#include "iCollisionListener.h"
#include "iDebugDraw.h"
#include "iDebugDrawable.h"
#include "iFixedUpdater.h"
#include "iLifetime.h"
#include "iPhysicsSceneHooks.h"
#include "iPhysicsSceneStats.h"
#include "iUserPointer.h"

#include <gtest/gtest.h>

#include <functional>
#include <vector>

using resolution_test::kDt;
using resolution_test::kG;
using resolution_test::SceneFixture;

namespace {

// Runs fn from the fixed updater of the n-th step (1-based).
struct AtStep final : iFixedUpdater {
    int step = 0, at = 0;
    std::function<void()> fn;
    void fixedUpdate(iPhysicsScene*, float) override {
        if (++step == at) fn();
    }
};

// A ball in free fall from rest: after n whole steps of semi-implicit Euler its speed is exactly g n dt.
void expectFreeFallSpeed(const iRigidBody* b, int steps) {
    EXPECT_NEAR(b->getDynamics().velocity.y, -kG * kDt * steps, 1e-4f * steps);
}

size_t bodies(iPhysicsScene* s) { return statsOf(s)->getBodyCount(); }

} // namespace

// Killed from a fixed updater in step 10: skipped from that step on (it does not move again), out of the
// scene when the step ends, still a valid object reporting isAlive() false; its neighbour falls on untouched.
TEST(Lifetime, AKilledBodyLeavesAtTheEndOfTheStepAndStaysValid) {
    SceneFixture s;
    iRigidBody* doomed = s.world->sphere(Vector(0, 10, 0), 0.5f, 1.0f)->getRB();
    iRigidBody* other = s.world->sphere(Vector(5, 10, 0), 0.5f, 1.0f)->getRB();
    ASSERT_TRUE(lifetimeOf(doomed) && lifetimeOf(doomed)->isAlive());
    AtStep updater;
    updater.at = 10;
    Vector where;
    updater.fn = [&] {
        lifetimeOf(doomed)->kill();
        where = doomed->getDynamics().position; // the pose nine steps left it at
        EXPECT_EQ(bodies(s.scene), 2u);         // still a member until the step ends
    };
    ASSERT_TRUE(hooksOf(s.scene)->addFixedUpdater(&updater));
    s.steps(10);
    EXPECT_FALSE(lifetimeOf(doomed)->isAlive());
    EXPECT_EQ(bodies(s.scene), 1u);
    expectFreeFallSpeed(doomed, 9); // nine steps of fall, none after the kill
    s.steps(50);
    EXPECT_EQ(doomed->getDynamics().position.y, where.y);
    expectFreeFallSpeed(other, 60);
    hooksOf(s.scene)->removeFixedUpdater(&updater);
}

// Killed from HitWall (delivered after the steps): the ball that hit the ground leaves the scene at once
// (the delivery ends like a step) and hangs where it was; the listener's pointer stays good.
TEST(Lifetime, KillFromAListenerRemovesTheBodyAfterTheDelivery) {
    struct Killer final : iCollisionListener {
        iRigidBody* self = nullptr;
        int calls = 0;
        void HitWall(iRigidBody*, Vector, Vector) override {
            ++calls;
            lifetimeOf(self)->kill();
        }
    } killer;
    SceneFixture s;
    s.world->ground();
    iRigidBody* ball = s.world->sphere(Vector(0, 1, 0), 0.5f, 1.0f)->getRB();
    killer.self = ball;
    ball->attachListener(&killer);
    int frames = 0;
    while (killer.calls == 0 && frames++ < 120) s.steps(1);
    ASSERT_EQ(killer.calls, 1);
    EXPECT_EQ(bodies(s.scene), 0u);
    const Vector landed = ball->getDynamics().position;
    s.steps(30);
    EXPECT_EQ(killer.calls, 1); // out of the scene: no more contacts resolved, no more calls
    EXPECT_EQ(ball->getDynamics().position.y, landed.y);
    ball->detachListener(&killer);
}

// Between updates, kill() takes effect in the next step: the body does not move in it and is gone after it.
TEST(Lifetime, KillBetweenStepsActsInTheNextStep) {
    SceneFixture s;
    iRigidBody* ball = s.world->sphere(Vector(0, 10, 0), 0.5f, 1.0f)->getRB();
    s.steps(5);
    const float y = ball->getDynamics().position.y;
    lifetimeOf(ball)->kill();
    EXPECT_EQ(bodies(s.scene), 1u);
    s.steps(1);
    EXPECT_EQ(bodies(s.scene), 0u);
    EXPECT_EQ(ball->getDynamics().position.y, y);
    expectFreeFallSpeed(ball, 5);
}

// Seed 000: "Before a killed object is returned to a physics scene, resetAlive must be called, or it will be
// removed again". Without it the body leaves after one step and does not move; with it, it falls at g again.
TEST(Lifetime, ADeadBodyPutBackLeavesAgainUnlessReset) {
    SceneFixture s;
    iRigidBody* ball = s.world->sphere(Vector(0, 10, 0), 0.5f, 1.0f)->getRB();
    lifetimeOf(ball)->kill();
    s.steps(1);
    ASSERT_EQ(bodies(s.scene), 0u);
    ball->getDynamics().velocity = Vector();

    ASSERT_TRUE(s.scene->add(ball));
    const float y = ball->getDynamics().position.y;
    s.steps(3);
    EXPECT_EQ(bodies(s.scene), 0u);
    EXPECT_EQ(ball->getDynamics().position.y, y);

    lifetimeOf(ball)->resetAlive();
    ASSERT_TRUE(s.scene->add(ball));
    s.steps(30);
    EXPECT_EQ(bodies(s.scene), 1u);
    EXPECT_TRUE(lifetimeOf(ball)->isAlive());
    expectFreeFallSpeed(ball, 30);
}

// The seed-001 remove() does not kill: removed and added again within a step or between steps, the body
// simply goes on.
TEST(Lifetime, RemoveDoesNotKill) {
    SceneFixture s;
    iRigidBody* ball = s.world->sphere(Vector(0, 10, 0), 0.5f, 1.0f)->getRB();
    s.scene->remove(ball);
    EXPECT_TRUE(lifetimeOf(ball)->isAlive());
    ASSERT_TRUE(s.scene->add(ball));
    AtStep updater;
    updater.at = 2;
    updater.fn = [&] {
        s.scene->remove(ball);
        ASSERT_TRUE(s.scene->add(ball)); // within the step: it simply stays
    };
    ASSERT_TRUE(hooksOf(s.scene)->addFixedUpdater(&updater));
    s.steps(20);
    EXPECT_EQ(bodies(s.scene), 1u);
    expectFreeFallSpeed(ball, 20);
    hooksOf(s.scene)->removeFixedUpdater(&updater);
}

// A body killed and deleted in one callback, and one deleted and then killed: both deleted once, no use
// after free (ASan), the scene intact. Killing inside the step and putting back within it does not revive.
TEST(Lifetime, KillAndDeleteInOneStepInEitherOrder) {
    SceneFixture s;
    iRigidBody* a = CreateRigidBody(nullptr);
    iRigidBody* b = CreateRigidBody(nullptr);
    iRigidBody* c = s.world->sphere(Vector(0, 10, 0), 0.5f, 1.0f)->getRB();
    ASSERT_EQ(bodies(s.scene), 3u);
    std::vector<const iRigidBody*> deleted;
    struct Watch {
        static void note(const iRigidBody* d, void* self) {
            static_cast<std::vector<const iRigidBody*>*>(self)->push_back(d);
        }
    };
    watchRigidBodies(&Watch::note, &deleted);
    AtStep updater;
    updater.at = 1;
    updater.fn = [&] {
        lifetimeOf(a)->kill();
        a->Delete();
        b->Delete();
        lifetimeOf(b)->kill(); // being deleted: nothing more to do
        lifetimeOf(c)->kill();
        EXPECT_TRUE(s.scene->add(c)); // still a member; dead, so it leaves anyway
    };
    ASSERT_TRUE(hooksOf(s.scene)->addFixedUpdater(&updater));
    s.steps(2);
    unwatchRigidBodies(&Watch::note, &deleted);
    EXPECT_EQ(deleted, (std::vector<const iRigidBody*>{b, a}));
    EXPECT_EQ(bodies(s.scene), 0u);
    EXPECT_FALSE(lifetimeOf(c)->isAlive());
    hooksOf(s.scene)->removeFixedUpdater(&updater);
}

// The game's pointer: set on a body and on its geometry, found again from what a callback is handed (the
// other body in HitWall), never touched by the engine; a clone starts without one.
TEST(Lifetime, UserPointersLeadBackToTheGamesObjects) {
    struct Player {
        int id;
    } player{7}, wall{9};
    struct Finder final : iCollisionListener {
        std::vector<const void*> found;
        void HitWall(iRigidBody* other, Vector, Vector) override {
            found.push_back(other ? userPointerOf(other)->getUserPointer() : nullptr);
        }
    } finder;
    SceneFixture s;
    iPhysicsFrame* floor = s.world->fixedBox(Vector(0, -0.5f, 0), Vector(5, 0.5f, 5));
    iRigidBody* ball = s.world->sphere(Vector(0, 0.499f, 0), 0.5f, 1.0f)->getRB();
    userPointerOf(ball)->setUserPointer(&player);
    userPointerOf(floor->getRB())->setUserPointer(&wall);
    iCollisionGeometry* shape = CreateCSphere(nullptr, 1.0f);
    ASSERT_NE(userPointerOf(shape), nullptr);
    EXPECT_EQ(userPointerOf(shape)->getUserPointer(), nullptr);
    userPointerOf(shape)->setUserPointer(&player);
    EXPECT_EQ(static_cast<Player*>(userPointerOf(shape)->getUserPointer())->id, 7);
    shape->Delete();
    ball->attachListener(&finder);
    s.steps(3);
    ASSERT_FALSE(finder.found.empty());
    for (const void* p : finder.found) EXPECT_EQ(p, &wall);
    EXPECT_EQ(static_cast<Player*>(userPointerOf(ball)->getUserPointer())->id, 7);
    iRigidBody* copy = ball->clone();
    EXPECT_EQ(userPointerOf(copy)->getUserPointer(), nullptr);
    copy->Delete();
    ball->detachListener(&finder);
}

// Centres of mass in the order the scene draws its bodies (debugDraw walks the scene's list, in join order).
struct CentreRecorder final : iDebugDraw {
    std::vector<Vector> centres;
    void drawLine(const Vector&, const Vector&, DebugColour) override {}
    void drawText(const Vector&, const char*, DebugColour) override {}
    void drawPoint(const Vector& at, float, DebugColour) override { centres.push_back(at); }
};

// A body leaving from the middle of the scene's list clears its slot and the list closes up at its next read:
// the others keep their join order (the scene draws them in it), and a stack whose scene also held two far
// boxes, removed after ten steps, ends bit for bit where the same stack alone does.
TEST(Lifetime, BodiesLeavingTheMiddleOfTheListKeepTheOthersOrder) {
    auto stack = [](bool withFarBoxes) {
        SceneFixture s;
        s.world->ground();
        std::vector<iRigidBody*> kept, far;
        for (int i = 0; i < 6; ++i) {
            const bool isFar = i == 1 || i == 3; // joins between the stack's boxes
            if (isFar && !withFarBoxes) continue;
            const Vector at =
                isFar ? Vector(30.0f * float(i), 100.0f, 0) : Vector(0.05f * float(i), 0.5f + float(i), 0);
            (isFar ? far : kept).push_back(s.world->box(at, Vector(0.5f, 0.5f, 0.5f), 1.0f)->getRB());
        }
        s.steps(10);
        for (iRigidBody* b : far) s.scene->remove(b);
        EXPECT_EQ(bodies(s.scene), kept.size());
        CentreRecorder drawn;
        debugDrawOf(s.scene)->debugDraw(drawn, DEBUGDRAW_BodyAxes);
        EXPECT_EQ(drawn.centres.size(), kept.size());
        for (size_t i = 0; i < kept.size() && i < drawn.centres.size(); ++i)
            EXPECT_EQ(drawn.centres[i].y, kept[i]->getDynamics().position.y)
                << "body " << i << " out of order";
        s.steps(110);
        std::vector<Vector> poses;
        for (iRigidBody* b : kept) poses.push_back(b->getDynamics().position);
        for (iRigidBody* b : far) s.scene->add(b); // back, so that the World deletes them with the scene's
        EXPECT_EQ(bodies(s.scene), kept.size() + far.size());
        return poses;
    };
    const std::vector<Vector> alone = stack(false), withFar = stack(true);
    ASSERT_EQ(alone.size(), 4u);
    ASSERT_EQ(withFar.size(), 4u);
    for (size_t i = 0; i < alone.size(); ++i) {
        EXPECT_EQ(withFar[i].x, alone[i].x) << i;
        EXPECT_EQ(withFar[i].y, alone[i].y) << i;
        EXPECT_EQ(withFar[i].z, alone[i].z) << i;
    }
    EXPECT_NEAR(alone[3].y, 3.5f, 0.05f); // the stack stands
}
