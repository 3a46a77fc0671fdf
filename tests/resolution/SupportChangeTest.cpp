// SupportChangeTest.cpp - a body asleep on something the game takes away falls (Collision/SpaceWake.cpp):
// a floor lowered with iCPlane::setPlane, a fixed platform moved away, its body deleted, its geometry
// removed from the space. Before, each left the sleeper hanging in the air: a pair of two resting things is
// not tested, and nothing touching the sleeper moved. The box falls freely (y = y0 - g t^2 / 2, as the
// integrator gives it) and comes to rest on what is below; what the change did not touch sleeps on.
#include "SceneFixture.h"
#include "iCOBB.h"
#include "iCPlane.h"
#include "iCSphere.h"
#include "iCollisionFilter.h"
#include "iCollisionQueries.h"
#include "iOctreeCollisionSpace.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace resolution_test;

namespace {

const Vector kHalf(0.5f, 0.5f, 0.5f);

iPhysicsFrame* clayBox(World& w, const Vector& at) {
    iPhysicsFrame* f = w.box(at, kHalf, 1.0f);
    f->getDynamics()->restitution = 0.0f; // lands without a bounce: rests within a second
    return f;
}

// The world's geometry bound to f.
iCollisionGeometry* shapeOf(const World& w, const iPhysicsFrame* f) {
    for (iCollisionGeometry* g : w.space()->getAttachedGeometry())
        if (g->getRigidBody() == f->getRB()) return g;
    return nullptr;
}

// A box on a fixed platform 3 m above the floor (the platform's top at 0).
struct BoxOnPlatform {
    SceneFixture s{4};
    iPhysicsFrame* platform = nullptr;
    iPhysicsFrame* box = nullptr;
    BoxOnPlatform() {
        s.world->ground(-3.0f);
        platform = s.world->fixedBox(Vector(0, -0.1f, 0), Vector(2, 0.1f, 2));
        box = clayBox(*s.world, Vector(0, 0.5f, 0));
    }
};

bool sleepsWithin(SceneFixture& s, iPhysicsFrame* f, float seconds) {
    for (int i = 0; i < int(seconds * 60) && !f->getDynamics()->sleeping; ++i) s.steps(1);
    return f->getDynamics()->sleeping;
}

// The box, asleep at restY, its support changed by change(): it falls freely for fallSteps steps (its
// bottom not yet at floorY), then rests on floorY.
void fallsToTheFloor(SceneFixture& s, iPhysicsFrame* box, float floorY, const std::function<void()>& change) {
    ASSERT_TRUE(sleepsWithin(s, box, 3.0f)) << "asleep on its support first";
    const float restY = box->getDynamics()->position.y;
    change();
    // Semi-implicit Euler at 60 Hz falls g t dt / 2 further than the analytic curve by time t.
    const float drop = restY - 0.5f - floorY, tFall = std::sqrt(2.0f * drop / kG);
    const int fallSteps = int(0.8f * tFall * 60.0f);
    s.steps(fallSteps);
    const float t = float(fallSteps) * kDt;
    EXPECT_NEAR(box->getDynamics()->position.y, restY - 0.5f * kG * t * t, 0.5f * kG * t * kDt + 0.005f)
        << "falls freely once its support is gone";
    s.seconds(2.0f);
    EXPECT_NEAR(box->getDynamics()->position.y, floorY + 0.5f, 0.01f) << "rests on what is below";
}

void floorLoweredWithSetPlane(iCollisionSpace* space) {
    SceneFixture s(4, space);
    iCollisionGeometry* floor = CreateCPlane(nullptr, Vector(0, 1, 0), 0.0f);
    iPhysicsFrame* box = clayBox(*s.world, Vector(0, 0.5f, 0));
    fallsToTheFloor(s, box, -2.0f, [&] {
        static_cast<iCPlane*>(floor)->setPlane(Vector(0, 1, 0), -2.0f);
        RayHit hit; // the queries see the floor where it now is
        ASSERT_TRUE(queriesOf(s.world->space())->rayCast(Vector(5, 10, 5), Vector(0, -1, 0), 100.0f, hit));
        EXPECT_NEAR(hit.point.y, -2.0f, 1e-4f);
    });
    floor->Delete();
}

} // namespace

TEST(SupportChange, AFloorLoweredWithSetPlaneDropsWhatSleptOnItInTheSimpleSpace) {
    floorLoweredWithSetPlane(nullptr);
}

TEST(SupportChange, AFloorLoweredWithSetPlaneDropsWhatSleptOnItInTheOctreeSpace) {
    floorLoweredWithSetPlane(CreateOctreeCollisionSpace());
}

TEST(SupportChange, AFixedPlatformMovedAwayDropsWhatSleptOnIt) {
    BoxOnPlatform p;
    fallsToTheFloor(p.s, p.box, -3.0f, [&] { p.platform->getDynamics()->position = Vector(10, -0.1f, 0); });
}

TEST(SupportChange, ADeletedSupportDropsWhatSleptOnIt) {
    SceneFixture s(4);
    s.world->ground(-3.0f);
    iPhysicsFrame* support = CreatePhysicsFrame(); // not the world's: deleted here
    support->getDynamics()->physicsType = PHYS_FixedInSpace;
    support->getDynamics()->position = Vector(0, -0.1f, 0);
    iCollisionGeometry* deck = CreateCOBB(support->getRB(), Vector(2, 0.1f, 2));
    iPhysicsFrame* box = clayBox(*s.world, Vector(0, 0.5f, 0));
    fallsToTheFloor(s, box, -3.0f, [&] { support->Delete(); }); // the deck loses its body
    deck->Delete();
}

TEST(SupportChange, ASupportRemovedFromTheSpaceDropsWhatSleptOnIt) {
    BoxOnPlatform p;
    iCollisionGeometry* deck = shapeOf(*p.s.world, p.platform);
    ASSERT_NE(deck, nullptr);
    fallsToTheFloor(p.s, p.box, -3.0f, [&] { p.s.world->space()->remove(deck); });
    p.s.world->space()->add(deck); // the world deletes it with its space
}

// The change wakes only what touched the changed support: a box asleep on the ground beside it, and a box
// asleep on a platform that stays, sleep on.
TEST(SupportChange, WhatDidNotTouchTheChangedSupportSleepsOn) {
    SceneFixture s(4);
    s.world->ground(-3.0f);
    iPhysicsFrame* leaving = s.world->fixedBox(Vector(0, -0.1f, 0), Vector(2, 0.1f, 2));
    s.world->fixedBox(Vector(10, -0.1f, 0), Vector(2, 0.1f, 2));
    iPhysicsFrame* falls = clayBox(*s.world, Vector(0, 0.5f, 0));
    iPhysicsFrame* stays = clayBox(*s.world, Vector(10, 0.5f, 0));
    iPhysicsFrame* onGround = clayBox(*s.world, Vector(-10, -2.5f, 0));
    ASSERT_TRUE(sleepsWithin(s, falls, 3.0f));
    ASSERT_TRUE(sleepsWithin(s, stays, 1.0f));
    ASSERT_TRUE(sleepsWithin(s, onGround, 1.0f));
    leaving->getDynamics()->position = Vector(0, -10, 0);
    s.steps(1);
    EXPECT_FALSE(falls->getDynamics()->sleeping);
    EXPECT_TRUE(stays->getDynamics()->sleeping);
    EXPECT_TRUE(onGround->getDynamics()->sleeping);
    EXPECT_LT(falls->getDynamics()->position.y, 0.5f);
}

// A composite asleep on a platform by an attached body's shape: the attached body's wake wakes its root, and
// the composite falls as one.
TEST(SupportChange, ACompositeRestingOnAnAttachedBodysShapeFallsAsOne) {
    SceneFixture s(4);
    s.world->ground(-0.5f);
    iPhysicsFrame* platform = s.world->fixedBox(Vector(0, -0.1f, 0), Vector(2, 0.1f, 2));
    iPhysicsFrame* root = clayBox(*s.world, Vector(0, 2.0f, 0)); // clear of the platform
    iPhysicsFrame* foot = clayBox(*s.world, Vector(0, 0.5f, 0)); // on it
    foot->getDynamics()->attachTo(root->getDynamics());
    ASSERT_TRUE(sleepsWithin(s, root, 3.0f));
    const float restY = root->getDynamics()->position.y; // the foot's position is its place on the root
    const Vector footPlace = foot->getDynamics()->position;
    platform->getDynamics()->position = Vector(10, -0.1f, 0);
    s.seconds(2.5f);
    EXPECT_NEAR(root->getDynamics()->position.y, restY - 0.5f, 0.01f) << "the foot rests on the ground ";
    EXPECT_LT((foot->getDynamics()->position - footPlace).length(), 1e-4f) << "still attached where it was";
}

// A sleeping ball shrunk with setRadius wakes (its own shape changed) and settles on the ground at its new
// radius.
TEST(SupportChange, ASleepingBallShrunkWithSetRadiusWakesAndSettlesAtItsNewRadius) {
    SceneFixture s(4);
    s.world->ground();
    iPhysicsFrame* ball = s.world->sphere(Vector(0, 1.0f, 0), 1.0f, 1.0f);
    ball->getDynamics()->restitution = 0.0f;
    iCollisionGeometry* shape = shapeOf(*s.world, ball);
    ASSERT_NE(shape, nullptr);
    ASSERT_TRUE(sleepsWithin(s, ball, 3.0f));
    static_cast<iCSphere*>(shape)->setRadius(0.5f);
    s.seconds(2.0f);
    EXPECT_NEAR(ball->getDynamics()->position.y, 0.5f, 0.01f);
}

// A box asleep on the floor whose own shape is removed from the space falls through the floor at g: nothing
// holds it up any more.
TEST(SupportChange, ASleeperWhoseOwnShapeLeavesTheSpaceFalls) {
    SceneFixture s(4);
    s.world->ground();
    iPhysicsFrame* box = clayBox(*s.world, Vector(0, 0.5f, 0));
    iCollisionGeometry* shape = shapeOf(*s.world, box);
    ASSERT_NE(shape, nullptr);
    ASSERT_TRUE(sleepsWithin(s, box, 3.0f));
    const float y0 = box->getDynamics()->position.y;
    s.world->space()->remove(shape);
    const int n = 30;
    s.steps(n);
    const float t = float(n) * kDt;
    EXPECT_NEAR(box->getDynamics()->position.y, y0 - 0.5f * kG * t * t, 0.5f * kG * t * kDt + 0.005f);
    s.world->space()->add(shape); // the world deletes it with its space
}

// A platform made to let the box's layer through (its mask changed) drops the box asleep on it.
TEST(SupportChange, APlatformFilteredToLetTheBoxThroughDropsIt) {
    BoxOnPlatform p;
    iCollisionGeometry* deck = shapeOf(*p.s.world, p.platform);
    ASSERT_NE(deck, nullptr);
    fallsToTheFloor(p.s, p.box, -3.0f, [&] { filterOf(deck)->setMask(~std::uint32_t(1)); }); // not layer 1
}
