// SwitchesTest.cpp - what a scene or a body may leave out (iSceneSwitches, iRigidBodySwitches), each against
// the physics of the simpler model it leaves: a locked body only translates, a frictionless box keeps its
// speed, an inelastic ball stays down, a drag-free body falls as a projectile; and each switch refused or
// accepted as documented. Every case runs through scene->update(now).
#include "SceneFixture.h"

#include "ErrorRecorder.h"
#include "iCollisionListener.h"
#include "iRigidBodySwitches.h"
#include "iSceneSwitches.h"
#include "iSimpleCollisionSpace.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using guardian_test::ErrorRecorder;
using namespace resolution_test;

namespace {

iRigidBodySwitches& switches(iPhysicsFrame* f) { return *switchesOf(f->getRB()); }

bool sameOrientation(const Matrix& a, const Matrix& b) {
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            if (a(r, c) != b(r, c)) return false;
    return true;
}

struct Counter final : iCollisionListener {
    int calls = 0;
    void HitWall(iRigidBody*, Vector, Vector) override { ++calls; }
};

const float kSlope = 20.0f * 3.14159265f / 180.0f;

// A sphere (r 0.5 m, 1 kg) on a fixed 20-degree slab, friction mu (the pair's sum); its acceleration down the
// slope measured between 0.5 s and 1.5 s.
float slopeAcceleration(float mu, bool locked, Matrix* orientationBefore = nullptr,
                        Matrix* orientationAfter = nullptr) {
    SceneFixture f;
    Matrix tilt = rotatez(kSlope); // the slope descends toward -x
    Vector down(-std::cos(kSlope), -std::sin(kSlope), 0);
    Vector normal = Vector(0, 1, 0) * tilt;
    iPhysicsFrame* slab = f.world->box(Vector(0, 0, 0), Vector(20, 0.5f, 2), 1.0f, tilt);
    slab->getDynamics()->physicsType = PHYS_FixedInSpace;
    slab->getDynamics()->friction = mu / 2;
    iPhysicsFrame* ball = f.world->sphere(normal * 1.0f, 0.5f, 1.0f);
    ball->getDynamics()->friction = mu / 2;
    switches(ball).setRotationLocked(locked);
    f.seconds(0.5f);
    const float v0 = dot(ball->getDynamics()->velocity, down);
    if (orientationBefore) *orientationBefore = ball->getDynamics()->orientation;
    f.seconds(1.0f);
    if (orientationAfter) *orientationAfter = ball->getDynamics()->orientation;
    return dot(ball->getDynamics()->velocity, down) - v0;
}

} // namespace

// Locked, an off-centre impulse J only pushes: v = J / m, the orientation kept bit for bit under a torque
// too. Unlocked again, the body has its own inertia back: the same impulse turns it at w = (r x J) / I with
// I = 2/5 m (1 m)^2, the tensor of a body with no geometry.
TEST(Switches, ARotationLockedBodyOnlyTranslatesAndUnlockingGivesItsInertiaBack) {
    SceneFixture f;
    iPhysicsFrame* body = CreatePhysicsFrame();
    RBDynamics& d = *body->getDynamics();
    d.physicsType = PHYS_Floating;
    d.mass = 2.0f;
    d.orientation = rotatey(0.3f);
    const Matrix start = d.orientation;
    switches(body).setRotationLocked(true);
    EXPECT_TRUE(switches(body).isRotationLocked());
    f.steps(1);
    d.ApplyImpulse(Vector(0, 0, 4), d.position + Vector(1, 0, 0)); // 1 m off the centre
    d.torque = Vector(0, 3, 0);
    f.seconds(1.0f);
    EXPECT_FLOAT_EQ(d.velocity.z, 4.0f / 2.0f);
    EXPECT_EQ(d.angularVelocity, Vector());
    EXPECT_TRUE(sameOrientation(d.orientation, start));

    d.torque = Vector();
    switches(body).setRotationLocked(false);
    d.angularVelocity = Vector();
    f.steps(1);
    d.ApplyImpulse(Vector(0, 0, 4), d.position + Vector(1, 0, 0)); // r x J = (0, -4, 0)
    f.steps(1);
    EXPECT_NEAR(d.angularVelocity.y, -4.0f / (0.4f * 2.0f), 1e-4f);
    EXPECT_FALSE(sameOrientation(d.orientation, start));
    body->Delete();
}

// A rotation-locked sphere on a 20-degree slope with mu = 0.2 cannot roll: it slides, a = g (sin - mu cos),
// and never turns. Unlocked, it rolls without slipping (mu >= 2/7 tan 20 = 0.10): a = 5/7 g sin.
TEST(Switches, ALockedSphereSlidesDownASlopeWhereAFreeOneRolls) {
    Matrix before, after;
    const float sliding = slopeAcceleration(0.2f, true, &before, &after);
    EXPECT_NEAR(sliding, kG * (std::sin(kSlope) - 0.2f * std::cos(kSlope)), 0.03f * 1.512f);
    EXPECT_TRUE(sameOrientation(before, after));
    const float rolling = slopeAcceleration(0.2f, false);
    EXPECT_NEAR(rolling, 5.0f / 7.0f * kG * std::sin(kSlope), 0.03f * 2.397f);
}

// Gravity off: a body keeps its velocity exactly. A gravity scale of 1/2 gives g/2 (semi-implicit Euler's
// velocity is exact under a constant force); a non-finite scale is refused and the old one kept.
TEST(Switches, GravityOffKeepsVelocityExactlyAndAScaleScalesIt) {
    SceneFixture f;
    iPhysicsFrame* a = CreatePhysicsFrame();
    iPhysicsFrame* b = CreatePhysicsFrame();
    a->getDynamics()->velocity = Vector(1.5f, 2.25f, -0.75f);
    b->getDynamics()->position = Vector(10, 0, 0);
    ErrorRecorder errors;
    EXPECT_TRUE(switches(b).setGravityScale(0.5f));
    EXPECT_FALSE(switches(b).setGravityScale(std::numeric_limits<float>::quiet_NaN()));
    EXPECT_FALSE(switches(b).setGravityScale(std::numeric_limits<float>::infinity()));
    EXPECT_EQ(errors.count(), 2u);
    EXPECT_EQ(switches(b).getGravityScale(), 0.5f);
    ASSERT_TRUE(switchesOf(f.scene)->setFeatureEnabled(FEATURE_Gravity, false));
    f.seconds(1.0f);
    EXPECT_EQ(a->getDynamics()->velocity, Vector(1.5f, 2.25f, -0.75f));
    EXPECT_EQ(b->getDynamics()->velocity, Vector());
    EXPECT_EQ(settingsOf(f.scene)->getGravity(), Vector(0, -kG, 0)); // the vector is kept
    ASSERT_TRUE(switchesOf(f.scene)->setFeatureEnabled(FEATURE_Gravity, true));
    f.seconds(1.0f);
    EXPECT_NEAR(b->getDynamics()->velocity.y, -0.5f * kG, 1e-4f);
    a->Delete();
    b->Delete();
}

// Drag off: a body whose drag would hold it near its terminal speed sqrt(2 m g / (rho Cd A)) = 2.28 m/s (A =
// pi: no geometry, the unit sphere) falls as a projectile, v = g t.
TEST(Switches, DragOffFallsAsAProjectile) {
    for (bool drag : {true, false}) {
        SceneFixture f;
        iPhysicsFrame* body = CreatePhysicsFrame();
        body->getDynamics()->dragCoefficient = 1.0f; // 1 kg: terminal speed 2.28 m/s
        switchesOf(f.scene)->setFeatureEnabled(FEATURE_Drag, drag);
        f.seconds(2.0f);
        const float fall = -body->getDynamics()->velocity.y;
        if (drag)
            EXPECT_LT(fall, std::sqrt(2.0f * kG / (1.2f * 3.14159265f)) * 1.001f);
        else
            EXPECT_NEAR(fall, kG * 2.0f, 1e-3f);
        body->Delete();
    }
}

// Friction off: a box sliding at 3 m/s on the floor keeps its speed; with friction (mu = 0.5 + the plane's
// default 0.25) it stops within v / (mu g) = 0.41 s.
TEST(Switches, FrictionOffABoxSlidesAtConstantSpeed) {
    for (bool friction : {true, false}) {
        SceneFixture f;
        f.world->ground();
        iPhysicsFrame* box = f.world->box(Vector(0, 0.5f, 0), Vector(0.5f, 0.5f, 0.5f), 1.0f);
        box->getDynamics()->friction = 0.5f;
        box->getDynamics()->velocity = Vector(3, 0, 0);
        switchesOf(f.scene)->setFeatureEnabled(FEATURE_Friction, friction);
        EXPECT_EQ(switchesOf(f.scene)->isFeatureEnabled(FEATURE_Friction), friction);
        f.seconds(1.0f);
        if (friction)
            EXPECT_LT(box->getDynamics()->velocity.x, 0.01f);
        else
            EXPECT_NEAR(box->getDynamics()->velocity.x, 3.0f, 1e-4f);
    }
}

// Restitution off: a superball (e = 1) reaching the floor at 5 m/s does not rebound; with it on it leaves at
// about 5 m/s.
TEST(Switches, RestitutionOffABallDoesNotRebound) {
    for (bool restitution : {true, false}) {
        SceneFixture f;
        f.world->ground();
        iPhysicsFrame* ball = f.world->sphere(Vector(0, 1.0f, 0), 0.5f, 1.0f);
        RBDynamics& d = *ball->getDynamics();
        d.restitution = 1.0f;
        // From 0.5 m above the floor at v0 such that it lands at 5 m/s: v0^2 = 25 - 2 g 0.5.
        d.velocity = Vector(0, -std::sqrt(25.0f - kG), 0);
        switchesOf(f.scene)->setFeatureEnabled(FEATURE_Restitution, restitution);
        float up = 0;
        f.seconds(1.0f, [&] { up = std::max(up, d.velocity.y); });
        if (restitution)
            EXPECT_NEAR(up, 5.0f, 0.05f * 5.0f);
        else
            EXPECT_LT(up, 0.05f);
    }
}

// Interpolation off: a frame drawn between two steps shows the last step's pose, not a blend of the last
// two (with it on, the frame lags behind the body).
TEST(Switches, InterpolationOffFramesShowTheLastStepsPose) {
    for (bool interpolate : {true, false}) {
        iPhysicsScene* scene = CreatePhysicsScene(nullptr);
        switchesOf(scene)->setFeatureEnabled(FEATURE_Interpolation, interpolate);
        scene->update(0);
        iPhysicsFrame* body = CreatePhysicsFrame();
        body->getDynamics()->physicsType = PHYS_Floating;
        body->getDynamics()->velocity = Vector(6, 0, 0);
        body->getDynamics()->angularVelocity = Vector(0, 2, 0);
        scene->update(125); // 7.5 steps at 60 Hz: half a step is left over
        const Vector framePos = body->position();
        const Vector bodyPos = body->getDynamics()->getWorldOrigin();
        if (interpolate)
            EXPECT_NEAR((framePos - bodyPos).length(), 6.0f / 120.0f, 1e-4f); // half a step behind
        else
            EXPECT_NEAR((framePos - bodyPos).length(), 0.0f, 1e-5f);
        body->Delete();
        scene->Delete();
    }
}

// Validation off: a NaN or a scaled orientation written straight into a body is neither reported nor undone
// (the check is skipped) and the scene steps on without crashing, a collision space included (the NaN
// spreads through the contact solver to the bodies on the same floor: that is what the check is for); what
// the API refuses is still refused (setDynamics, ApplyImpulse, a tensor setter), the old state kept. On
// again, the next step reports every invalid body and puts it back to its last state checked valid.
TEST(Switches, ValidationOffSkipsTheCheckButTheApiStillRefusesAndNothingCrashes) {
    SceneFixture f;
    f.world->ground();
    iPhysicsFrame* good = f.world->sphere(Vector(0, 0.5f, 0), 0.5f, 1.0f);
    iPhysicsFrame* bad = f.world->sphere(Vector(3, 0.5f, 0), 0.5f, 1.0f);
    iPhysicsFrame* scaled = f.world->box(Vector(-3, 0.5f, 0), Vector(0.5f, 0.5f, 0.5f), 1.0f);
    ASSERT_TRUE(switchesOf(f.scene)->setFeatureEnabled(FEATURE_Validation, false));
    f.seconds(0.1f);
    ErrorRecorder errors;
    RBDynamics candidate = *good->getDynamics();
    candidate.mass = -1.0f;
    good->getRB()->setDynamics(candidate);
    EXPECT_EQ(good->getDynamics()->mass, 1.0f);
    good->getDynamics()->ApplyImpulse(Vector(std::nanf(""), 0, 0), Vector());
    good->getDynamics()->setInertiaTensor(Matrix(0));
    EXPECT_EQ(errors.count(), 3u);
    EXPECT_TRUE(good->getDynamics()->velocity.isFinite());

    bad->getDynamics()->velocity = Vector(std::nanf(""), 0, 0);
    scaled->getDynamics()->orientation = Matrix(2);
    f.seconds(2.0f);
    // The scene reports nothing (the space may: it skips a body whose pose is not finite).
    EXPECT_EQ(ErrorRecorder::last().find(L"invalid rigid body state"), std::wstring::npos);
    EXPECT_FALSE(bad->getDynamics()->velocity.isFinite()); // simulated as written: not undone
    // ... but kept to itself: the ground it rests on is never written, so a ball resting 3 m away stays
    // sound.
    EXPECT_TRUE(good->getDynamics()->velocity.isFinite());
    EXPECT_TRUE(good->getDynamics()->position.isFinite());

    switchesOf(f.scene)->setFeatureEnabled(FEATURE_Validation, true);
    f.steps(1);
    EXPECT_GE(errors.count(), 3u + 2u);
    EXPECT_TRUE(f.world->allFinite());
    // The scaled box: its first step turned it by a unit quaternion, so it became a rotation again and rests
    // flat on the ground.
    const Matrix& turned = scaled->getDynamics()->orientation;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(turned(r, c), r == c ? 1.0f : 0.0f, 1e-5f) << r << c;
}

// Listeners off: no HitWall call while a ball rests on the floor; on again, one a frame.
TEST(Switches, ListenersOffNoHitWall) {
    SceneFixture f;
    f.world->ground();
    iPhysicsFrame* ball = f.world->sphere(Vector(0, 0.499f, 0), 0.5f, 1.0f);
    Counter listener;
    ball->getRB()->attachListener(&listener);
    switchesOf(f.scene)->setFeatureEnabled(FEATURE_Listeners, false);
    f.seconds(1.0f);
    EXPECT_EQ(listener.calls, 0);
    switchesOf(f.scene)->setFeatureEnabled(FEATURE_Listeners, true);
    f.steps(1); // the first delivery reports the pair once
    listener.calls = 0;
    f.steps(30);
    EXPECT_EQ(listener.calls, 30);
}

// Per body: a box that may not sleep stays awake, and so does a box resting on it (one island), while a box
// alone on the floor falls asleep; allowed again, the two fall asleep too.
TEST(Switches, ABodyThatMayNotSleepKeepsItsIslandAwake) {
    SceneFixture f;
    f.world->ground();
    const Vector half(0.5f, 0.5f, 0.5f);
    iPhysicsFrame* insomniac = f.world->box(Vector(0, 0.5f, 0), half, 1.0f);
    iPhysicsFrame* neighbour = f.world->box(Vector(0, 1.5f, 0), half, 1.0f); // resting on it
    iPhysicsFrame* alone = f.world->box(Vector(10, 0.5f, 0), half, 1.0f);
    switches(insomniac).setSleepAllowed(false);
    EXPECT_FALSE(switches(insomniac).getSleepAllowed());
    f.seconds(3.0f);
    EXPECT_FALSE(insomniac->getDynamics()->sleeping);
    EXPECT_FALSE(neighbour->getDynamics()->sleeping);
    EXPECT_TRUE(alone->getDynamics()->sleeping);
    switches(insomniac).setSleepAllowed(true);
    f.seconds(1.0f);
    EXPECT_TRUE(insomniac->getDynamics()->sleeping);
    EXPECT_TRUE(neighbour->getDynamics()->sleeping);
}

// Per body and per scene: continuous collision off lets a 5 cm ball at 300 m/s (5 m a step) pass a 4 cm
// fixed wall that it cannot pass with it on (in a space that does not sample motions itself).
TEST(Switches, ContinuousCollisionOffPerBodyOrPerSceneLetsAFastBallTunnel) {
    enum { On, BodyOff, SceneOff };
    for (int mode : {On, BodyOff, SceneOff}) {
        SceneFixture f(4, CreateSimpleCollisionSpace(0)); // the space's own sampling off: the stage alone
        f.world->fixedBox(Vector(0, 0, 0), Vector(0.02f, 2, 2));
        iPhysicsFrame* ball = f.world->sphere(Vector(-2.6f, 0, 0), 0.05f, 1.0f);
        ball->getDynamics()->physicsType = PHYS_Floating;
        ball->getDynamics()->velocity = Vector(300, 0, 0);
        if (mode == BodyOff) switches(ball).setContinuousCollisionEnabled(false);
        if (mode == SceneOff) switchesOf(f.scene)->setFeatureEnabled(FEATURE_ContinuousCollision, false);
        EXPECT_EQ(settingsOf(f.scene)->getContinuousCollisionEnabled(), mode != SceneOff);
        f.steps(3);
        if (mode == On)
            EXPECT_LT(ball->getDynamics()->position.x, 0.0f);
        else
            EXPECT_GT(ball->getDynamics()->position.x, 5.0f);
    }
}

// Every feature starts on and can be switched off and on; a value that is not a SceneFeature is refused
// with one error and changes nothing. The sleeping switch is the settings' one.
TEST(Switches, SceneSwitchesAcceptEveryFeatureAndRefuseOthers) {
    SceneFixture f;
    iSceneSwitches* s = switchesOf(f.scene);
    ASSERT_NE(s, nullptr);
    for (int i = 0; i < FEATURE_Count; ++i) {
        const SceneFeature feature = SceneFeature(i);
        EXPECT_TRUE(s->isFeatureEnabled(feature));
        EXPECT_TRUE(s->setFeatureEnabled(feature, false));
        EXPECT_FALSE(s->isFeatureEnabled(feature));
        for (int j = 0; j < FEATURE_Count; ++j)
            if (j != i) {
                EXPECT_TRUE(s->isFeatureEnabled(SceneFeature(j))) << i << " turned off " << j;
            }
        EXPECT_TRUE(s->setFeatureEnabled(feature, true));
    }
    ErrorRecorder errors;
    EXPECT_FALSE(s->setFeatureEnabled(FEATURE_Count, false));
    EXPECT_FALSE(s->setFeatureEnabled(SceneFeature(-1), false));
    EXPECT_FALSE(s->isFeatureEnabled(SceneFeature(99)));
    EXPECT_EQ(errors.count(), 2u);
    for (int i = 0; i < FEATURE_Count; ++i) EXPECT_TRUE(s->isFeatureEnabled(SceneFeature(i)));
    settingsOf(f.scene)->setSleepingEnabled(false);
    EXPECT_FALSE(s->isFeatureEnabled(FEATURE_Sleeping));
}
