// WakeTest.cpp - a sleeping island wakes whole and warm: woken at one body (by the game or by a touch), a
// resting pyramid stays at rest. Woken a layer a step, each layer started cold under the weight above and
// the pyramid collapsed in a wave: 84 J of kinetic energy from nothing, 6.6 cm of overlap.
#include "ErrorRecorder.h"
#include "SceneFixture.h"
#include "Scenes.h"
#include "iBallJoint.h"
#include "iCPlane.h"
#include "iForceGenerator.h"
#include "iHingeJoint.h"
#include "iPhysicsSceneHooks.h"
#include "iPhysicsSceneStats.h"
#include "iRigidBodyMotion.h"
#include "iSpring.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using resolution_test::SceneFixture;

namespace {

struct SleepingPyramid {
    SleepingPyramid() {
        buildPyramid(*s.world, 20);
        s.seconds(6.0f);
        restingOverlap = statsOf(s.scene)->getMaxPenetration();
    }
    SceneFixture s{4};
    float restingOverlap = 0;
};

} // namespace

// The game wakes the top box: all 210 wake in the same step, and nothing moves that was not moving. The
// awake pyramid's own jitter is about 2 mJ; its resting overlap the springs' give, 2.1 mm.
TEST(Wake, APyramidWokenByTheGameStaysAtRest) {
    SleepingPyramid p;
    ASSERT_EQ(statsOf(p.s.scene)->getAwakeBodyCount(), 0u);
    motionOf(p.s.world->bodies().back()->getRB())->wake();
    float worstEnergy = 0, worstOverlap = 0;
    p.s.steps(1);
    EXPECT_EQ(statsOf(p.s.scene)->getAwakeBodyCount(), 210u);
    p.s.steps(29, [&] {
        worstEnergy = std::max(worstEnergy, p.s.world->kineticEnergy());
        worstOverlap = std::max(worstOverlap, statsOf(p.s.scene)->getMaxPenetration());
    });
    EXPECT_LT(worstEnergy, 0.01f);
    EXPECT_LT(worstOverlap, p.restingOverlap + 0.001f);
}

// A ball rolling at 0.5 m/s into the sleeping pyramid's base wakes it by touch. No energy appears: the
// kinetic energy of everything stays below what the ball brought (the pyramid may settle by a hair, which
// the 10 mJ allows). While the ball rolled beside it, the ball's own contacts were solved every step: the
// pyramid's sleeping manifolds are carried unsolved meanwhile, so it wakes warm-started (dropped, it woke
// cold under its own weight: 2.5 J). Overlap: the ball's, found a step late (no contact is reported before
// a touch: up to its 0.5 m/s x 1/60 s), on top of the resting give.
TEST(Wake, APyramidWokenByATouchGainsNoEnergy) {
    SleepingPyramid p;
    iPhysicsFrame* ball = p.s.world->sphere(Vector(-10.8f, 0.25f, 0), 0.25f, 1.0f);
    ball->getDynamics()->velocity = Vector(0.5f, 0, 0);
    const float brought = 0.5f * 1.0f * 0.5f * 0.5f;
    float worstEnergy = 0, worstOverlap = 0;
    bool woke = false;
    p.s.seconds(4.0f, [&] {
        worstEnergy = std::max(worstEnergy, p.s.world->kineticEnergy());
        worstOverlap = std::max(worstOverlap, statsOf(p.s.scene)->getMaxPenetration());
        woke = woke || statsOf(p.s.scene)->getAwakeBodyCount() > 100;
    });
    EXPECT_TRUE(woke); // the ball reached it
    EXPECT_LT(worstEnergy, brought + 0.01f);
    EXPECT_LT(worstOverlap, p.restingOverlap + 0.5f / 60.0f + 0.0005f);
}

// Gravity turned upward: a box asleep on the floor wakes and falls up at g (y = y0 + g t^2 / 2, within the
// integrator's g t dt / 2). Asleep under the old gravity it hung on the floor. Setting the same gravity again
// wakes nothing.
TEST(Wake, GravityChangedWakesWhatSleptUnderTheOld) {
    SceneFixture s(4);
    s.world->ground();
    iPhysicsFrame* box = s.world->box(Vector(0, 0.5f, 0), Vector(0.5f, 0.5f, 0.5f), 1.0f);
    for (int i = 0; i < 180 && !box->getDynamics()->sleeping; ++i) s.steps(1);
    ASSERT_TRUE(box->getDynamics()->sleeping);
    iPhysicsSceneSettings* settings = settingsOf(s.scene);
    settings->setGravity(settings->getGravity());
    s.steps(1);
    EXPECT_TRUE(box->getDynamics()->sleeping) << "the same gravity again changes nothing";
    const float y0 = box->getDynamics()->position.y;
    settings->setGravity(Vector(0, resolution_test::kG, 0));
    const int n = 30;
    s.steps(n);
    const float t = n * resolution_test::kDt;
    EXPECT_FALSE(box->getDynamics()->sleeping);
    EXPECT_NEAR(box->getDynamics()->position.y, y0 + 0.5f * resolution_test::kG * t * t,
                0.5f * resolution_test::kG * t * resolution_test::kDt + 1e-3f);
}

namespace {

bool sleepsWithin(SceneFixture& s, iPhysicsFrame* f, float seconds) {
    for (int i = 0; i < int(seconds * 60) && !f->getDynamics()->sleeping; ++i) s.steps(1);
    return f->getDynamics()->sleeping;
}

// Where a body starting at rest at y0 is after n steps under a constant vertical acceleration a, and how far
// semi-implicit Euler may be from it (|a| t dt / 2).
void expectUniformAcceleration(const iPhysicsFrame* f, float y0, float a, int n) {
    const float t = float(n) * resolution_test::kDt;
    EXPECT_NEAR(f->getDynamics()->position.y, y0 + 0.5f * a * t * t,
                0.5f * std::fabs(a) * t * resolution_test::kDt + 1e-3f);
}

struct ConstantForce final : iForceGenerator {
    Vector force;
    void addForces(const iRigidBody*, const RigidBodyState&, Vector& f, Vector&) override { f += force; }
};

} // namespace

// A box asleep hanging from a joint: the joint deleted, or let go because the body it hung from was deleted,
// the box wakes and falls at g. Asleep, it hung in the air.
TEST(Wake, AJointGoingDropsWhatSleptHangingFromIt) {
    for (int how = 0; how < 2; ++how) {
        SceneFixture s(4);
        iPhysicsFrame* hook = CreatePhysicsFrame(); // not the world's: deleted here
        hook->getDynamics()->physicsType = PHYS_FixedInSpace;
        hook->getDynamics()->position = Vector(0, 6, 0);
        iPhysicsFrame* box = s.world->box(Vector(0, 5, 0), Vector(0.5f, 0.5f, 0.5f), 1.0f);
        iBallJoint* joint = CreateBallJoint(box->getRB(), hook->getRB(), Vector(0, 5.5f, 0));
        ASSERT_NE(joint, nullptr);
        ASSERT_TRUE(sleepsWithin(s, box, 5.0f)) << how;
        const float y0 = box->getDynamics()->position.y;
        if (how == 0)
            joint->Delete();
        else
            hook->Delete(); // the joint lets go of the box
        const int n = 30;
        s.steps(n);
        EXPECT_FALSE(box->getDynamics()->sleeping) << how;
        expectUniformAcceleration(box, y0, -resolution_test::kG, n);
        if (how == 0)
            hook->Delete();
        else
            joint->Delete();
    }
}

// A force generator added to a sleeping body acts on it (30 N up on 1 kg asleep on the floor: it rises at
// 30 - g m/s^2); removed from a body it held floating asleep, the body falls at g. A sleeping body's
// generators are not evaluated: asleep, it never felt the one added.
TEST(Wake, AddingOrRemovingAForceGeneratorWakesItsBody) {
    SceneFixture s(4);
    s.world->ground();
    iPhysicsFrame* box = s.world->box(Vector(0, 0.5f, 0), Vector(0.5f, 0.5f, 0.5f), 1.0f);
    ASSERT_TRUE(sleepsWithin(s, box, 3.0f));
    ConstantForce lift;
    lift.force = Vector(0, 30, 0);
    ASSERT_TRUE(hooksOf(s.scene)->addForceGenerator(box->getRB(), &lift));
    float y0 = box->getDynamics()->position.y;
    s.steps(30);
    expectUniformAcceleration(box, y0, 30.0f - resolution_test::kG, 30);
    hooksOf(s.scene)->removeForceGenerator(box->getRB(), &lift);

    iPhysicsFrame* floating = s.world->box(Vector(10, 5, 0), Vector(0.5f, 0.5f, 0.5f), 1.0f);
    ConstantForce hold; // exactly its weight
    hold.force = Vector(0, resolution_test::kG, 0);
    ASSERT_TRUE(hooksOf(s.scene)->addForceGenerator(floating->getRB(), &hold));
    ASSERT_TRUE(sleepsWithin(s, floating, 3.0f));
    y0 = floating->getDynamics()->position.y;
    hooksOf(s.scene)->removeForceGenerator(floating->getRB(), &hold);
    s.steps(30);
    expectUniformAcceleration(floating, y0, -resolution_test::kG, 30);
}

// A joint's setters wake its bodies when they change something: a motor turned on at a sleeping hinge drives
// it at the motor's speed; a spring shortened by 0.5 m under a sleeping box lifts it 0.5 m (k = 100 N/m,
// critically damped, 1 kg). Asleep, neither felt the change.
TEST(Wake, AJointsSettersWakeItsBodies) {
    SceneFixture s(4);
    iPhysicsFrame* wheel = s.world->box(Vector(0, 3, 0), Vector(0.5f, 0.5f, 0.1f), 1.0f);
    iHingeJoint* hinge = CreateHingeJoint(wheel->getRB(), nullptr, Vector(0, 3, 0), Vector(0, 0, 1));
    iPhysicsFrame* box = s.world->box(Vector(5, 3, 0), Vector(0.5f, 0.5f, 0.5f), 1.0f);
    const float k = 100.0f, stretch = resolution_test::kG / k;
    iSpring* spring =
        CreateSpring(box->getRB(), nullptr, Vector(5, 3.5f, 0), Vector(5, 5, 0), 1.5f - stretch, k, 20.0f);
    ASSERT_NE(hinge, nullptr);
    ASSERT_NE(spring, nullptr);
    ASSERT_TRUE(sleepsWithin(s, wheel, 3.0f));
    ASSERT_TRUE(sleepsWithin(s, box, 3.0f));
    const float boxY = box->getDynamics()->position.y;
    // The same values again (a game setting them every frame) change nothing: both sleep on.
    ASSERT_TRUE(hinge->setMotor(0.0f, 0.0f));
    ASSERT_TRUE(spring->setRestLength(spring->getRestLength()));
    s.steps(1);
    EXPECT_TRUE(wheel->getDynamics()->sleeping);
    EXPECT_TRUE(box->getDynamics()->sleeping);
    ASSERT_TRUE(hinge->setMotor(2.0f, 100.0f));
    ASSERT_TRUE(spring->setRestLength(1.5f - stretch - 0.5f));
    s.seconds(3.0f);
    EXPECT_NEAR(std::fabs(wheel->getDynamics()->angularVelocity.z), 2.0f, 0.02f);
    EXPECT_NEAR(box->getDynamics()->position.y, boxY + 0.5f, 0.01f);
    hinge->Delete();
    spring->Delete();
}

// A fixed box the game adds overlapping a box asleep on the floor (a wall spawned into it): the sleeper
// wakes (a new fixed body counts as one that moved: Islands::outsiderMoves) and is pushed out of the wall.
TEST(Wake, AFixedBodyAddedIntoASleeperWakesIt) {
    SceneFixture s(4);
    s.world->ground();
    iPhysicsFrame* box = s.world->box(Vector(0, 0.5f, 0), Vector(0.5f, 0.5f, 0.5f), 1.0f);
    ASSERT_TRUE(sleepsWithin(s, box, 3.0f));
    s.world->fixedBox(Vector(0.8f, 0.5f, 0), Vector(0.5f, 0.5f, 0.5f)); // 0.2 m into the box
    s.steps(60);
    EXPECT_LT(box->getDynamics()->position.x, -0.2f + 0.005f) << "pushed out of the wall";
}

// A property written bad into a sleeping body is refused before that body takes part in a contact. Here
// restitution 50 (it does not wake the body): a 1 kg box dropped 0.5 m onto it would leave at 50 times its
// impact speed (combine rule max). Refused, the pair keeps restitution 0: the box stops on the one below (no
// rise above its drop height, no speed beyond the impact speed), and the value is reported once and put back.
TEST(Wake, ABadValueWrittenIntoASleeperIsRefusedBeforeATouchUsesIt) {
    SceneFixture s(4);
    s.world->ground();
    iPhysicsFrame* below = s.world->box(Vector(0, 0.5f, 0), Vector(0.5f, 0.5f, 0.5f), 1.0f);
    below->getDynamics()->restitution = 0.0f;
    ASSERT_TRUE(sleepsWithin(s, below, 3.0f));
    guardian_test::ErrorRecorder errors;
    below->getDynamics()->restitution = 50.0f;
    s.steps(1);
    ASSERT_TRUE(below->getDynamics()->sleeping); // not a motion edit: still asleep
    iPhysicsFrame* above = s.world->box(Vector(0, 2.0f, 0), Vector(0.5f, 0.5f, 0.5f), 1.0f);
    above->getDynamics()->restitution = 0.0f;
    const float impact = std::sqrt(2.0f * 9.81f * 0.5f); // 3.1 m/s
    float highest = 0.0f, fastest = 0.0f;
    for (int i = 0; i < 120; ++i) {
        s.steps(1);
        highest = std::max(highest, above->getDynamics()->position.y);
        fastest = std::max(fastest, above->getDynamics()->velocity.length());
    }
    EXPECT_EQ(errors.count(), 1u);
    EXPECT_EQ(below->getDynamics()->restitution, 0.0f);
    EXPECT_LE(highest, 2.0f + 1e-4f);
    EXPECT_LT(fastest, impact + 0.2f);
    EXPECT_NEAR(above->getDynamics()->position.y, 1.5f, 0.02f);
    EXPECT_NEAR(below->getDynamics()->position.y, 0.5f, 0.02f);
}

TEST(Wake, APlaneAddedIntoASleeperWakesIt) {
    // As a fixed body does: a bodiless wall plane added 0.2 m into a box asleep on the ground pushes it out.
    SceneFixture s(4);
    s.world->ground();
    iPhysicsFrame* box = s.world->box(Vector(0, 0.5f, 0), Vector(0.5f, 0.5f, 0.5f), 1.0f);
    ASSERT_TRUE(sleepsWithin(s, box, 3.0f));
    iCollisionGeometry* wall = CreateCPlane(nullptr, Vector(-1, 0, 0), -0.3f); // solid at x > 0.3
    s.steps(60);
    EXPECT_LT(box->getDynamics()->position.x, -0.2f + 0.005f) << "pushed out of the wall";
    wall->Delete();
}
