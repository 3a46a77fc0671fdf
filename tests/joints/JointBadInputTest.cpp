// JointBadInputTest.cpp - every joint factory and setter refuses bad input: nullptr (with one error()) from
// a factory given no body A, a body joined to itself, a NaN anchor, a zero axis or a game's own iRigidBody;
// false (with one error(), the old value kept) from a setter given a value outside its documented range.
#include "JointTestSupport.h"
#include "iBallJoint.h"
#include "iDistanceJoint.h"
#include "iFixedJoint.h"
#include "iHingeJoint.h"
#include "iSliderJoint.h"
#include "iSpring.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

using namespace joint_test;

namespace {

const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

// A game's own body (the collision-only route): an RBDynamics and nothing of the simulator's.
class GameBody final : public iRigidBody {
public:
    iRigidBody* clone() const override { return nullptr; }
    void attach(iFrame*) override {}
    void attachListener(iCollisionListener*) override {}
    void detachListener(const iCollisionListener*) override {}
    void restore(int) override {}
    std::vector<iCollisionListener*>& getListeners() override { return m_listeners; }
    iFrame* getFrame() override { return nullptr; }
    RBDynamics& getDynamics() override { return m_dynamics; }
    const RBDynamics& getDynamics() const override { return m_dynamics; }
    void setDynamics(const RBDynamics& d) override { m_dynamics = d; }
    void reset(int) override {}
    void suspend() const override {}
    void release() const override {}
    void Delete() const override {}

private:
    RBDynamics m_dynamics;
    std::vector<iCollisionListener*> m_listeners;
};

// Every factory as one signature: a, b, anchor, axis (the distance joint and spring take the axis as the
// second anchor's offset: a zero axis is no error for them, so they are skipped in that case).
using Factory = std::function<iJoint*(iRigidBody*, iRigidBody*, const Vector&, const Vector&)>;
struct Named {
    const char* name;
    Factory make;
    bool hasAxis;
};
std::vector<Named> factories() {
    return {
        {"ball",
         [](iRigidBody* a, iRigidBody* b, const Vector& p, const Vector& x) -> iJoint* {
             return CreateBallJoint(a, b, p, x);
         },
         true},
        {"hinge",
         [](iRigidBody* a, iRigidBody* b, const Vector& p, const Vector& x) -> iJoint* {
             return CreateHingeJoint(a, b, p, x);
         },
         true},
        {"slider",
         [](iRigidBody* a, iRigidBody* b, const Vector& p, const Vector& x) -> iJoint* {
             return CreateSliderJoint(a, b, p, x);
         },
         true},
        {"fixed",
         [](iRigidBody* a, iRigidBody* b, const Vector& p, const Vector&) -> iJoint* {
             return CreateFixedJoint(a, b, p);
         },
         false},
        {"distance",
         [](iRigidBody* a, iRigidBody* b, const Vector& p, const Vector& x) -> iJoint* {
             return CreateDistanceJoint(a, b, p, p + x);
         },
         false},
        {"spring",
         [](iRigidBody* a, iRigidBody* b, const Vector& p, const Vector& x) -> iJoint* {
             return CreateSpring(a, b, p, p + x, 1.0f, 10.0f);
         },
         false},
    };
}

} // namespace

TEST(JointBadInput, EveryFactoryRefusesWithOneError) {
    StepScene s(60);
    iRigidBody* a = sphereBody(Vector(0, 0, 0), 1.0f, 0.1f);
    iRigidBody* b = sphereBody(Vector(1, 0, 0), 1.0f, 0.1f);
    GameBody game;
    const Vector p(0.5f, 0, 0), x(0, 0, 1);
    for (const Named& f : factories()) {
        struct Case {
            const char* what;
            iRigidBody *a, *b;
            Vector p, x;
        };
        std::vector<Case> cases = {{"no body A", nullptr, b, p, x},
                                   {"a == b", a, a, p, x},
                                   {"NaN anchor", a, b, Vector(kNaN, 0, 0), x},
                                   {"Inf anchor", a, nullptr, Vector(0, kInf, 0), x},
                                   {"game's body A", &game, b, p, x},
                                   {"game's body B", a, &game, p, x}};
        if (f.hasAxis) {
            cases.push_back({"zero axis", a, b, p, Vector(0, 0, 0)});
            cases.push_back({"NaN axis", a, b, p, Vector(0, kNaN, 1)});
        }
        for (const Case& c : cases) {
            ErrorRecorder errors;
            EXPECT_EQ(f.make(c.a, c.b, c.p, c.x), nullptr) << f.name << ": " << c.what;
            EXPECT_EQ(errors.count(), 1u) << f.name << ": " << c.what;
        }
        // and good input is accepted, silently
        ErrorRecorder errors;
        iJoint* j = f.make(a, b, p, x);
        EXPECT_NE(j, nullptr) << f.name;
        EXPECT_EQ(errors.count(), 0u) << f.name;
        if (j) j->Delete();
    }
}

namespace {
// Calls set (which must refuse) and expects false, exactly one error() and the getter's value unchanged.
void expectRefused(
    const char* what, const std::function<bool()>& set,
    const std::function<float()>& get = [] { return 0.0f; }) {
    const float before = get();
    ErrorRecorder errors;
    EXPECT_FALSE(set()) << what;
    EXPECT_EQ(errors.count(), 1u) << what;
    const float after = get();
    EXPECT_TRUE(after == before || (std::isnan(after) && std::isnan(before))) << what;
}
} // namespace

TEST(JointBadInput, EverySetterRefusesOutOfRangeValues) {
    StepScene s(60);
    iRigidBody* a = sphereBody(Vector(0, 0, 0), 1.0f, 0.1f);
    iBallJoint* ball = CreateBallJoint(a, nullptr, Vector(0, 1, 0));
    iHingeJoint* hinge = CreateHingeJoint(a, nullptr, Vector(0, 1, 0));
    iSliderJoint* slider = CreateSliderJoint(a, nullptr, Vector(0, 1, 0));
    iDistanceJoint* distance = CreateDistanceJoint(a, nullptr, Vector(0, 0, 0), Vector(0, 1, 0));
    iSpring* spring = CreateSpring(a, nullptr, Vector(0, 0, 0), Vector(0, 1, 0), 1.0f, 10.0f);
    ASSERT_TRUE(ball && hinge && slider && distance && spring);
    for (iJoint* j : std::vector<iJoint*>{ball, hinge, slider, distance, spring})
        for (float v : {0.0f, -1.0f, kNaN}) {
            expectRefused("setBreakForce", [&] { return j->setBreakForce(v); });
            expectRefused("setBreakTorque", [&] { return j->setBreakTorque(v); });
        }
    ASSERT_TRUE(ball->setConeLimit(1.0f));
    for (float v : {0.0f, -1.0f, kNaN})
        expectRefused(
            "setConeLimit", [&] { return ball->setConeLimit(v); }, [&] { return ball->getConeLimit(); });
    expectRefused("setTwistLimits 1 > 0", [&] { return ball->setTwistLimits(1, 0); });
    expectRefused("setTwistLimits -4", [&] { return ball->setTwistLimits(-4, 0); });
    expectRefused("setTwistLimits NaN", [&] { return ball->setTwistLimits(kNaN, 0); });
    expectRefused("hinge setLimits 1 > 0", [&] { return hinge->setLimits(1, 0); });
    expectRefused("hinge setLimits pi", [&] { return hinge->setLimits(0, 3.1416f); });
    expectRefused("hinge setLimits NaN", [&] { return hinge->setLimits(0, kNaN); });
    expectRefused("hinge setMotor NaN speed", [&] { return hinge->setMotor(kNaN, 1); });
    expectRefused("hinge setMotor -1", [&] { return hinge->setMotor(1, -1); });
    expectRefused("hinge setMotor Inf", [&] { return hinge->setMotor(1, kInf); });
    expectRefused("slider setLimits 1 > 0", [&] { return slider->setLimits(1, 0); });
    expectRefused("slider setLimits NaN", [&] { return slider->setLimits(kNaN, 1); });
    expectRefused("slider setLimits Inf", [&] { return slider->setLimits(0, kInf); });
    expectRefused("slider setMotor Inf speed", [&] { return slider->setMotor(kInf, 1); });
    expectRefused("slider setMotor -1", [&] { return slider->setMotor(1, -1); });
    expectRefused("slider setMotor NaN", [&] { return slider->setMotor(1, kNaN); });
    auto minLength = [&] { return distance->getMinLength(); };
    auto maxLength = [&] { return distance->getMaxLength(); };
    for (auto get : {std::function<float()>(minLength), std::function<float()>(maxLength)}) {
        expectRefused(
            "distance setLimits -1", [&] { return distance->setLimits(-1, 1); }, get);
        expectRefused(
            "distance setLimits 2 > 1", [&] { return distance->setLimits(2, 1); }, get);
        expectRefused(
            "distance setLimits Inf", [&] { return distance->setLimits(0, kInf); }, get);
        expectRefused(
            "distance setLimits NaN", [&] { return distance->setLimits(kNaN, 1); }, get);
    }
    auto rest = [&] { return spring->getRestLength(); };
    expectRefused(
        "setRestLength -1", [&] { return spring->setRestLength(-1); }, rest);
    expectRefused(
        "setRestLength NaN", [&] { return spring->setRestLength(kNaN); }, rest);
    expectRefused(
        "setRestLength Inf", [&] { return spring->setRestLength(kInf); }, rest);
    auto k = [&] { return spring->getStiffness(); };
    expectRefused(
        "setStiffness -1", [&] { return spring->setStiffness(-1); }, k);
    expectRefused(
        "setStiffness Inf", [&] { return spring->setStiffness(kInf); }, k);
    auto c = [&] { return spring->getDamping(); };
    expectRefused(
        "setDamping -1", [&] { return spring->setDamping(-1); }, c);
    expectRefused(
        "setDamping NaN", [&] { return spring->setDamping(kNaN); }, c);
    expectRefused(
        "setFrequency 0 Hz", [&] { return spring->setFrequency(0, 1); }, k);
    expectRefused(
        "setFrequency ratio -1", [&] { return spring->setFrequency(1, -1); }, k);
    expectRefused(
        "setFrequency NaN", [&] { return spring->setFrequency(kNaN, 1); }, k);
    expectRefused("setMaxForce 0", [&] { return spring->setMaxForce(0); });
    expectRefused("setMaxForce NaN", [&] { return spring->setMaxForce(kNaN); });
    for (iJoint* j : std::vector<iJoint*>{ball, hinge, slider, distance, spring}) j->Delete();
}
