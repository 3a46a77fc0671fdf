// SpringTest.cpp - springs as soft constraints through whole scenes: the period 2 pi sqrt(m / k) where the
// step resolves it, energy never gained, a stiff spring bounded, the force limit.
#include "JointTestSupport.h"
#include "iPhysicsSceneSettings.h"
#include "iSpring.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace joint_test;

namespace {
// A 1 kg body on a spring of stiffness k to a world anchor at the origin, weightless, let go 0.1 m out.
struct Oscillator {
    StepScene s;
    iRigidBody* body;
    iSpring* spring;
    Oscillator(int hz, float k, float c = 0.0f) : s(hz) {
        settingsOf(s.scene())->setGravity(Vector(0, 0, 0));
        body = sphereBody(Vector(1.1f, 0, 0), 1.0f, 0.05f);
        spring = CreateSpring(body, nullptr, Vector(1.1f, 0, 0), Vector(0, 0, 0), 1.0f, k, c);
    }
    ~Oscillator() {
        spring->Delete();
        body->Delete();
    }
    double energy(float k) const {
        const RBDynamics& d = body->getDynamics();
        const double stretch = d.position.length() - 1.0;
        return 0.5 * d.velocity.lengthSquared() + 0.5 * k * stretch * stretch;
    }
};
} // namespace

// Undamped, where the step resolves it (omega dt = 0.5 at 60 Hz, k = 900 N/m): the period is
// 2 pi sqrt(m / k) within 1 %, and the energy never grows.
TEST(Spring, ThePeriodIsTwoPiRootMOverKWhereTheStepResolvesIt) {
    const float k = 900.0f; // omega = 30 rad/s
    Oscillator o(60, k);
    ASSERT_NE(o.spring, nullptr);
    std::vector<double> x;
    double last = o.energy(k), first = last;
    bool gained = false;
    o.s.recorder.fn = [&] {
        x.push_back(o.body->getDynamics().position.x - 1.0);
        const double e = o.energy(k);
        gained = gained || e > last * (1 + 1e-5);
        last = e;
    };
    o.s.seconds(3);
    const double period = meanPeriod(x, 1.0 / 60), truth = 2 * M_PI / 30.0;
    EXPECT_NEAR(period / truth, 1.0, 0.01) << period;
    EXPECT_FALSE(gained);
    EXPECT_LT(last, first);
}

// 10^6 N/m on 1 kg at 60 Hz (omega dt = 16.7): the spring seed 000's engine could not hold stays bounded
// for 10^5 steps and only loses energy.
TEST(Spring, AStiffSpringStaysBoundedAndLosesEnergy) {
    const float k = 1e6f;
    Oscillator o(60, k);
    ASSERT_NE(o.spring, nullptr);
    double last = o.energy(k), first = last;
    bool gained = false;
    float farthest = 0;
    o.s.recorder.fn = [&] {
        const double e = o.energy(k);
        gained = gained || e > last * (1 + 1e-5) + 1e-9;
        last = e;
        farthest = std::max(farthest, o.body->getDynamics().position.length());
    };
    o.s.step(100000);
    EXPECT_FALSE(gained);
    EXPECT_LE(last, first);
    EXPECT_LT(farthest, 1.1001f);
}
