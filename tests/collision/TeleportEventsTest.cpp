// TeleportEventsTest.cpp - the collision-only route: a game's own body that teleports is not swept across
// the jump, a resting pair is still reported while it rests, and held events come once per delivery.
#include "DefaultSpace.h"
#include "UserBody.h"
#include "iCOBB.h"
#include "iCSphere.h"
#include "iCollisionEvents.h"
#include "iCollisionListener.h"
#include "iSimpleCollisionSpace.h"

#include <gtest/gtest.h>

namespace {

struct Count final : iCollisionListener {
    int calls = 0;
    void HitWall(iRigidBody*, Vector, Vector) override { ++calls; }
};

struct Space {
    Space() : space(CreateSimpleCollisionSpace(60)), scope(space) {}
    ~Space() { space->Delete(); }
    iCollisionSpace* space;
    DefaultSpace scope;
};

// A 0.1 m ball moving 1 m per call at x = 10, then put at x = -10: a coin at the origin is on the straight
// line between. Marked as a teleport, nothing is found; not marked, the space sweeps the jump and finds the
// coin (which shows the test can tell the difference).
int coinHitsOnRespawn(bool marked) {
    Space s;
    UserBody mover(Vector(12, 0, 0)), coin(Vector(0, 0, 0), PHYS_FixedInSpace);
    iCollisionGeometry* a = CreateCSphere(&mover, 0.1f);
    iCollisionGeometry* b = CreateCSphere(&coin, 0.2f);
    Count heard;
    coin.attachListener(&heard);
    for (float x : {12.0f, 11.0f, 10.0f}) {
        mover.place(Vector(x, 0, 0));
        s.space->populateContactList(1.0f / 60.0f);
    }
    mover.place(Vector(-10, 0, 0));
    if (marked) mover.getDynamics().markTeleported();
    s.space->populateContactList(1.0f / 60.0f);
    int found = int(s.space->getNumContacts());
    a->Delete();
    b->Delete();
    return found + heard.calls;
}

} // namespace

TEST(TeleportEvents, AMarkedTeleportIsNotSwept) {
    EXPECT_EQ(coinHitsOnRespawn(true), 0);
    EXPECT_GT(coinHitsOnRespawn(false), 0);
}

// Two bodies touching, then both at rest (one asleep, one fixed): the pair is no longer tested, and is still
// reported to listeners every call from its last contact; once one moves away it is tested and not heard.
TEST(TeleportEvents, RestingPairsAreStillHeard) {
    Space s;
    UserBody ground(Vector(0, -1, 0), PHYS_FixedInSpace), ball(Vector(0, 0.24f, 0));
    iCollisionGeometry* g = CreateCOBB(&ground, Vector(5, 1, 5));
    iCollisionGeometry* b = CreateCSphere(&ball, 0.25f);
    Count heard;
    ball.attachListener(&heard);
    s.space->populateContactList(0);
    EXPECT_EQ(heard.calls, 1);
    EXPECT_EQ(s.space->getNumContacts(), 1u);
    ball.getDynamics().sleeping = true;
    for (int i = 0; i < 5; ++i) s.space->populateContactList(0);
    EXPECT_EQ(s.space->getNumContacts(), 0u); // not tested ...
    EXPECT_EQ(heard.calls, 6);                // ... but heard every call
    ball.getDynamics().sleeping = false;
    ball.place(Vector(0, 2, 0));
    s.space->populateContactList(0);
    EXPECT_EQ(heard.calls, 6);
    g->Delete();
    b->Delete();
}

// Held events: three calls, one delivery, one HitWall per side; a delivery with no call in between still
// reports what touches.
TEST(TeleportEvents, HeldEventsComeOncePerDelivery) {
    Space s;
    UserBody p(Vector(0, 0, 0)), q(Vector(0.3f, 0, 0));
    iCollisionGeometry* a = CreateCSphere(&p, 0.2f);
    iCollisionGeometry* b = CreateCSphere(&q, 0.2f);
    Count hp, hq;
    p.attachListener(&hp);
    q.attachListener(&hq);
    iCollisionEvents* events = eventsOf(s.space);
    ASSERT_NE(events, nullptr);
    events->holdEvents(true);
    for (int i = 0; i < 3; ++i) s.space->populateContactList(1.0f / 180.0f);
    EXPECT_EQ(hp.calls + hq.calls, 0);
    events->deliverEvents();
    EXPECT_EQ(hp.calls, 1);
    EXPECT_EQ(hq.calls, 1);
    events->deliverEvents(); // no call in between: still touching
    EXPECT_EQ(hp.calls, 2);
    q.place(Vector(3, 0, 0)); // apart now
    s.space->populateContactList(1.0f / 180.0f);
    events->deliverEvents();
    EXPECT_EQ(hp.calls, 2);
    b->Delete(); // a deleted geometry is forgotten, never delivered
    events->deliverEvents();
    EXPECT_EQ(hp.calls, 2);
    a->Delete();
}
