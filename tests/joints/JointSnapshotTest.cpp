// JointSnapshotTest.cpp - a snapshot carries the joints' impulses: the steps after a restore repeat those
// after the snapshot bit for bit (the warm start included), for a swinging chain of every joint kind.
#include "JointTestSupport.h"
#include "iBallJoint.h"
#include "iDistanceJoint.h"
#include "iFixedJoint.h"
#include "iHingeJoint.h"
#include "iSliderJoint.h"
#include "iSnapshots.h"
#include "iSpring.h"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

using namespace joint_test;

namespace {
std::vector<float> stateOf(const std::vector<iRigidBody*>& bodies) {
    std::vector<float> out;
    for (const iRigidBody* b : bodies) {
        const RBDynamics& d = b->getDynamics();
        for (const Vector& v : {d.position, d.velocity, d.angularVelocity})
            out.insert(out.end(), {v.x, v.y, v.z});
        out.insert(out.end(), d.orientation.data(), d.orientation.data() + 16);
    }
    return out;
}
} // namespace

TEST(JointSnapshot, StepsAfterARestoreRepeatThoseAfterTheSnapshotBitForBit) {
    StepScene s(60);
    std::vector<iRigidBody*> bodies;
    std::vector<iJoint*> joints;
    for (int i = 0; i < 7; ++i)
        bodies.push_back(boxBody(Vector(0.3f * float(i + 1), 0, 0), 1.0f, 0.1f, 0.1f, 0.1f));
    joints.push_back(CreateBallJoint(bodies[0], nullptr, Vector(0, 0, 0)));
    joints.push_back(CreateHingeJoint(bodies[1], bodies[0], Vector(0.45f, 0, 0), Vector(0, 0, 1)));
    joints.push_back(CreateSliderJoint(bodies[2], bodies[1], Vector(0.75f, 0, 0), Vector(1, 0, 0)));
    joints.push_back(CreateFixedJoint(bodies[3], bodies[2], Vector(1.05f, 0, 0)));
    joints.push_back(CreateDistanceJoint(bodies[4], bodies[3], Vector(1.5f, 0, 0), Vector(1.2f, 0, 0)));
    joints.push_back(
        CreateSpring(bodies[5], bodies[4], Vector(1.8f, 0, 0), Vector(1.5f, 0, 0), 0.3f, 200.0f, 1.0f));
    joints.push_back(CreateHingeJoint(bodies[6], bodies[5], Vector(1.95f, 0, 0), Vector(0, 1, 0)));
    for (iJoint* j : joints) ASSERT_NE(j, nullptr);
    s.seconds(0.5); // swinging, with impulses to warm-start from
    iSnapshot* snapshot = snapshotsOf(s.scene())->takeSnapshot();
    ASSERT_NE(snapshot, nullptr);
    s.seconds(0.5);
    const std::vector<float> first = stateOf(bodies);
    ASSERT_TRUE(snapshotsOf(s.scene())->restoreSnapshot(snapshot));
    s.steps -= 30; // the clock went back with the snapshot
    s.seconds(0.5);
    const std::vector<float> again = stateOf(bodies);
    ASSERT_EQ(first.size(), again.size());
    EXPECT_EQ(std::memcmp(first.data(), again.data(), first.size() * sizeof(float)), 0);
    snapshot->Delete();
    for (iJoint* j : joints) j->Delete();
    for (iRigidBody* b : bodies) b->Delete();
}
