// PendulumTest.cpp - pendulums and chains on joints through whole scenes: the small-angle period
// 2 pi sqrt(L / g), a 20-link hinge chain's stretch, and energy that a rigid joint must not add (a heavy load
// on a light chain: TetherTest.cpp).
#include "JointTestSupport.h"
#include "iBallJoint.h"
#include "iDistanceJoint.h"
#include "iHingeJoint.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace joint_test;

// A point-like bob on a 1 m rod (distance joint) to the world, let go 0.05 rad out: the period of x is
// 2 pi sqrt(L / g) = 2.006 s (the small-angle error at 0.05 rad is 0.016 %); within 2 % at 60 and 240 Hz.
TEST(Pendulum, TheSmallAnglePeriodIsTwoPiRootLOverG) {
    for (int hz : {60, 240}) {
        StepScene s(hz);
        const float L = 1.0f, angle = 0.05f;
        iRigidBody* bob = sphereBody(Vector(L * std::sin(angle), -L * std::cos(angle), 0), 1.0f, 0.05f);
        iDistanceJoint* rod = CreateDistanceJoint(bob, nullptr, bob->getDynamics().position, Vector(0, 0, 0));
        ASSERT_NE(rod, nullptr);
        std::vector<double> x;
        s.recorder.fn = [&] { x.push_back(bob->getDynamics().position.x); };
        s.seconds(10);
        const double period = meanPeriod(x, 1.0 / hz), truth = 2 * M_PI * std::sqrt(L / kG);
        EXPECT_NEAR(period / truth, 1.0, 0.02) << hz << " Hz: " << period << " s";
        RecordProperty("period_over_truth_" + std::to_string(hz) + "Hz", std::to_string(period / truth));
        // the rod neither stretches nor shortens
        EXPECT_NEAR(rod->getLength(), L, 0.001f * L);
        rod->Delete();
        bob->Delete();
    }
}

// 20 boxes on hinges hang from the world, each 0.1 m long: the chain is 2 m long within 1 % at every step,
// at the default settings, from the moment it is let go (all 20 links start without impulses), hanging
// still, and swinging (the last link kicked sideways at 0.5 m/s).
TEST(HingeChain, TwentyLinksHangWithUnderOnePercentStretch) {
    for (float kick : {0.0f, 0.5f}) {
        StepScene s(60);
        const int links = 20;
        const float half = 0.05f;
        std::vector<iHingeJoint*> hinge;
        const std::vector<iRigidBody*> body =
            hangChain(links, half, 0.02f, [&](iRigidBody* b, iRigidBody* above, const Vector& anchor) {
                hinge.push_back(CreateHingeJoint(b, above, anchor, Vector(0, 0, 1)));
                EXPECT_NE(hinge.back(), nullptr);
            });
        // a little sideways kick so that the chain swings (and must still not stretch)
        body.back()->getDynamics().velocity = Vector(kick, 0, 0);
        const float length = 2 * half * links;
        float worst = 0;
        s.recorder.fn = [&] {
            // the chain's end: the last link's bottom
            const RBDynamics& d = body.back()->getDynamics();
            const Vector bottom = d.position + Vector(0, -half, 0) * d.orientation;
            worst = std::max(worst, bottom.length() / length - 1.0f);
        };
        s.seconds(5);
        EXPECT_LT(worst, 0.01f) << "kick " << kick << ": stretch " << worst * 100 << " %";
        RecordProperty(kick > 0 ? "stretch_swinging" : "stretch_hanging", std::to_string(worst));
        for (iHingeJoint* j : hinge) j->Delete();
        for (iRigidBody* b : body) b->Delete();
    }
}
