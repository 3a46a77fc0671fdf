// BadValuesTest.cpp - impossible values are refused, never obeyed (issue 11, item 4): inertia tensors
// whose inverse does not fit a float, tensors that do (a 1 km rock), a zero inverse tensor (rotation locked),
// and a NaN written into a bound frame (refused once, not re-adopted every update).
#include "PhysicsTestSupport.h"
#include "iPhysicsFrame.h"
#include "iPhysicsSceneSettings.h"
#include "iPhysicsSceneStats.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using physics_test::ErrorRecorder;
using physics_test::kG;
using physics_test::SceneHolder;

namespace {

Matrix diagonal(float d) { return Matrix(d); } // 3x3 block d, m44 = 1

// Every property of RBDynamics written bad, one at a time (a NaN where a number may be anything finite).
struct BadWrite {
    const char* name;
    void (*write)(RBDynamics&, float nan);
};
const BadWrite kBadWrites[] = {
    {"position", [](RBDynamics& x, float n) { x.position.y = n; }},
    {"velocity", [](RBDynamics& x, float n) { x.velocity.z = n; }},
    {"lastVelocity", [](RBDynamics& x, float n) { x.lastVelocity.x = n; }},
    {"acceleration", [](RBDynamics& x, float n) { x.acceleration.y = n; }},
    {"force", [](RBDynamics& x, float n) { x.force.x = n; }},
    {"temporalForce", [](RBDynamics& x, float n) { x.temporalForce.z = n; }},
    {"com", [](RBDynamics& x, float n) { x.com.x = n; }},
    {"angularVelocity", [](RBDynamics& x, float n) { x.angularVelocity.y = n; }},
    {"torque", [](RBDynamics& x, float n) { x.torque.x = n; }},
    {"temporalTorque", [](RBDynamics& x, float n) { x.temporalTorque.y = n; }},
    {"angularMomentum", [](RBDynamics& x, float n) { x.angularMomentum.z = n; }},
    {"mass", [](RBDynamics& x, float) { x.mass = -1.0f; }},
    {"dragCoefficient", [](RBDynamics& x, float) { x.dragCoefficient = -1.0f; }},
    {"angularDrag", [](RBDynamics& x, float n) { x.angularDrag = n; }},
    {"restitution", [](RBDynamics& x, float) { x.restitution = 50.0f; }},
    {"friction", [](RBDynamics& x, float) { x.friction = -1.0f; }},
    {"physicsType", [](RBDynamics& x, float) { x.physicsType = PhysicsType(7); }},
    {"orientation", [](RBDynamics& x, float) { x.orientation = Matrix(2); }},
    {"inertia tensor", [](RBDynamics& x, float) { x.getInertiaTensor() = Matrix(-1); }},
    {"inverse inertia tensor", [](RBDynamics& x, float) { x.getInverseInertiaTensor() = Matrix(-1); }},
};
} // namespace

// A 1 km rock: mass 2.5e12 kg, a solid sphere of radius 500 m, I = 0.4 m r^2 = 2.5e17 kg m^2. Its inverse,
// 4e-18, is an ordinary float; the float 3x3 inverse overflowed the determinant (1.6e52) and gave zero, so
// the tensor was refused every step with "inertia tensor and inverse inertia tensor disagree". It must spin
// up under a torque tau at tau t / I: tau = 2.5e17 N m for 1 s gives 1 rad/s.
TEST(BadValues, AOneKilometreRockIsAcceptedAndSpinsAtTauTOverI) {
    SceneHolder h(60);
    iPhysicsFrame* rock = CreatePhysicsFrame();
    RBDynamics& d = *rock->getDynamics();
    d.mass = 2.5e12f;
    d.physicsType = PHYS_Floating;
    ErrorRecorder errors;
    const float inertia = 0.4f * 2.5e12f * 500.0f * 500.0f;
    d.setInertiaTensor(diagonal(inertia));
    EXPECT_EQ(errors.count(), 0u);
    EXPECT_NEAR(d.getInverseInertiaTensor().m11 * inertia, 1.0f, 1e-5f);
    d.torque = Vector(0, inertia, 0); // 1 rad/s^2
    h.run(1000);
    EXPECT_EQ(errors.count(), 0u);
    EXPECT_NEAR(d.angularVelocity.y, 1.0f, 1e-3f);
    RecordProperty("rock_omega_rad_s", std::to_string(d.angularVelocity.y));
    rock->Delete();
}

// 1e30 kg m^2 has a representable inverse (1e-30) once inverted in double: accepted, and the body just
// falls, with no error at any step (it used to get a NaN inverse and freeze, reported every step).
// A tensor whose inverse overflows (1e-39 -> 1e39), an infinite one and a negative one are refused at once,
// and the old tensor is kept.
TEST(BadValues, InertiaTensorsAreAcceptedExactlyWhenTheyAndTheirInverseAreFiniteAndPositive) {
    SceneHolder h(60);
    iPhysicsFrame* f = CreatePhysicsFrame();
    RBDynamics& d = *f->getDynamics();
    ErrorRecorder errors;
    d.setInertiaTensor(diagonal(1e30f));
    EXPECT_EQ(errors.count(), 0u);
    EXPECT_TRUE(d.getInverseInertiaTensor().isFinite());
    EXPECT_NEAR(d.getInverseInertiaTensor().m22 * 1e30f, 1.0f, 1e-5f);
    h.run(1000);
    EXPECT_EQ(errors.count(), 0u);
    EXPECT_NEAR(d.velocity.y, -kG, 1e-3f); // it fell for the whole second
    const Matrix kept = d.getInertiaTensor();
    d.setInertiaTensor(diagonal(1e-39f)); // denormal, positive, but its inverse is infinite
    EXPECT_EQ(errors.count(), 1u);
    d.setInertiaTensor(diagonal(std::numeric_limits<float>::infinity()));
    EXPECT_EQ(errors.count(), 2u);
    d.setInertiaTensor(diagonal(-1.0f));
    EXPECT_EQ(errors.count(), 3u);
    d.setInverseInertiaTensor(diagonal(1e-39f)); // its inverse, 1e39, is not a float
    EXPECT_EQ(errors.count(), 4u);
    EXPECT_EQ(d.getInertiaTensor(), kept);
    // Written through the reference: refused at the next step, the body restored.
    d.getInertiaTensor() = diagonal(-2.0f);
    h.run(20);
    EXPECT_EQ(errors.count(), 5u);
    EXPECT_EQ(d.getInertiaTensor(), kept);
    f->Delete();
}

// A zero inverse tensor is infinite inertia: rotation locked, allowed without an error. Under a torque, an
// angular velocity written by the game, and an off-centre impulse, the body never turns; the impulse still
// moves it by J / m.
TEST(BadValues, AZeroInverseInertiaTensorLocksRotation) {
    SceneHolder h(60);
    iPhysicsFrame* f = CreatePhysicsFrame();
    RBDynamics& d = *f->getDynamics();
    d.physicsType = PHYS_Floating;
    d.mass = 2.0f;
    ErrorRecorder errors;
    d.setInverseInertiaTensor(Matrix(0));
    EXPECT_EQ(errors.count(), 0u);
    d.torque = Vector(3, 10, -5);
    d.angularVelocity = Vector(0, 4, 0);
    d.ApplyImpulse(Vector(0, 0, 2), Vector(1, 0, 0)); // 1 m off the centre
    EXPECT_NEAR(d.velocity.z, 1.0f, 1e-6f);
    h.run(1000);
    EXPECT_EQ(errors.count(), 0u);
    EXPECT_EQ(d.angularVelocity, Vector());
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(d.orientation(r, c), r == c ? 1.0f : 0.0f, 1e-6f);
    EXPECT_NEAR(d.position.z, 1.0f, 1e-3f); // 1 m/s for 1 s
    f->Delete();
}

// A NaN written into a bound frame's transform is refused once (one error, not one per update), the body
// keeps its state and keeps falling, and a NaN rotation is overwritten with the body's valid pose.
TEST(BadValues, ANaNRotationInABoundFrameIsRefusedOnceAndOverwritten) {
    SceneHolder h(60);
    iPhysicsFrame* f = CreatePhysicsFrame();
    f->getDynamics()->position = Vector(0, 100, 0);
    h.run(100);
    ErrorRecorder errors;
    f->rotatex(std::numeric_limits<float>::quiet_NaN());
    ASSERT_FALSE(f->world().isFinite());
    for (int i = 0; i < 10; ++i) h.run(10);
    EXPECT_EQ(errors.count(), 1u);
    const float t = h.now / 1000.0f;
    EXPECT_NEAR(f->getDynamics()->velocity.y, -kG * t, 0.2f); // kept falling: about -1.96 m/s
    EXPECT_TRUE(f->world().isFinite());
    EXPECT_NEAR(f->position().y, f->getDynamics()->position.y, 0.1f); // drawn where the body is
    RecordProperty("errors_after_10_updates", std::to_string(errors.count()));
    f->Delete();
}

// The same for a NaN in the frame's translation: iFrame's members (translate adds to T) cannot clear it, but
// it is reported once, not adopted, and the body keeps falling.
TEST(BadValues, ANaNTranslationInABoundFrameIsRefusedOnce) {
    SceneHolder h(60);
    iPhysicsFrame* f = CreatePhysicsFrame();
    f->getDynamics()->position = Vector(0, 100, 0);
    h.run(100);
    ErrorRecorder errors;
    f->translate(std::numeric_limits<float>::quiet_NaN(), 0, 0);
    for (int i = 0; i < 10; ++i) h.run(10);
    EXPECT_EQ(errors.count(), 1u);
    const float t = h.now / 1000.0f;
    EXPECT_NEAR(f->getDynamics()->velocity.y, -kG * t, 0.2f);
    EXPECT_TRUE(f->getDynamics()->position.isFinite());
    f->Delete();
}

// A body nothing touched since the last step is accepted without the checks (RigidBody::acceptState): every
// property written bad into such a body, one at a time, must still be refused, reported and put back.
TEST(BadValues, EachPropertyWrittenBadIntoABodyUnchangedSinceTheLastStepIsRefused) {
    SceneHolder h(60);
    settingsOf(h.scene)->setSleepingEnabled(false); // (a sleeping body is checked when it wakes)
    iPhysicsFrame* f = CreatePhysicsFrame();
    RBDynamics& d = *f->getDynamics();
    d.physicsType = PHYS_Floating; // at rest, no gravity: a step leaves its state as it was
    d.position = Vector(1, 2, 3);
    h.run(100);
    for (const BadWrite& e : kBadWrites) {
        h.run(50); // steps in which nothing changes
        const float mass = d.mass, restitution = d.restitution;
        const Vector position = d.position;
        ErrorRecorder errors;
        e.write(d, std::numeric_limits<float>::quiet_NaN());
        h.run(20); // one step at least
        EXPECT_EQ(errors.count(), 1u) << e.name;
        EXPECT_NE(ErrorRecorder::last().find(L"invalid rigid body state"), std::wstring::npos) << e.name;
        // Put back: the state is the last valid one.
        EXPECT_EQ(d.mass, mass) << e.name;
        EXPECT_EQ(d.restitution, restitution) << e.name;
        EXPECT_EQ(d.position, position) << e.name;
        EXPECT_EQ(d.physicsType, PHYS_Floating) << e.name;
        EXPECT_TRUE(d.velocity.isFinite() && d.angularMomentum.isFinite() && d.com.isFinite()) << e.name;
        EXPECT_TRUE(isRotation(d.orientation, 1e-4f)) << e.name;
    }
    f->Delete();
}

// A moving body's state differs after every step only in its motion, and only that is checked and kept
// then (RigidBody::acceptState): every property written bad into a falling, spinning body is still refused
// and reported once, and the body goes on from the last state a step left, in free fall (v = v0 - g n dt
// after n steps) and spinning as before.
TEST(BadValues, EachPropertyWrittenBadIntoAMovingBodyIsRefusedAndItFallsOnFromItsLastStep) {
    SceneHolder h(60);
    settingsOf(h.scene)->setSleepingEnabled(false);
    iPhysicsFrame* f = CreatePhysicsFrame();
    RBDynamics& d = *f->getDynamics();
    d.position = Vector(0, 1000, 0);
    d.angularVelocity = Vector(0, 1, 0); // about a principal axis of its (spherical) inertia: it stays
    h.run(100);
    for (const BadWrite& e : kBadWrites) {
        h.run(50);
        const float mass = d.mass, restitution = d.restitution, v0 = d.velocity.y, y0 = d.position.y;
        const long long steps0 = statsOf(h.scene)->getStepCount();
        ErrorRecorder errors;
        e.write(d, std::numeric_limits<float>::quiet_NaN());
        h.run(50);
        const long long n = statsOf(h.scene)->getStepCount() - steps0;
        ASSERT_GE(n, 1) << e.name;
        EXPECT_EQ(errors.count(), 1u) << e.name;
        EXPECT_NE(ErrorRecorder::last().find(L"invalid rigid body state"), std::wstring::npos) << e.name;
        EXPECT_EQ(d.mass, mass) << e.name;
        EXPECT_EQ(d.restitution, restitution) << e.name;
        EXPECT_EQ(d.physicsType, PHYS_Falling) << e.name;
        EXPECT_NEAR(d.velocity.y, v0 - kG * float(n) / 60.0f, 1e-3f) << e.name;
        EXPECT_LT(d.position.y, y0) << e.name;
        EXPECT_NEAR(d.angularVelocity.y, 1.0f, 1e-4f) << e.name;
        EXPECT_TRUE(d.position.isFinite() && d.angularMomentum.isFinite() && d.com.isFinite()) << e.name;
        EXPECT_TRUE(isRotation(d.orientation, 1e-4f)) << e.name;
    }
    f->Delete();
}

// A clone takes the state it is given; when that state is invalid (a NaN written into the original just
// before), the clone's next step refuses it like the original's, and puts back the original's last valid
// state, never the NaN.
TEST(BadValues, ACloneOfABodyHoldingANaNIsPutBackToAValidState) {
    SceneHolder h(60);
    settingsOf(h.scene)->setSleepingEnabled(false);
    iRigidBody* original = CreateRigidBody(nullptr);
    original->getDynamics().position = Vector(0, 10, 0);
    h.run(100);
    ErrorRecorder errors;
    original->getDynamics().velocity.x = std::numeric_limits<float>::quiet_NaN();
    iRigidBody* copy = original->clone();
    h.run(50);
    EXPECT_TRUE(original->getDynamics().velocity.isFinite());
    EXPECT_TRUE(copy->getDynamics().velocity.isFinite());
    EXPECT_TRUE(copy->getDynamics().position.isFinite());
    EXPECT_EQ(errors.count(), 2u); // each refused once, then valid
}

TEST(BadValues, AFramesCloneOfABodyHoldingANaNIsPutBackToAValidState) {
    // The same through iPhysicsFrame::clone, which places its copy at a new frame.
    SceneHolder h(60);
    settingsOf(h.scene)->setSleepingEnabled(false);
    iPhysicsFrame* original = CreatePhysicsFrame();
    h.scene->add(original->getRB());
    original->getDynamics()->position = Vector(0, 10, 0);
    h.run(100);
    ErrorRecorder errors;
    original->getDynamics()->velocity.x = std::numeric_limits<float>::quiet_NaN();
    iPhysicsFrame* copy = original->clone();
    h.run(50);
    EXPECT_TRUE(original->getDynamics()->velocity.isFinite());
    EXPECT_TRUE(copy->getDynamics()->velocity.isFinite());
    EXPECT_TRUE(copy->getDynamics()->position.isFinite());
    EXPECT_EQ(errors.count(), 2u); // each refused once, then valid
    copy->Delete();
    original->Delete();
}
