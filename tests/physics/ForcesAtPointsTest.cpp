// ForcesAtPointsTest.cpp - forces where they act (RBDynamics::ApplyForce) and angular drag
// (RBDynamics::angularDrag), through whole scenes, against the impulse-momentum theorem and the exponential
// decay dL/dt = -c L.
#include "PhysicsTestSupport.h"
#include "iFixedUpdater.h"
#include "iPhysicsSceneHooks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using physics_test::ErrorRecorder;
using physics_test::SceneHolder;

namespace {

// Calls fn at the start of every step (what a game's thruster does).
struct EveryStep final : iFixedUpdater {
    std::function<void()> fn;
    void fixedUpdate(iPhysicsScene*, float) override { fn(); }
};

// A weightless scene at 60 Hz (forces alone move the bodies).
struct Weightless {
    SceneHolder h{60};
    Weightless() { settingsOf(h.scene)->setGravity(Vector(0, 0, 0)); }
};

} // namespace

// F = (0, 2, 0) N at 1 m from the centre along x, on a 3 kg body, for 1 s: the body gains F t / m = 2/3 m/s
// and the angular momentum (r x F) t = (0, 0, 2) kg m^2/s, whatever it turned through meanwhile (the point
// is held 1 m from the centre along world x each step, so the moment is constant).
TEST(ForcesAtPoints, AnOffCentreForceGivesTheMomentumAndSpinTheTheoremSays) {
    Weightless w;
    iRigidBody* b = CreateRigidBody(nullptr);
    b->getDynamics().mass = 3.0f;
    b->getDynamics().position = Vector(5, 0, 0);
    EveryStep thruster;
    thruster.fn = [&] {
        RBDynamics& d = b->getDynamics();
        d.ApplyForce(Vector(0, 2, 0), d.getWorldPosition() + Vector(1, 0, 0));
    };
    ASSERT_TRUE(hooksOf(w.h.scene)->addFixedUpdater(&thruster));
    w.h.run(1000);
    const RBDynamics& d = b->getDynamics();
    EXPECT_NEAR(d.velocity.y, 2.0f / 3.0f, 1e-5f);
    EXPECT_NEAR(d.velocity.x, 0.0f, 1e-6f);
    EXPECT_NEAR(d.angularMomentum.z, 2.0f, 1e-5f);
    EXPECT_NEAR(d.angularMomentum.x, 0.0f, 1e-6f);
    EXPECT_NEAR(d.angularMomentum.y, 0.0f, 1e-6f);
    hooksOf(w.h.scene)->removeFixedUpdater(&thruster);
}

// Through the centre of mass: no spin at all.
TEST(ForcesAtPoints, AForceThroughTheCentreOfMassDoesNotTurn) {
    Weightless w;
    iRigidBody* b = CreateRigidBody(nullptr);
    b->getDynamics().com = Vector(0.3f, 0, 0); // the centre of mass off the frame's origin
    EveryStep thruster;
    thruster.fn = [&] {
        RBDynamics& d = b->getDynamics();
        d.ApplyForce(Vector(0, 0, 4), d.getWorldPosition());
    };
    ASSERT_TRUE(hooksOf(w.h.scene)->addFixedUpdater(&thruster));
    w.h.run(500);
    EXPECT_NEAR(b->getDynamics().velocity.z, 2.0f, 1e-5f); // 4 N on 1 kg for 0.5 s
    EXPECT_EQ(b->getDynamics().angularVelocity, Vector());
    hooksOf(w.h.scene)->removeFixedUpdater(&thruster);
}

// Two 1 kg bodies welded 2 m apart: pushing the child at the pair's middle moves the pair without turning it
// (the moment is taken about the composite's centre of mass, not the child's).
TEST(ForcesAtPoints, OnAnAttachedBodyTheMomentIsAboutTheCompositesCentre) {
    Weightless w;
    iRigidBody* root = CreateRigidBody(nullptr);
    iRigidBody* child = CreateRigidBody(nullptr);
    child->getDynamics().position = Vector(2, 0, 0);
    child->getDynamics().attachTo(&root->getDynamics());
    EveryStep thruster;
    thruster.fn = [&] { child->getDynamics().ApplyForce(Vector(0, 1, 0), Vector(1, 0, 0)); };
    ASSERT_TRUE(hooksOf(w.h.scene)->addFixedUpdater(&thruster));
    w.h.run(1000);
    EXPECT_NEAR(root->getDynamics().velocity.y, 0.5f, 1e-5f); // 1 N on 2 kg for 1 s
    EXPECT_NEAR(root->getDynamics().angularVelocity.z, 0.0f, 1e-5f);
    hooksOf(w.h.scene)->removeFixedUpdater(&thruster);
}

// A sphere spun at 10 rad/s with angularDrag 2/s: w(t) = 10 e^(-2t), at every step rate (the decay is taken
// exactly over each step); its axis stays put.
TEST(ForcesAtPoints, AngularDragDecaysTheSpinExponentially) {
    for (int hz : {30, 60, 240}) {
        SceneHolder h(hz);
        settingsOf(h.scene)->setGravity(Vector(0, 0, 0));
        iRigidBody* b = CreateRigidBody(nullptr);
        b->getDynamics().angularDrag = 2.0f;
        b->getDynamics().angularVelocity = Vector(0, 10, 0);
        h.run(1000);
        EXPECT_NEAR(b->getDynamics().angularVelocity.y, 10.0f * std::exp(-2.0f), 1e-4f) << hz << " Hz";
        EXPECT_EQ(b->getDynamics().angularVelocity.x, 0.0f);
    }
}

// A drag far beyond what one step resolves (c dt = 10^4) stops the spin without overshooting or blowing up;
// the linear motion is untouched.
TEST(ForcesAtPoints, AHugeAngularDragStopsTheSpinWithoutOvershoot) {
    Weightless w;
    iRigidBody* b = CreateRigidBody(nullptr);
    b->getDynamics().angularDrag = 6e5f;
    b->getDynamics().angularVelocity = Vector(3, 0, 0);
    b->getDynamics().velocity = Vector(1, 0, 0);
    w.h.run(100);
    EXPECT_GE(b->getDynamics().angularVelocity.x, 0.0f);
    EXPECT_LT(b->getDynamics().angularVelocity.x, 1e-6f);
    EXPECT_FLOAT_EQ(b->getDynamics().velocity.x, 1.0f);
}

// Bad input: a non-finite force or point is refused with error() and changes nothing; a negative or NaN
// angular drag is refused by the step's validation and the body keeps its last valid state.
TEST(ForcesAtPoints, BadInputIsRefused) {
    Weightless w;
    iRigidBody* b = CreateRigidBody(nullptr);
    ErrorRecorder errors;
    b->getDynamics().ApplyForce(Vector(NAN, 0, 0), Vector());
    b->getDynamics().ApplyForce(Vector(1, 0, 0), Vector(0, INFINITY, 0));
    EXPECT_EQ(errors.count(), 2u);
    EXPECT_EQ(b->getDynamics().temporalForce, Vector());
    EXPECT_EQ(b->getDynamics().temporalTorque, Vector());
    for (float bad : {-1.0f, NAN}) {
        b->getDynamics().angularVelocity = Vector(0, 1, 0);
        w.h.run(20);
        b->getDynamics().angularDrag = bad;
        const unsigned long before = errors.count();
        w.h.run(20);
        EXPECT_GT(errors.count(), before);
        EXPECT_EQ(b->getDynamics().angularDrag, 0.0f); // the last valid state
        EXPECT_TRUE(std::isfinite(b->getDynamics().angularVelocity.y));
    }
}
