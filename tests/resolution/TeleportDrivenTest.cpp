// TeleportDrivenTest.cpp - teleports and driven motion through whole scenes (issue 11, item 1 and 3): a
// teleport arrives exactly and moves nothing on its path; a driven or game-moved body pushes, carries and
// wakes what it touches.
#include "../collision/UserBody.h"
#include "SceneFixture.h"
#include "iCOBB.h"
#include "iCollisionListener.h"
#include "iRigidBodyMotion.h"

#include <gtest/gtest.h>

using resolution_test::SceneFixture;

namespace {

struct HitCount final : iCollisionListener {
    int hits = 0;
    void HitWall(iRigidBody*, Vector, Vector) override { ++hits; }
};

iRigidBodyMotion* motion(iPhysicsFrame* f) { return motionOf(f->getRB()); }

// Runs until the body sleeps (at most `limit` seconds); true if it did.
bool sleepsWithin(SceneFixture& s, iPhysicsFrame* f, float limit) {
    for (int i = 0; i < int(limit * 60) && !f->getDynamics()->sleeping; ++i) s.steps(1);
    return f->getDynamics()->sleeping;
}

} // namespace

// The respawn: a ball at x = 10 put at x = -10, a 1 m box between. Today the ball stopped at -4.5
// and shoved the box 5.5 m.
TEST(Teleport, RespawnAcrossABoxArrivesExactlyAndMovesNothing) {
    for (int how = 0; how < 3; ++how) { // write RBDynamics, move the frame, call teleport()
        SceneFixture s;
        settingsOf(s.scene)->setGravity(Vector());
        iPhysicsFrame* ball = s.world->sphere(Vector(10, 0, 0), 0.25f, 1.0f);
        iPhysicsFrame* box = s.world->box(Vector(), Vector(0.5f, 0.5f, 0.5f), 1.0f);
        HitCount ballHits, boxHits;
        ball->getRB()->attachListener(&ballHits);
        box->getRB()->attachListener(&boxHits);
        s.steps(5);
        const Vector target(-10, 0, 0);
        if (how == 0) ball->getDynamics()->position = target;
        if (how == 1) ball->translate(-20, 0, 0);
        if (how == 2) {
            EXPECT_TRUE(motion(ball)->teleport(target, Matrix(1)));
        }
        s.steps(60);
        const Vector p = ball->getDynamics()->position;
        EXPECT_FLOAT_EQ(p.x, target.x) << how;
        EXPECT_EQ(p.y, 0.0f) << how;
        EXPECT_EQ(box->getDynamics()->position.x, 0.0f) << how; // nothing on the path was pushed
        EXPECT_EQ(box->getDynamics()->velocity.length(), 0.0f) << how;
        EXPECT_EQ(ballHits.hits + boxHits.hits, 0) << how; // nor heard of a hit
        EXPECT_GT(ball->getDynamics()->teleports, 0u) << how;
    }
}

// A teleport keeps the velocities: a ball moving at 2 m/s keeps moving at 2 m/s from where it was put.
TEST(Teleport, KeepsVelocity) {
    SceneFixture s;
    settingsOf(s.scene)->setGravity(Vector());
    iPhysicsFrame* ball = s.world->sphere(Vector(0, 0, 0), 0.25f, 1.0f);
    ball->getDynamics()->velocity = Vector(2, 0, 0);
    s.steps(3);
    EXPECT_TRUE(motion(ball)->teleport(Vector(0, 5, 0), Matrix(1)));
    s.steps(30); // half a second
    EXPECT_NEAR(ball->getDynamics()->position.x, 1.0f, 1e-4f);
    EXPECT_EQ(ball->getDynamics()->position.y, 5.0f);
}

// Landing inside something: the ordinary resolution separates them, no faster than the solver's push-out
// speed cap (SolverSettings::maxPushSpeed, 3 m/s).
TEST(Teleport, LandingInsideSeparatesWithinThePushCap) {
    SceneFixture s;
    settingsOf(s.scene)->setGravity(Vector());
    s.world->fixedBox(Vector(), Vector(0.5f, 0.5f, 0.5f));
    iPhysicsFrame* ball = s.world->sphere(Vector(5, 0, 0), 0.25f, 1.0f);
    s.steps(2);
    EXPECT_TRUE(motion(ball)->teleport(Vector(0.65f, 0, 0), Matrix(1))); // 0.1 m inside the box's face
    // The push moves the ball's position (its velocity is relaxed back to zero): measure the motion.
    float fastest = 0;
    Vector last = ball->getDynamics()->position;
    s.seconds(1.0f, [&] {
        Vector now = ball->getDynamics()->position;
        fastest = std::fmax(fastest, (now - last).length() * 60.0f);
        fastest = std::fmax(fastest, ball->getDynamics()->velocity.length());
        last = now;
    });
    EXPECT_GE(ball->getDynamics()->position.x, 0.75f - 1e-3f); // separated: centre a radius off the face
    EXPECT_LE(fastest, 3.0f + 1e-3f);
    EXPECT_GT(fastest, 0.0f);
}

// Refusals: a teleport to NaN or with a scaled matrix, moveTo on a body with mass.
TEST(Teleport, BadInputIsRefused) {
    SceneFixture s;
    iPhysicsFrame* ball = s.world->sphere(Vector(0, 3, 0), 0.25f, 1.0f);
    const float nan = std::nanf("");
    EXPECT_FALSE(motion(ball)->teleport(Vector(nan, 0, 0), Matrix(1)));
    Matrix scaled(1);
    scaled.scale(2, 2, 2);
    EXPECT_FALSE(motion(ball)->teleport(Vector(), scaled));
    EXPECT_FALSE(motion(ball)->moveTo(Vector(), Matrix(1), 1.0f)); // finite mass: not kinematic
    ball->getDynamics()->mass = INFINITE_MASS;
    EXPECT_FALSE(motion(ball)->moveTo(Vector(), Matrix(1), 0.0f));
    EXPECT_FALSE(motion(ball)->moveTo(Vector(), Matrix(1), -1.0f));
    EXPECT_EQ(ball->getDynamics()->position.y, 3.0f);
    UserBody own;
    EXPECT_EQ(motionOf(&own), nullptr); // a game's own body class does not provide it
}

// moveTo: a kinematic body reaches the target pose (here 1 m up and a quarter turn about y) in the given
// time, exactly as a constant velocity would take it there.
TEST(Driven, MoveToArrivesAtTheTargetPose) {
    SceneFixture s;
    iPhysicsFrame* k = s.world->box(Vector(), Vector(1, 0.1f, 1), 1.0f);
    k->getDynamics()->mass = INFINITE_MASS;
    Matrix turn(1);
    turn.rotatey(float(M_PI / 2));
    ASSERT_TRUE(motion(k)->moveTo(Vector(0, 1, 0), turn, 0.5f));
    s.steps(30); // 0.5 s
    EXPECT_NEAR(k->getDynamics()->position.y, 1.0f, 1e-4f);
    const float* got = k->getDynamics()->orientation.data();
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(got[i], turn.data()[i], 1e-4f) << i;
}

// A kinematic paddle driven through a floating ball pushes it ahead, never through it: the ball leaves at
// (1 + e) v, the rebound off an infinitely heavy wall moving at v (e = 0.5 for both). At 5 m/s the ball's
// surface never falls behind the paddle's face by more than 2 cm; faster, the hit is found a step late and
// the ball overlaps the paddle for that step (a measured limit in README), but it still goes ahead.
TEST(Driven, KinematicPaddlePushesWhatIsInItsWay) {
    for (float v : {5.0f, 30.0f, 300.0f, 1000.0f}) {
        SceneFixture s;
        settingsOf(s.scene)->setGravity(Vector());
        iPhysicsFrame* paddle = s.world->box(Vector(-2, 0, 0), Vector(0.1f, 1, 1), 1.0f);
        paddle->getDynamics()->mass = INFINITE_MASS;
        paddle->getDynamics()->velocity = Vector(v, 0, 0);
        iPhysicsFrame* ball = s.world->sphere(Vector(0, 0, 0), 0.25f, 1.0f);
        float worstLag = 0; // how far the ball's surface got behind the paddle's front face
        s.steps(int(60 * 4.0f / v) + 30, [&] {
            float front = paddle->getDynamics()->position.x + 0.1f;
            worstLag = std::fmax(worstLag, front - (ball->getDynamics()->position.x - 0.25f));
        });
        EXPECT_GT(ball->getDynamics()->position.x - 0.25f, paddle->getDynamics()->position.x + 0.1f) << v;
        EXPECT_NEAR(ball->getDynamics()->velocity.x, 1.5f * v, 0.01f * v) << v;
        if (v <= 5.0f) {
            EXPECT_LT(worstLag, 0.02f);
        }
    }
}

// A platform driven up 0.8 m with moveTo, every frame, under a ball that has gone to sleep on it: the ball
// wakes and rides up, ending within 5 cm of 0.8 m higher.
TEST(Driven, MoveToPlatformCarriesASleepingBall) {
    SceneFixture s;
    iPhysicsFrame* platform = s.world->box(Vector(), Vector(2, 0.1f, 2), 1.0f);
    platform->getDynamics()->mass = INFINITE_MASS;
    platform->getDynamics()->physicsType = PHYS_Floating;
    iPhysicsFrame* ball = s.world->sphere(Vector(0, 0.35f, 0), 0.25f, 1.0f);
    ASSERT_TRUE(sleepsWithin(s, ball, 3.0f));
    const float restY = ball->getDynamics()->position.y;
    for (int i = 1; i <= 120; ++i) { // 0.8 m in 2 s
        motion(platform)->moveTo(Vector(0, 0.8f * float(i) / 120.0f, 0), Matrix(1), 1.0f / 60.0f);
        s.steps(1);
    }
    platform->getDynamics()->velocity = Vector();
    s.seconds(0.5f);
    EXPECT_NEAR(platform->getDynamics()->position.y, 0.8f, 1e-3f);
    EXPECT_NEAR(ball->getDynamics()->position.y - restY, 0.8f, 0.05f);
}

// A fixed platform the game raises by small position edits every frame (each one a teleport) still lifts
// what rests on it, even once it slept.
TEST(Driven, PlatformRaisedByPositionEditsLiftsASleepingBall) {
    SceneFixture s;
    iPhysicsFrame* platform = s.world->fixedBox(Vector(), Vector(2, 0.1f, 2));
    iPhysicsFrame* ball = s.world->sphere(Vector(0, 0.35f, 0), 0.25f, 1.0f);
    ASSERT_TRUE(sleepsWithin(s, ball, 3.0f));
    const float restY = ball->getDynamics()->position.y;
    for (int i = 1; i <= 120; ++i) {
        platform->getDynamics()->position = Vector(0, 0.8f * float(i) / 120.0f, 0);
        s.steps(1);
    }
    s.seconds(0.5f);
    EXPECT_NEAR(ball->getDynamics()->position.y - restY, 0.8f, 0.05f);
}

// A game's own body (its own iRigidBody class, not simulated) used as a lift under a sleeping ball: today
// it rose 0.8 m straight through the ball. The ball wakes and rides up.
TEST(Driven, GamesOwnLiftWakesAndCarriesASleepingBall) {
    SceneFixture s;
    UserBody lift(Vector(), PHYS_FixedInSpace);
    iCollisionGeometry* deck = CreateCOBB(&lift, Vector(2, 0.1f, 2));
    iPhysicsFrame* ball = s.world->sphere(Vector(0, 0.35f, 0), 0.25f, 1.0f);
    ASSERT_TRUE(sleepsWithin(s, ball, 3.0f));
    const float restY = ball->getDynamics()->position.y;
    for (int i = 1; i <= 120; ++i) {
        lift.place(Vector(0, 0.8f * float(i) / 120.0f, 0));
        s.steps(1);
    }
    s.seconds(0.5f);
    EXPECT_NEAR(ball->getDynamics()->position.y - restY, 0.8f, 0.05f);
    deck->Delete();
}

// wake() wakes a sleeping body at once.
TEST(Driven, WakeWakesASleepingBody) {
    SceneFixture s;
    s.world->ground();
    iPhysicsFrame* ball = s.world->sphere(Vector(0, 0.25f, 0), 0.25f, 1.0f);
    ASSERT_TRUE(sleepsWithin(s, ball, 3.0f));
    motion(ball)->wake();
    EXPECT_FALSE(ball->getDynamics()->sleeping);
    s.steps(1);
    EXPECT_FALSE(ball->getDynamics()->sleeping);
}
