// HitWallPerFrameTest.cpp - HitWall "will be called by PhysicsScene every frame that two objects are
// colliding" (the seed): once per update per touching pair, whatever the number of steps in the update
// (none, one, several), and also while the pair sleeps.
#include "SceneFixture.h"
#include "iCSphere.h"
#include "iCollisionListener.h"
#include "iPhysicsSceneStats.h"

#include <gtest/gtest.h>

using resolution_test::SceneFixture;

namespace {

struct PerUpdate final : iCollisionListener {
    int calls = 0;
    iRigidBody* lastOther = reinterpret_cast<iRigidBody*>(1);
    Vector lastNormal;
    void HitWall(iRigidBody* other, Vector normal, Vector) override {
        ++calls;
        lastOther = other;
        lastNormal = normal;
    }
};

// A ball resting on a fixed box, updated at `hz` frames per second: counts calls per update.
struct RestingBall {
    RestingBall(float frameHz, bool onPlane) : hz(frameHz) {
        if (onPlane)
            s.world->ground(); // a plane with no body: HitWall's other is nullptr
        else
            ground = s.world->fixedBox(Vector(0, -0.5f, 0), Vector(5, 0.5f, 5));
        ball = s.world->sphere(Vector(0, 0.249f, 0), 0.25f, 1.0f); // touching from the start
        ball->getRB()->attachListener(&listener);
    }
    // One frame: returns the calls it brought.
    int frame() {
        ++frames;
        listener.calls = 0;
        s.scene->update(int(std::ceil(frames * 1000.0 / hz)));
        return listener.calls;
    }
    SceneFixture s; // its first update(0) set the time base
    float hz;
    long frames = 0;
    iPhysicsFrame *ground = nullptr, *ball;
    PerUpdate listener;
};

} // namespace

// At 60 Hz (one step a frame), 144 Hz (frames without a step) and 20 Hz (three steps a frame): exactly one
// call per update while touching, before and for 1 s after the ball fell asleep; on a box and on a plane.
TEST(HitWallPerFrame, OncePerUpdateAwakeAndAsleep) {
    for (int onPlane = 0; onPlane < 2; ++onPlane)
        for (float hz : {60.0f, 144.0f, 20.0f}) {
            RestingBall r(hz, onPlane);
            int framesAsleep = 0, framesAwake = 0;
            for (int i = 0; i < int(4 * hz) && framesAsleep < int(hz); ++i) {
                int calls = r.frame();
                if (statsOf(r.s.scene)->getStepCount() == 0) continue; // nothing computed yet: nothing known
                bool asleep = r.ball->getDynamics()->sleeping;
                (asleep ? framesAsleep : framesAwake) += 1;
                ASSERT_EQ(calls, 1) << hz << " Hz, frame " << i << (asleep ? " asleep" : " awake");
            }
            EXPECT_EQ(framesAsleep, int(hz)) << hz << " Hz: the ball never slept";
            EXPECT_GT(framesAwake, 0);
            EXPECT_EQ(r.listener.lastOther, onPlane ? nullptr : r.ground->getRB());
            EXPECT_NEAR(r.listener.lastNormal.y, -1.0f,
                        1e-4f); // toward the other body: down, into the ground
        }
}

// A ball dropped from 1 m hears nothing while it falls (t = sqrt(2 h / g) = 0.45 s less its radius) and is
// heard once per frame from the frame it lands.
TEST(HitWallPerFrame, NothingBeforeTheImpactThenEveryFrame) {
    SceneFixture s;
    iPhysicsFrame* ground = s.world->fixedBox(Vector(0, -0.5f, 0), Vector(5, 0.5f, 5));
    iPhysicsFrame* ball = s.world->sphere(Vector(0, 1.25f, 0), 0.25f, 1.0f);
    ball->getDynamics()->restitution = ground->getDynamics()->restitution = 0.0f; // lands, stays
    PerUpdate l;
    ball->getRB()->attachListener(&l);
    const float fall = std::sqrt(2.0f * 1.0f / resolution_test::kG);
    int firstFrame = -1;
    for (int f = 1; f <= 120; ++f) {
        l.calls = 0;
        s.scene->update(int(std::ceil(f * 1000.0 / 60.0)));
        if (firstFrame < 0 && l.calls > 0) firstFrame = f;
        if (firstFrame > 0) {
            EXPECT_EQ(l.calls, 1) << "frame " << f;
        }
    }
    ASSERT_GT(firstFrame, 0);
    EXPECT_NEAR(firstFrame / 60.0f, fall, 2.5f / 60.0f);
}

// A listener that deletes the body it hears about, during the once-a-frame delivery: the body goes at the
// end of the delivery, the scene goes on, and nobody hears of it again.
TEST(HitWallPerFrame, DeletingFromTheDeliveryIsSafe) {
    SceneFixture s;
    s.world->ground();
    iPhysicsFrame* a = s.world->sphere(Vector(0, 0.25f, 0), 0.25f, 1.0f);
    iPhysicsFrame* b = s.world->sphere(Vector(0.45f, 0.25f, 0), 0.25f, 1.0f);
    struct Deleter final : iCollisionListener {
        iRigidBody* victim = nullptr;
        int calls = 0;
        void HitWall(iRigidBody* other, Vector, Vector) override {
            ++calls;
            if (other && other == victim) {
                victim->Delete(); // a simulated body (not a PhysicsFrame's)
                victim = nullptr;
            }
        }
    } deleter;
    iRigidBody* loose = CreateRigidBody(nullptr);
    loose->getDynamics().position = Vector(-0.45f, 0.25f, 0);
    iCollisionGeometry* g = CreateCSphere(loose, 0.25f);
    deleter.victim = loose;
    a->getRB()->attachListener(&deleter);
    s.steps(5);
    EXPECT_EQ(deleter.victim, nullptr);    // it heard of the loose ball and deleted it
    EXPECT_EQ(g->getRigidBody(), nullptr); // the geometry was unbound from the dead body
    const size_t bodies = statsOf(s.scene)->getBodyCount();
    s.steps(30);
    EXPECT_EQ(statsOf(s.scene)->getBodyCount(), bodies);
    EXPECT_TRUE(b->getDynamics()->position.isFinite());
    g->Delete();
}
