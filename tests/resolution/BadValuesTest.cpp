// BadValuesTest.cpp - impossible values are refused, never obeyed (issue 11, item 4), through whole
// simulations: restitution above 1, negative friction, a plane normal whose length overflows a float.
#include "SceneFixture.h"

#include "iCPlane.h"
#include "iCollisionGeometry.h"
#include "iUtilities.h"

#include "ErrorRecorder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace resolution_test;

namespace {
using Quiet = guardian_test::ErrorRecorder; // tests/ErrorRecorder.h
} // namespace

// Restitution 50 sent a ball dropped from 2 m to 1,089 m. Refused at the next step (the body is restored to
// its last valid state, restitution 0.5), the ball never rises above its drop height.
TEST(BadValues, RestitutionAboveOneIsRefusedAndTheBallNeverRisesAboveItsDrop) {
    SceneFixture f;
    f.world->ground();
    RBDynamics* ball = f.world->sphere(Vector(0, 2.5f, 0), 0.5f, 1.0f)->getDynamics();
    f.steps(1); // a valid state to restore (before its first step a body's last valid state is its creation)
    Quiet errors;
    ball->restitution = 50.0f;
    float apex = 0;
    bool bounced = false;
    f.seconds(4.0f, [&] {
        if (ball->velocity.y > 0) bounced = true;
        if (bounced) apex = std::max(apex, ball->position.y - 0.5f);
    });
    EXPECT_TRUE(bounced);
    EXPECT_LE(apex, 2.0f + 1e-3f);
    EXPECT_GE(errors.count(), 1u);
    EXPECT_GE(ball->restitution, 0.0f);
    EXPECT_LE(ball->restitution, 1.0f);
    RecordProperty("apex_m", std::to_string(apex));
}

// Friction -1 sped a box sliding at 2 m/s up to 21 m/s. Refused: the box's kinetic energy never grows.
TEST(BadValues, NegativeFrictionIsRefusedAndASlidingBoxNeverSpeedsUp) {
    SceneFixture f;
    f.world->ground();
    RBDynamics* box = f.world->box(Vector(0, 0.5f, 0), Vector(0.5f, 0.5f, 0.5f), 1.0f)->getDynamics();
    f.seconds(0.5f); // settle
    box->velocity = Vector(2, 0, 0);
    f.steps(1); // sliding: the state a refusal restores is a sliding one
    Quiet errors;
    box->friction = -1.0f;
    float energy = f.world->kineticEnergy(), maxSpeed = 0;
    bool grew = false;
    f.seconds(3.0f, [&] {
        float e = f.world->kineticEnergy();
        if (e > energy + 1e-4f) grew = true;
        energy = e;
        maxSpeed = std::max(maxSpeed, box->velocity.length());
    });
    EXPECT_FALSE(grew);
    EXPECT_GT(box->position.x, 0.3f); // it did slide (2^2 / (2 * 0.5 * 9.81) = 0.41 m)
    EXPECT_LE(maxSpeed, 2.0f + 1e-3f);
    EXPECT_GE(errors.count(), 1u);
    EXPECT_GE(box->friction, 0.0f);
    RecordProperty("max_speed_m_s", std::to_string(maxSpeed));
}

// (0, 1e20, 0) overflowed when squared and normalised to a zero normal: balls fell through the floor. Scaled
// by its largest component first it is (0, 1, 0), and a ball rests on it. A zero or NaN normal is refused.
TEST(BadValues, APlaneNormalThatOverflowsWhenSquaredIsNormalisedAndHoldsABall) {
    SceneFixture f;
    iCollisionGeometry* g = CreateCPlane(nullptr, Vector(0, 1e20f, 0), 0.0f);
    ASSERT_NE(g, nullptr);
    auto* plane = static_cast<iCPlane*>(g);
    EXPECT_EQ(plane->getNormal(), Vector(0, 1, 0));
    RBDynamics* ball = f.world->sphere(Vector(0, 1.5f, 0), 0.5f, 1.0f)->getDynamics();
    f.seconds(3.0f);
    EXPECT_NEAR(ball->position.y, 0.5f, 0.02f);
    RecordProperty("rest_height_m", std::to_string(ball->position.y));

    Quiet errors;
    plane->setPlane(Vector(0, 0, 3e-30f), 0.0f); // tiny: underflowed the same way
    EXPECT_EQ(plane->getNormal(), Vector(0, 0, 1));
    plane->setPlane(Vector(0, 0, 0), 0.0f);
    plane->setPlane(Vector(0, std::nanf(""), 0), 0.0f);
    plane->setPlane(Vector(0, std::numeric_limits<float>::infinity(), 0), 0.0f);
    EXPECT_EQ(errors.count(), 3u);
    EXPECT_EQ(plane->getNormal(), Vector(0, 0, 1)); // kept
    EXPECT_EQ(CreateCPlane(nullptr, Vector(0, 0, 0), 0.0f), nullptr);
    EXPECT_EQ(errors.count(), 4u);
    g->Delete();
}

// A realistic big body passes through the whole pipeline: a 1 km rock (radius 500 m, 2.5e12 kg) made by the
// world's sphere derives I = 0.4 m r^2 = 2.5e17 kg m^2 with no error, and spins up at tau t / I.
TEST(BadValues, AOneKilometreRockSphereGeometryDerivesItsInertiaAndSpins) {
    SceneFixture f;
    Quiet errors;
    RBDynamics* rock = f.world->sphere(Vector(0, 0, 0), 500.0f, 2.5e12f)->getDynamics();
    rock->physicsType = PHYS_Floating;
    const float inertia = 0.4f * 2.5e12f * 500.0f * 500.0f;
    f.steps(1);
    EXPECT_NEAR(rock->getInertiaTensor().m11 / inertia, 1.0f, 1e-4f);
    rock->torque = Vector(0, 2.0f * inertia, 0); // 2 rad/s^2
    f.seconds(1.0f);
    EXPECT_NEAR(rock->angularVelocity.y, 2.0f, 0.01f);
    EXPECT_EQ(errors.count(), 0u);
}
