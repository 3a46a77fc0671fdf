// ListenerTest.cpp - HitWall: once per touching body pair per populate call, on both sides, normal toward
// `other`; and the safety rules: listeners that detach themselves, delete or remove geometry, or delete
// bodies during the call.
#include "DefaultSpace.h"
#include "UserBody.h"
#include "iCOBB.h"
#include "iCPlane.h"
#include "iCSphere.h"
#include "iCollisionListener.h"
#include "iCollisionSpace.h"
#include "iSimpleCollisionSpace.h"

#include <gtest/gtest.h>

#include <functional>
#include <vector>

namespace {

struct Hit {
    iRigidBody* other;
    Vector normal, location;
};

class Recorder final : public iCollisionListener {
public:
    std::vector<Hit> hits;
    std::function<void(Recorder*, iRigidBody*)> onHit;
    void HitWall(iRigidBody* other, Vector n, Vector at) override {
        hits.push_back({other, n, at});
        if (onHit) onHit(this, other);
    }
};

} // namespace

TEST(Listeners, OncePerBodyPairOnBothSidesWithNormalTowardOther) {
    iCollisionSpace* space = CreateSimpleCollisionSpace();
    DefaultSpace joins(space); // new geometry joins it
    UserBody a(Vector(0, 0, 0)), b(Vector(1.5f, 0, 0)), far(Vector(50, 0, 0));
    Recorder ra, rb, rfar;
    a.attachListener(&ra);
    b.attachListener(&rb);
    far.attachListener(&rfar);
    // Two geometries on a, both touching b: still one call per side.
    iCollisionGeometry* g[] = {CreateCSphere(&a, 1), CreateCOBB(&a, Vector(0.9f, 0.9f, 0.9f)),
                               CreateCOBB(&b, Vector(1, 1, 1)), CreateCSphere(&far, 1)};
    for (auto* x : g) space->add(x);
    space->populateContactList(0);
    EXPECT_GE(space->getNumContacts(), 2u);
    ASSERT_EQ(ra.hits.size(), 1u);
    ASSERT_EQ(rb.hits.size(), 1u);
    EXPECT_TRUE(rfar.hits.empty());
    EXPECT_EQ(ra.hits[0].other, &b);
    EXPECT_EQ(rb.hits[0].other, &a);
    EXPECT_GT(ra.hits[0].normal.x, 0.99f); // a's normal points at b
    EXPECT_LT(rb.hits[0].normal.x, -0.99f);
    EXPECT_NEAR(ra.hits[0].location.x, rb.hits[0].location.x, 1e-6f);
    space->populateContactList(0); // every call
    EXPECT_EQ(ra.hits.size(), 2u);
    for (auto* x : g) x->Delete();
    space->Delete();
}

TEST(Listeners, SelfDetachAndDetachingOthersIsSafe) {
    iCollisionSpace* space = CreateSimpleCollisionSpace();
    DefaultSpace joins(space); // new geometry joins it
    UserBody a(Vector(0, 0, 0)), b(Vector(0.5f, 0, 0));
    Recorder first, second, third;
    first.onHit = [&](Recorder* self, iRigidBody*) {
        a.detachListener(self);    // itself
        a.detachListener(&second); // and the next one: it must not be called
    };
    a.attachListener(&first);
    a.attachListener(&second);
    a.attachListener(&third);
    iCollisionGeometry* ga = CreateCSphere(&a, 1);
    iCollisionGeometry* gb = CreateCSphere(&b, 1);
    space->add(ga);
    space->add(gb);
    space->populateContactList(0);
    EXPECT_EQ(first.hits.size(), 1u);
    EXPECT_EQ(second.hits.size(), 0u);
    EXPECT_EQ(third.hits.size(), 1u);
    space->populateContactList(0);
    EXPECT_EQ(first.hits.size(), 1u);
    EXPECT_EQ(third.hits.size(), 2u);
    ga->Delete();
    gb->Delete();
    space->Delete();
}

TEST(Listeners, DeletingOrRemovingGeometryDuringTheCallIsDeferred) {
    iCollisionSpace* space = CreateSimpleCollisionSpace();
    DefaultSpace joins(space); // new geometry joins it
    UserBody a(Vector(0, 0, 0)), b(Vector(0.5f, 0, 0)), c(Vector(-0.5f, 0, 0));
    iCollisionGeometry* ga = CreateCSphere(&a, 1);
    iCollisionGeometry* gb = CreateCSphere(&b, 1);
    iCollisionGeometry* gc = CreateCSphere(&c, 1);
    for (auto* x : {ga, gb, gc}) space->add(x);
    Recorder ra, rb, rc;
    ra.onHit = [&](Recorder*, iRigidBody* other) {
        if (other == &b && gb) {
            gb->Delete(); // deleted in HitWall
            gb = nullptr;
        }
    };
    a.attachListener(&ra);
    b.attachListener(&rb);
    c.attachListener(&rc);
    space->populateContactList(0);
    // Only contacts between live, still-attached geometry remain.
    for (size_t i = 0; i < space->getNumContacts(); ++i) {
        const CollisionContact& k = space->getContactList()[i];
        EXPECT_TRUE((k.g1 == ga || k.g1 == gc) && (k.g2 == ga || k.g2 == gc));
    }
    EXPECT_EQ(space->getNumContacts(), 1u);
    EXPECT_EQ(space->getAttachedGeometry().size(), 2u);
    // Removing during the call: takes effect after the notifications.
    rc.onHit = [&](Recorder*, iRigidBody*) { space->remove(gc); };
    space->populateContactList(0);
    EXPECT_EQ(space->getNumContacts(), 0u);
    EXPECT_EQ(gc->getSpace(), nullptr);
    ga->Delete();
    gc->Delete();
    space->Delete();
}

TEST(Listeners, DeletingABodyDuringTheCallStopsItsCalls) {
    iCollisionSpace* space = CreateSimpleCollisionSpace();
    DefaultSpace joins(space); // new geometry joins it
    auto* victim = new UserBody(Vector(0.5f, 0, 0));
    UserBody a(Vector(0, 0, 0));
    iCollisionGeometry* ga = CreateCSphere(&a, 1);
    iCollisionGeometry* gv = CreateCSphere(victim, 1);
    space->add(ga);
    space->add(gv);
    Recorder ra, rv;
    ra.onHit = [&](Recorder*, iRigidBody* other) {
        if (other == victim) victim->Delete();
    };
    rv.onHit = [&](Recorder*, iRigidBody*) { ADD_FAILURE() << "a deleted body's listener was called"; };
    a.attachListener(&ra);
    victim->attachListener(&rv);
    space->populateContactList(0);
    EXPECT_EQ(ra.hits.size(), 1u);
    EXPECT_EQ(gv->getRigidBody(), nullptr);
    EXPECT_EQ(space->getNumContacts(), 0u); // its contacts were dropped
    ga->Delete();
    gv->Delete();
    space->Delete();
}

TEST(Listeners, ABodilessPlaneIsReportedAsNullOther) {
    iCollisionSpace* space = CreateSimpleCollisionSpace();
    DefaultSpace joins(space); // new geometry joins it
    UserBody a(Vector(0, 0.2f, 0));
    Recorder ra;
    a.attachListener(&ra);
    iCollisionGeometry* floor = CreateCPlane();
    iCollisionGeometry* ga = CreateCSphere(&a, 0.5f);
    space->add(floor);
    space->add(ga);
    space->populateContactList(0);
    ASSERT_EQ(ra.hits.size(), 1u);
    EXPECT_EQ(ra.hits[0].other, nullptr);
    EXPECT_NEAR(ra.hits[0].normal.y, -1.0f, 1e-6f); // toward the plane
    floor->Delete();
    ga->Delete();
    space->Delete();
}
