// JointContactTest.cpp - joints meeting contacts in whole scenes with collision geometry (World): a joined
// pair's contacts are dropped unless setCollideConnected(true), and a hinged door stopped by its limit while
// a ball hits it (the limit holds, the ball does not pass through the door).
#include "SceneFixture.h"
#include "iBallJoint.h"
#include "iHingeJoint.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using resolution_test::SceneFixture;

// Two spheres (r 0.5 m) overlapping by 0.4 m, weightless, joined by a ball joint 0.5 m above the midpoint of
// their centres, where they can swing apart like scissors. Not colliding (the default), nothing pushes them:
// the centres stay 0.6 m apart. Colliding, the contact pushes them apart until they no longer overlap
// (centres at least 2 r apart, within the contact slop).
TEST(JointContact, AJoinedPairCollidesOnlyWhenAskedTo) {
    for (bool collide : {false, true}) {
        SceneFixture s;
        settingsOf(s.scene)->setGravity(Vector(0, 0, 0));
        iRigidBody* a = s.world->sphere(Vector(-0.3f, 5, 0), 0.5f, 1.0f)->getRB();
        iRigidBody* b = s.world->sphere(Vector(0.3f, 5, 0), 0.5f, 1.0f)->getRB();
        iBallJoint* joint = CreateBallJoint(a, b, Vector(0, 5.5f, 0));
        ASSERT_NE(joint, nullptr);
        joint->setCollideConnected(collide);
        EXPECT_EQ(joint->getCollideConnected(), collide);
        s.seconds(3);
        const float apart = (b->getDynamics().position - a->getDynamics().position).length();
        if (collide)
            EXPECT_GT(apart, 1.0f - 0.02f) << apart;
        else
            EXPECT_NEAR(apart, 0.6f, 1e-4f);
        // the joint held either way: the anchors together
        const Vector anchorA =
            joint->getLocalAnchorA() * a->getDynamics().orientation + a->getDynamics().position;
        const Vector anchorB =
            joint->getLocalAnchorB() * b->getDynamics().orientation + b->getDynamics().position;
        EXPECT_LT((anchorA - anchorB).length(), 1e-3f) << collide;
        joint->Delete();
    }
}

// A door (1 x 2 x 0.1 m box, 10 kg) on a vertical hinge along its edge at x = 0, opening at most 0.3 rad
// either way; a 5 kg ball hits it at 10 m/s 0.7 m from the hinge, weightless. The door swings to its limit
// and stops there (within 0.01 rad at every step), its hinge edge is back in place (1 mm) after the hit, and
// the ball never passes through the door's plane (its centre stays at least r - 2 cm in front of it while
// over the door).
TEST(JointContact, AHingedDoorStoppedByItsLimitWhileABallHitsIt) {
    SceneFixture s;
    settingsOf(s.scene)->setGravity(Vector(0, 0, 0));
    const float r = 0.2f, limit = 0.3f;
    iRigidBody* door = s.world->box(Vector(0.5f, 1, 0), Vector(0.5f, 1, 0.05f), 10.0f)->getRB();
    iRigidBody* ball = s.world->sphere(Vector(0.7f, 1, -2), r, 5.0f)->getRB();
    iHingeJoint* hinge = CreateHingeJoint(door, nullptr, Vector(0, 1, 0), Vector(0, 1, 0));
    ASSERT_NE(hinge, nullptr);
    ASSERT_TRUE(hinge->setLimits(-limit, limit));
    ball->getDynamics().velocity = Vector(0, 0, 10);
    float widest = 0, closest = 1e9f, edgeMoved = 0;
    s.seconds(2, [&] {
        widest = std::max(widest, std::fabs(hinge->getAngle()));
        const RBDynamics &d = door->getDynamics(), &bd = ball->getDynamics();
        const Vector normal(d.orientation.m31, d.orientation.m32, d.orientation.m33); // the door's local z
        const Vector along(d.orientation.m11, d.orientation.m12, d.orientation.m13);  // across the door
        const Vector fromCentre = bd.position - d.position;
        if (std::fabs(dot(fromCentre, along)) < 0.5f) closest = std::min(closest, -dot(fromCentre, normal));
        const Vector edge = Vector(-0.5f, 0, 0) * d.orientation + d.position; // the hinge edge's midpoint
        edgeMoved = std::max(edgeMoved, (edge - Vector(0, 1, 0)).length());
    });
    EXPECT_LE(widest, limit + 0.01f);
    EXPECT_GT(widest, limit - 0.01f); // it was stopped by the limit, not short of it
    EXPECT_GT(closest, r - 0.02f) << closest;
    // the hinge gives a little while the hit lasts (measured 5.4 mm: the point rows share the sweeps with
    // the limit and the contact), and is back in place once it is over
    EXPECT_LT(edgeMoved, 0.01f);
    const RBDynamics& d = door->getDynamics();
    EXPECT_LT((Vector(-0.5f, 0, 0) * d.orientation + d.position - Vector(0, 1, 0)).length(), 1e-3f);
    std::printf("[ door ] swing at most %.4f rad (limit %.1f), hinge edge moved at most %.2f mm\n", widest,
                limit, 1000 * edgeMoved);
    EXPECT_LT(ball->getDynamics().velocity.z, 10.0f); // the ball was stopped or turned back
    hinge->Delete();
}
