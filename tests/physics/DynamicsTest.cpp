// DynamicsTest.cpp - what each RBDynamics property does in a scene: physics types, infinite mass, the
// one-step temporal force, and invalid values refused with the body left as it was.
#include "PhysicsTestSupport.h"
#include "iPhysicsSceneSettings.h"

#include <gtest/gtest.h>

#include <cmath>

using physics_test::ErrorRecorder;
using physics_test::SceneHolder;

TEST(Dynamics, InfiniteMassIsKinematicAndFixedInSpaceNeverMoves) {
    SceneHolder h(60);
    iRigidBody* kinematic = CreateRigidBody(nullptr);
    RBDynamics& k = kinematic->getDynamics();
    k.mass = INFINITE_MASS;
    k.velocity = Vector(1, 0, 0);
    k.force = Vector(0, 100, 0);
    k.temporalForce = Vector(0, 0, 50);
    k.angularVelocity = Vector(0, 0.5f, 0);
    k.torque = Vector(3, 0, 0);
    k.ApplyImpulse(Vector(0, 10, 0), k.position + Vector(1, 0, 0)); // no effect
    EXPECT_EQ(k.velocity, Vector(1, 0, 0));
    EXPECT_EQ(k.getMass(), INFINITE_MASS);

    iRigidBody* fixed = CreateRigidBody(nullptr);
    RBDynamics& f = fixed->getDynamics();
    f.physicsType = PHYS_FixedInSpace;
    f.position = Vector(0, 5, 0);
    f.velocity = Vector(1, 1, 1);
    f.angularVelocity = Vector(1, 0, 0);
    f.force = Vector(0, 100, 0);
    f.ApplyImpulse(Vector(0, 10, 0), Vector(1, 5, 0));

    h.run(1000);
    // Kinematic: constant velocity and spin, no gravity, forces or torques.
    EXPECT_NEAR(k.position.x, 1.0f, 1e-5f);
    EXPECT_EQ(k.position.y, 0.0f);
    EXPECT_EQ(k.position.z, 0.0f);
    EXPECT_EQ(k.velocity, Vector(1, 0, 0));
    EXPECT_NEAR(k.orientation.direction('x').z, -std::sin(0.5f), 1e-5f); // x axis turned 0.5 rad about y
    EXPECT_NEAR(k.angularVelocity.y, 0.5f, 1e-6f);
    // Fixed: exactly where it was.
    EXPECT_EQ(f.position, Vector(0, 5, 0));
    EXPECT_EQ(f.orientation, Matrix(1));
}

TEST(Dynamics, FloatingBodiesFeelNoGravityAndFallingOnesDo) {
    SceneHolder h(60);
    iRigidBody* floating = CreateRigidBody(nullptr);
    floating->getDynamics().physicsType = PHYS_Floating;
    floating->getDynamics().velocity = Vector(0, 1, 0);
    iRigidBody* falling = CreateRigidBody(nullptr);
    settingsOf(h.scene)->setGravity(Vector(0, -2, 0));
    h.run(1000);
    EXPECT_NEAR(floating->getDynamics().position.y, 1.0f, 1e-5f);
    EXPECT_NEAR(floating->getDynamics().velocity.y, 1.0f, 1e-6f);
    EXPECT_NEAR(falling->getDynamics().velocity.y, -2.0f, 1e-5f);
    EXPECT_NEAR(falling->getDynamics().lastVelocity.y, falling->getDynamics().velocity.y + 2.0f / 60.0f,
                1e-6f);
}

// a = acceleration + (force + temporalForce) / mass; temporalForce and temporalTorque act for one step.
TEST(Dynamics, TemporalForceAndTorqueActForOneStep) {
    SceneHolder h(60);
    settingsOf(h.scene)->setGravity(Vector());
    iRigidBody* b = CreateRigidBody(nullptr);
    RBDynamics& d = b->getDynamics();
    d.mass = 2.0f;
    d.setInertiaTensor(Matrix(4.0f));
    d.temporalForce = Vector(4, 0, 0);
    d.temporalTorque = Vector(0, 8, 0);
    d.force = Vector(0, 0, 2);
    d.acceleration = Vector(0, 1, 0);
    h.scene->update(17); // one step
    const float dt = 1.0f / 60.0f;
    EXPECT_NEAR(d.velocity.x, 2.0f * dt, 1e-7f);
    EXPECT_NEAR(d.velocity.y, 1.0f * dt, 1e-7f);
    EXPECT_NEAR(d.velocity.z, 1.0f * dt, 1e-7f);
    EXPECT_NEAR(d.angularMomentum.y, 8.0f * dt, 1e-7f);
    EXPECT_NEAR(d.angularVelocity.y, 2.0f * dt, 1e-7f);
    EXPECT_EQ(d.temporalForce, Vector());
    EXPECT_EQ(d.temporalTorque, Vector());
    h.scene->update(34); // a second step: only force and acceleration remain
    EXPECT_NEAR(d.velocity.x, 2.0f * dt, 1e-7f);
    EXPECT_NEAR(d.velocity.z, 2.0f * dt, 1e-7f);
    EXPECT_NEAR(d.angularVelocity.y, 2.0f * dt, 1e-7f);
}

// Writing angularMomentum alone sets w = I_world^-1 L; writing angularVelocity sets L = I_world w.
TEST(Dynamics, AngularVelocityAndMomentumFollowWhicheverWasWritten) {
    SceneHolder h(60);
    settingsOf(h.scene)->setGravity(Vector());
    iRigidBody* b = CreateRigidBody(nullptr);
    RBDynamics& d = b->getDynamics();
    d.setInertiaTensor(Matrix(Vector(1, 2, 4)));
    d.angularMomentum = Vector(0, 0, 2);
    h.scene->update(17);
    EXPECT_NEAR(d.angularVelocity.z, 0.5f, 1e-6f);
    d.angularVelocity = Vector(0, 0, 1); // both written: w wins
    d.angularMomentum = Vector(0, 0, 100);
    h.scene->update(34);
    EXPECT_NEAR(d.angularMomentum.z, 4.0f, 1e-5f);
}

TEST(Dynamics, InvalidStatesAreRefusedAndTheLastValidStateKept) {
    SceneHolder h(60);
    ErrorRecorder errors;
    iRigidBody* b = CreateRigidBody(nullptr);
    RBDynamics& d = b->getDynamics();
    h.run(100);
    RBDynamics good = d;
    auto restored = [&] {
        EXPECT_EQ(d.position, good.position);
        EXPECT_EQ(d.mass, good.mass);
        EXPECT_EQ(d.orientation, good.orientation);
    };
    d.position.x = NAN;
    h.scene->update(h.now += 1); // no step yet: validation happens in steps
    h.scene->update(h.now += 16);
    EXPECT_EQ(errors.count(), 1u);
    EXPECT_TRUE(d.position.isFinite());
    good = d;

    d.mass = 0.0f;
    h.run(17);
    EXPECT_EQ(errors.count(), 2u);
    EXPECT_EQ(d.mass, 1.0f);
    d.mass = -INFINITE_MASS;
    h.run(17);
    EXPECT_EQ(errors.count(), 3u);
    EXPECT_EQ(d.mass, 1.0f);

    d.orientation = Matrix(2.0f); // scaled: refused
    h.run(17);
    EXPECT_EQ(errors.count(), 4u);
    EXPECT_TRUE(isRotation(d.orientation));
    d.orientation = rotatey(0.3f) * Matrix(1.001f); // 1e-3 drift: cleaned silently
    h.run(17);
    EXPECT_EQ(errors.count(), 4u);
    EXPECT_TRUE(isRotation(d.orientation, 1e-5f));
    EXPECT_NEAR(d.orientation.direction('x').z, -std::sin(0.3f), 1e-4f);

    d.getInertiaTensor() = Matrix(Vector(1, -1, 1)); // through the reference: not positive definite
    h.run(17);
    EXPECT_EQ(errors.count(), 5u);
    EXPECT_EQ(d.getInertiaTensor(), good.getInertiaTensor());

    good = d;
    d.setInertiaTensor(Matrix(Vector(1, NAN, 1)));
    d.setInverseInertiaTensor(Matrix(Vector(1, 0, 1)));
    EXPECT_EQ(errors.count(), 7u);
    EXPECT_EQ(d.getInertiaTensor(), good.getInertiaTensor());
    d.ApplyImpulse(Vector(INFINITE_MASS, 0, 0), Vector());
    EXPECT_EQ(errors.count(), 8u);
    EXPECT_EQ(d.velocity, good.velocity);
    RBDynamics bad = d;
    bad.mass = -1.0f;
    b->setDynamics(bad);
    EXPECT_EQ(errors.count(), 9u);
    EXPECT_EQ(d.mass, 1.0f);
    restored();
}

// Absurd forces that overflow to Inf during the step: the step is undone for that body only.
TEST(Dynamics, AStepThatOverflowsIsUndone) {
    SceneHolder h(60);
    ErrorRecorder errors;
    iRigidBody* wild = CreateRigidBody(nullptr);
    iRigidBody* calm = CreateRigidBody(nullptr);
    wild->getDynamics().mass = 1e-3f;
    wild->getDynamics().velocity = Vector(3e38f, 0, 0);
    wild->getDynamics().force = Vector(3e38f, 0, 0); // a = 3e41: overflows to Inf
    h.run(17);
    EXPECT_GE(errors.count(), 1u);
    EXPECT_TRUE(wild->getDynamics().position.isFinite());
    EXPECT_TRUE(wild->getDynamics().velocity.isFinite());
    EXPECT_LT(calm->getDynamics().velocity.y, 0.0f);
}

// A step undone for a body puts back the bodies attached to it (their poses are relative to it): the pose
// each ends the step with is the one after the undo, so the next step does not take them for teleported by
// the game (a teleport is never swept). The attached body is listed first, ahead of the one undone.
TEST(Dynamics, AStepUndoneForABodyLeavesTheBodiesAttachedToItUnteleported) {
    SceneHolder h(60);
    ErrorRecorder errors;
    iRigidBody* rider = CreateRigidBody(nullptr);
    iRigidBody* wild = CreateRigidBody(nullptr);
    rider->getDynamics().position = Vector(0, 1, 0);
    rider->getDynamics().attachTo(&wild->getDynamics());
    wild->getDynamics().mass = 1e-3f;
    wild->getDynamics().velocity = Vector(3e38f, 0, 0);
    wild->getDynamics().force = Vector(3e38f, 0, 0); // overflows to Inf in every step, which is undone
    h.run(17); // the first step: a new body's placed pose counts as one teleport, undo or not
    const unsigned teleports = rider->getDynamics().teleports;
    h.run(50);
    EXPECT_GE(errors.count(), 1u);
    EXPECT_TRUE(wild->getDynamics().position.isFinite());
    EXPECT_TRUE(rider->getDynamics().getWorldPosition().isFinite());
    EXPECT_EQ(rider->getDynamics().teleports, teleports);
}

// Setting either tensor sets the other to its inverse.
TEST(Dynamics, InertiaTensorAndItsInverseStayConsistent) {
    RBDynamics d;
    d.setInertiaTensor(getBoxInertiaTensor(3.0f, Vector(0.5f, 1.0f, 2.0f)));
    Matrix product = d.getInertiaTensor() * d.getInverseInertiaTensor();
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(product(r, c), r == c ? 1.0f : 0.0f, 1e-6f);
    d.setInverseInertiaTensor(Matrix(Vector(0.5f, 0.25f, 0.125f)));
    EXPECT_NEAR(d.getInertiaTensor().m11, 2.0f, 1e-6f);
    EXPECT_NEAR(d.getInertiaTensor().m22, 4.0f, 1e-6f);
    EXPECT_NEAR(d.getInertiaTensor().m33, 8.0f, 1e-6f);
}
