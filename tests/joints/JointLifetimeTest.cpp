// JointLifetimeTest.cpp - joints as objects with a lifetime through whole scenes: breaking (the listener told
// once, the body then in free fall), deletion from a listener or an updater, bodies killed or deleted under
// a joint, any deletion order, and a jointed chain sleeping and waking as one. CI runs these under ASan and
// UBSan, which is what proves the deletions safe.
#include "JointTestSupport.h"
#include "iBallJoint.h"
#include "iDistanceJoint.h"
#include "iFixedJoint.h"
#include "iHingeJoint.h"
#include "iLifetime.h"
#include "iRigidBodyMotion.h"

#include <gtest/gtest.h>

#include <functional>
#include <vector>

using namespace joint_test;

namespace {

const float kH = 1.0f / 60;

// Counts jointBroken calls and runs an optional action in them.
struct BreakLog final : iJointListener {
    std::vector<iJoint*> broken;
    std::function<void(iJoint*)> then;
    void jointBroken(iJoint* j) override {
        broken.push_back(j);
        if (then) then(j);
    }
};

// Runs fn at the start of the n-th step from now (1-based) only.
struct AtStep final : iFixedUpdater {
    int step = 0, at = 0;
    std::function<void()> fn;
    void fixedUpdate(iPhysicsScene*, float) override {
        if (++step == at) fn();
    }
};

// Steps one at a time and checks that every step from the next on adds exactly g h of downward speed
// (semi-implicit Euler's free fall: no joint acts).
void expectFreeFall(StepScene& s, const iRigidBody* b, int steps) {
    for (int i = 0; i < steps; ++i) {
        const float before = b->getDynamics().velocity.y;
        s.step();
        ASSERT_NEAR(b->getDynamics().velocity.y - before, -kG * kH, 1e-4f) << "step " << i;
    }
}

} // namespace

// A 2 kg ball on a rod (load m g = 19.6 N): a break force of 10 N breaks it in the first step, the listener
// is told exactly once with that joint, and the ball then falls freely; a break force of 30 N holds it.
TEST(JointBreak, BelowTheLoadItBreaksOnceAndTheBodyFallsAboveItHolds) {
    for (float limit : {10.0f, 30.0f}) {
        StepScene s(60);
        iRigidBody* ball = sphereBody(Vector(0, -1, 0), 2.0f, 0.1f);
        iDistanceJoint* rod = CreateDistanceJoint(ball, nullptr, Vector(0, -1, 0), Vector(0, 0, 0));
        ASSERT_NE(rod, nullptr);
        ASSERT_TRUE(rod->setBreakForce(limit));
        BreakLog log;
        rod->setListener(&log);
        s.step();
        if (limit < 2 * kG) {
            ASSERT_EQ(log.broken.size(), 1u);
            EXPECT_EQ(log.broken[0], rod);
            EXPECT_TRUE(rod->isBroken());
            EXPECT_FALSE(rod->isActive());
            expectFreeFall(s, ball, 60);
            EXPECT_EQ(log.broken.size(), 1u); // told once only
        } else {
            s.seconds(2);
            EXPECT_TRUE(log.broken.empty());
            EXPECT_FALSE(rod->isBroken());
            EXPECT_NEAR(rod->getLength(), 1.0f, 1e-3f);
        }
        rod->Delete();
    }
}

// The listener deletes the joint it is told about (the joint must not be touched after); the scene steps on
// and the body falls freely. Torque breaking too: a cantilever weld (m g L = 9.81 N m) with a 5 N m limit.
TEST(JointBreak, DeletingTheJointInsideJointBrokenIsSafe) {
    StepScene s(60);
    iRigidBody* box = boxBody(Vector(1, 0, 0), 1.0f, 0.1f, 0.1f, 0.1f);
    iFixedJoint* weld = CreateFixedJoint(box, nullptr, Vector(0, 0, 0));
    ASSERT_NE(weld, nullptr);
    ASSERT_TRUE(weld->setBreakTorque(5.0f));
    BreakLog log;
    log.then = [](iJoint* j) { j->Delete(); };
    weld->setListener(&log);
    s.step();
    ASSERT_EQ(log.broken.size(), 1u);
    expectFreeFall(s, box, 30);
    EXPECT_EQ(log.broken.size(), 1u);
}

// A joint deleted from a fixed updater in step 5: it stops acting at once (that step is already free fall)
// and is freed when the update ends.
TEST(JointDelete, FromAFixedUpdaterDuringAStepIsSafe) {
    StepScene s(60);
    iRigidBody* ball = sphereBody(Vector(0, -1, 0), 1.0f, 0.1f);
    iBallJoint* joint = CreateBallJoint(ball, nullptr, Vector(0, 0, 0));
    ASSERT_NE(joint, nullptr);
    AtStep killer;
    killer.at = 5;
    killer.fn = [&] { joint->Delete(); };
    ASSERT_TRUE(hooksOf(s.scene())->addFixedUpdater(&killer));
    s.step(4);
    EXPECT_NEAR(ball->getDynamics().position.y, -1.0f, 1e-3f); // held until then
    expectFreeFall(s, ball, 30);
    hooksOf(s.scene())->removeFixedUpdater(&killer);
}

// A ball hangs from a box welded to the world. The box is killed from a fixed updater in step 10: at the end
// of that step the rod lets go (inactive, getBodyB nullptr, getBodyA still the ball), the ball falls freely
// from then on, and the killed box stays a valid object the test still reads.
TEST(JointKill, AKilledBodyIsLetGoAndTheOtherFallsFreely) {
    StepScene s(60);
    iRigidBody* box = boxBody(Vector(0, 0, 0), 5.0f, 0.1f, 0.1f, 0.1f);
    iRigidBody* ball = sphereBody(Vector(0, -1, 0), 1.0f, 0.1f);
    iFixedJoint* weld = CreateFixedJoint(box, nullptr, Vector(0, 0, 0));
    iDistanceJoint* rod = CreateDistanceJoint(ball, box, Vector(0, -1, 0), Vector(0, 0, 0));
    ASSERT_TRUE(weld && rod);
    AtStep killer;
    killer.at = 10;
    killer.fn = [&] { lifetimeOf(box)->kill(); };
    ASSERT_TRUE(hooksOf(s.scene())->addFixedUpdater(&killer));
    s.step(9);
    EXPECT_TRUE(rod->isActive());
    EXPECT_NEAR(ball->getDynamics().position.y, -1.0f, 1e-3f);
    s.step();
    EXPECT_FALSE(rod->isActive());
    EXPECT_EQ(rod->getBodyA(), ball);
    EXPECT_EQ(rod->getBodyB(), nullptr);
    EXPECT_FALSE(weld->isActive());
    EXPECT_EQ(weld->getBodyA(), nullptr);
    EXPECT_FALSE(lifetimeOf(box)->isAlive());
    EXPECT_NEAR(box->getDynamics().position.y, 0.0f, 1e-3f); // still readable, where it was
    expectFreeFall(s, ball, 60);
    hooksOf(s.scene())->removeFixedUpdater(&killer);
    rod->Delete();
    weld->Delete();
    box->Delete();
}

// Deleting a jointed body between steps makes its joints let go; the joint deleted after both its bodies,
// and bodies deleted after their joint, are both safe (ASan).
TEST(JointDelete, AnyOrderOfJointAndBodyDeletionIsSafe) {
    StepScene s(60);
    iRigidBody* a = sphereBody(Vector(0, 0, 0), 1.0f, 0.1f);
    iRigidBody* b = sphereBody(Vector(0, -1, 0), 1.0f, 0.1f);
    iHingeJoint* hinge = CreateHingeJoint(a, b, Vector(0, -0.5f, 0));
    iFixedJoint* weld = CreateFixedJoint(a, nullptr, Vector(0, 0, 0));
    ASSERT_TRUE(hinge && weld);
    s.step(10);
    b->Delete();
    EXPECT_FALSE(hinge->isActive());
    EXPECT_EQ(hinge->getBodyA(), a);
    EXPECT_EQ(hinge->getBodyB(), nullptr);
    EXPECT_TRUE(weld->isActive());
    s.step(10);
    a->Delete(); // both of the hinge's bodies gone: the hinge is deleted after them
    EXPECT_EQ(hinge->getBodyA(), nullptr);
    hinge->Delete();
    weld->Delete();
    s.step(10);
    // and a joint deleted before its bodies
    iRigidBody* c = sphereBody(Vector(0, 0, 0), 1.0f, 0.1f);
    iBallJoint* ball = CreateBallJoint(c, nullptr, Vector(0, 1, 0));
    ASSERT_NE(ball, nullptr);
    s.step(10);
    ball->Delete();
    s.step(10);
    c->Delete();
    s.step(10);
}

// A 5-link hinge chain let go hanging from the world: it comes to rest (the joints start with no impulses,
// so it settles first) and every link falls asleep in the same step, within 20 s; waking one link (wake(), or
// writing its velocity) wakes every link by the end of the next step.
TEST(JointSleep, AChainSleepsAndWakesAsOne) {
    for (int how = 0; how < 2; ++how) {
        StepScene s(60);
        std::vector<iRigidBody*> link;
        std::vector<iHingeJoint*> hinge;
        iRigidBody* above = nullptr;
        for (int i = 0; i < 5; ++i) {
            iRigidBody* b = boxBody(Vector(0, -0.1f - 0.2f * float(i), 0), 0.5f, 0.02f, 0.1f, 0.02f);
            hinge.push_back(CreateHingeJoint(b, above, Vector(0, -0.2f * float(i), 0)));
            ASSERT_NE(hinge.back(), nullptr);
            link.push_back(b);
            above = b;
        }
        int asleep = -1;
        bool split = false;
        for (int n = 0; n < 60 * 20 && asleep < 0; ++n) {
            s.step();
            int count = 0;
            for (iRigidBody* b : link) count += b->getDynamics().sleeping ? 1 : 0;
            split = split || (count != 0 && count != 5);
            if (count == 5) asleep = n;
        }
        ASSERT_GE(asleep, 0) << "the chain never fell asleep";
        EXPECT_FALSE(split) << "some links slept while others were awake";
        if (how == 0)
            motionOf(link[0])->wake();
        else
            link[4]->getDynamics().velocity = Vector(0.5f, 0, 0);
        s.step();
        for (size_t i = 0; i < link.size(); ++i) EXPECT_FALSE(link[i]->getDynamics().sleeping) << how << i;
        for (iHingeJoint* j : hinge) j->Delete();
    }
}
