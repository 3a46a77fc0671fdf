// SpaceTest.cpp - the simple space through the public API with a game's own iRigidBody (UserBody.h):
// contacts, filters, several spaces, membership, body lifetime, bad input, compounds, queries.
#include "CollisionGeometry.h"
#include "UserBody.h"
#include "iCCompound.h"
#include "iCOBB.h"
#include "iCPlane.h"
#include "iCSphere.h"
#include "iCollisionQueries.h"
#include "iCollisionSpace.h"
#include "iContactFeatures.h"
#include "iSimpleCollisionSpace.h"
#include "iUtilities.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace {

// Restores the default space and error handler after each test.
class SpaceTest : public ::testing::Test {
protected:
    void SetUp() override {
        setErrorHandler([](const wchar_t*) {});
        space = CreateSimpleCollisionSpace();
        CollisionGeometry::setGlobalCollisionSpace(space);
    }
    void TearDown() override {
        CollisionGeometry::setGlobalCollisionSpace(nullptr);
        if (space) space->Delete();
        setErrorHandler(nullptr);
    }
    iCollisionSpace* space = nullptr;
};

bool contains(const std::vector<iCollisionGeometry*>& v, const iCollisionGeometry* g) {
    return std::find(v.begin(), v.end(), g) != v.end();
}

} // namespace

TEST_F(SpaceTest, UserWrittenBodyGetsContacts) {
    UserBody a(Vector(0, 0, 0)), b(Vector(1.5f, 0, 0));
    iCollisionGeometry* s = CreateCSphere(&a, 1.0f);
    iCollisionGeometry* box = CreateCOBB(&b, Vector(1, 1, 1));
    ASSERT_EQ(s->getSpace(), space);
    ASSERT_EQ(space->getAttachedGeometry().size(), 2u);
    space->populateContactList(1.0f / 60.0f);
    ASSERT_EQ(space->getNumContacts(), 1u);
    const CollisionContact& c = space->getContactList()[0];
    EXPECT_EQ(c.g1, s);
    EXPECT_EQ(c.g2, box);
    EXPECT_NEAR(c.normal.x, 1.0f, 1e-6f); // points at g2
    EXPECT_NEAR(c.depth, 0.5f, 1e-5f);
    EXPECT_NEAR(c.pos.x, 0.75f, 1e-5f); // midway between the surfaces
    // Moving the body apart ends the contact; the geometry follows getDynamics().
    b.place(Vector(2.5f, 0, 0));
    space->populateContactList(1.0f / 60.0f);
    EXPECT_EQ(space->getNumContacts(), 0u);
    EXPECT_EQ(space->getContactList(), nullptr);
    // The geometry's centre is the body frame's origin: COM minus the com offset turned by the orientation.
    b.getDynamics().com = Vector(0, 0, 1);
    b.getDynamics().orientation = rotatey(1.5707963f); // local z -> world -x... origin = pos - com*R
    b.place(Vector(2.5f, 0, 0), rotatey(1.5707963f));
    float lo, hi;
    box->getProjectionBounds(Vector(1, 0, 0), lo, hi);
    Vector origin = b.getDynamics().getWorldOrigin();
    EXPECT_NEAR(0.5f * (lo + hi), origin.x, 1e-5f);
    s->Delete();
    box->Delete();
    EXPECT_TRUE(space->getAttachedGeometry().empty());
}

TEST_F(SpaceTest, SeedDefaultsAndRefusals) {
    iCollisionGeometry* s = CreateCSphere();
    iCollisionGeometry* b = CreateCOBB();
    EXPECT_FLOAT_EQ(static_cast<iCSphere*>(s)->getRadius(), 10.0f);
    EXPECT_EQ(static_cast<iCOBB*>(b)->getRadius(), Vector(10, 10, 10));
    EXPECT_EQ(s->getCollisionType(), CT_SPHERE);
    EXPECT_EQ(b->getCollisionType(), CT_OBB);
    unsigned long errors = errorCount();
    EXPECT_EQ(CreateCSphere(nullptr, -1.0f), nullptr);
    EXPECT_EQ(CreateCSphere(nullptr, NAN), nullptr);
    EXPECT_EQ(CreateCOBB(nullptr, Vector(1, 0, 1)), nullptr);
    EXPECT_EQ(CreateCPlane(nullptr, Vector(0, 0, 0)), nullptr);
    static_cast<iCSphere*>(s)->setRadius(0.0f);
    EXPECT_FLOAT_EQ(static_cast<iCSphere*>(s)->getRadius(), 10.0f);
    EXPECT_FALSE(space->add(nullptr));
    space->remove(nullptr);
    EXPECT_EQ(errorCount(), errors + 7);
    s->Delete();
    b->Delete();
}

TEST_F(SpaceTest, FiltersFixedPairsSameBodyAndBodiless) {
    UserBody f1(Vector(0, 0, 0), PHYS_FixedInSpace), f2(Vector(0.5f, 0, 0), PHYS_FixedInSpace);
    UserBody m(Vector(0, 0.5f, 0));
    iCollisionGeometry* a = CreateCSphere(&f1, 1);
    iCollisionGeometry* b = CreateCSphere(&f2, 1);
    iCollisionGeometry* c = CreateCOBB(&m, Vector(0.5f, 0.5f, 0.5f));
    iCollisionGeometry* d = CreateCSphere(&m, 0.5f);   // same body as c: never tested against c
    iCollisionGeometry* e = CreateCSphere(nullptr, 5); // no body: never collides
    space->populateContactList(0);
    for (size_t i = 0; i < space->getNumContacts(); ++i) {
        const CollisionContact& k = space->getContactList()[i];
        EXPECT_FALSE((k.g1 == a && k.g2 == b) || (k.g1 == b && k.g2 == a)) << "two fixed bodies";
        EXPECT_FALSE((k.g1 == c && k.g2 == d) || (k.g1 == d && k.g2 == c)) << "same body";
        EXPECT_TRUE(k.g1 != e && k.g2 != e) << "bodiless";
    }
    EXPECT_EQ(space->getNumContacts(), 4u); // m's box and sphere each against both fixed spheres
    for (iCollisionGeometry* g : {a, b, c, d, e}) g->Delete();
}

TEST_F(SpaceTest, PairsOfSleepingOrFixedBodiesAreNotTestedButAnAwakeBodyStillTouchesThem) {
    // Two overlapping sleeping spheres resting on a fixed box: no pair among them is tested. An awake sphere
    // overlapping one of them is.
    UserBody ground(Vector(0, -1, 0), PHYS_FixedInSpace), s1(Vector(0, 0.4f, 0)), s2(Vector(0.8f, 0.4f, 0));
    UserBody awake(Vector(-0.8f, 0.4f, 0));
    s1.getDynamics().sleeping = s2.getDynamics().sleeping = true;
    iCollisionGeometry* g = CreateCOBB(&ground, Vector(5, 1, 5));
    iCollisionGeometry* a = CreateCSphere(&s1, 0.5f);
    iCollisionGeometry* b = CreateCSphere(&s2, 0.5f);
    space->populateContactList(0);
    EXPECT_EQ(space->getNumContacts(), 0u);
    iCollisionGeometry* c = CreateCSphere(&awake, 0.5f);
    space->populateContactList(0);
    // The awake sphere touches the floor and s1; nothing else is tested.
    ASSERT_EQ(space->getNumContacts(), 2u);
    for (size_t i = 0; i < space->getNumContacts(); ++i) {
        const CollisionContact& k = space->getContactList()[i];
        EXPECT_TRUE(k.g1 == c || k.g2 == c);
    }
    s2.getDynamics().sleeping = false; // woken: its floor contact and its contact with s1 come back
    space->populateContactList(0);
    EXPECT_EQ(space->getNumContacts(), 4u);
    for (iCollisionGeometry* x : {g, a, b, c}) x->Delete();
}

TEST_F(SpaceTest, TwoSpacesNeverSeeEachOthersContacts) {
    iCollisionSpace* other = CreateSimpleCollisionSpace(120);
    UserBody a(Vector(0, 0, 0)), b(Vector(0.5f, 0, 0)), c(Vector(0, 0.2f, 0)), d(Vector(0.4f, 0.2f, 0));
    iCollisionGeometry* ga = CreateCSphere(&a, 1); // joins the default space
    iCollisionGeometry* gb = CreateCOBB(&b, Vector(1, 1, 1));
    CollisionGeometry::setGlobalCollisionSpace(other);
    iCollisionGeometry* gc = CreateCSphere(&c, 1);
    iCollisionGeometry* gd = CreateCOBB(&d, Vector(1, 1, 1));
    CollisionGeometry::setGlobalCollisionSpace(space);
    EXPECT_EQ(gc->getSpace(), other);
    for (int frame = 0; frame < 3; ++frame) {
        space->populateContactList(1.0f / 60);
        other->populateContactList(1.0f / 60);
        ASSERT_EQ(space->getNumContacts(), 1u);
        ASSERT_EQ(other->getNumContacts(), 1u);
        EXPECT_EQ(space->getContactList()[0].g1, ga);
        EXPECT_EQ(space->getContactList()[0].g2, gb);
        EXPECT_EQ(other->getContactList()[0].g1, gc);
        EXPECT_EQ(other->getContactList()[0].g2, gd);
    }
    // A geometry is in one space at a time: adding it to the other moves it.
    EXPECT_TRUE(other->add(ga));
    EXPECT_FALSE(other->add(ga));
    EXPECT_EQ(ga->getSpace(), other);
    EXPECT_EQ(space->getAttachedGeometry().size(), 1u);
    space->populateContactList(0);
    other->populateContactList(0);
    EXPECT_EQ(space->getNumContacts(), 0u);
    EXPECT_EQ(other->getNumContacts(), 3u); // ga-gc, ga-gd, gc-gd
    // Deleting a space leaves its geometry alive and spaceless.
    other->Delete();
    EXPECT_EQ(ga->getSpace(), nullptr);
    EXPECT_EQ(gc->getSpace(), nullptr);
    for (iCollisionGeometry* g : {ga, gb, gc, gd}) g->Delete();
}

TEST_F(SpaceTest, DyingBodyUnbindsItsGeometry) {
    auto* a = new UserBody(Vector(0, 0, 0));
    UserBody b(Vector(0.5f, 0, 0));
    iCollisionGeometry* ga = CreateCSphere(a, 1);
    iCollisionGeometry* gb = CreateCSphere(&b, 1);
    space->populateContactList(0);
    EXPECT_EQ(space->getNumContacts(), 1u);
    a->Delete(); // calls rigidBodyDestroyed
    EXPECT_EQ(ga->getRigidBody(), nullptr);
    space->populateContactList(0);
    EXPECT_EQ(space->getNumContacts(), 0u);
    ga->attach(&b); // re-bound later: collides again (but not with gb: same body)
    space->populateContactList(0);
    EXPECT_EQ(space->getNumContacts(), 0u);
    ga->Delete();
    gb->Delete();
}

TEST_F(SpaceTest, NonFinitePoseIsSkippedAndReportedOnce) {
    UserBody a(Vector(0, 0, 0)), b(Vector(0.5f, 0, 0));
    iCollisionGeometry* ga = CreateCSphere(&a, 1);
    iCollisionGeometry* gb = CreateCOBB(&b, Vector(1, 1, 1));
    a.getDynamics().position.x = NAN;
    unsigned long errors = errorCount();
    for (int i = 0; i < 5; ++i) {
        space->populateContactList(1.0f / 60);
        EXPECT_EQ(space->getNumContacts(), 0u);
    }
    EXPECT_EQ(errorCount(), errors + 1);
    b.getDynamics().orientation.m11 = INFINITY;
    space->populateContactList(1.0f / 60);
    EXPECT_EQ(errorCount(), errors + 2);
    a.getDynamics().position.x = 0;
    b.getDynamics().orientation = Matrix(1);
    space->populateContactList(1.0f / 60);
    EXPECT_EQ(space->getNumContacts(), 1u);
    ga->Delete();
    gb->Delete();
}

TEST_F(SpaceTest, PlanesCollideWithEveryShapeButNotWithFixedOrPlanes) {
    iCollisionGeometry* floor = CreateCPlane(); // y = 0, bodiless: fixed
    iCollisionGeometry* wall = CreateCPlane(nullptr, Vector(1, 0, 0), -3.0f);
    UserBody s(Vector(0, 0.4f, 0)), bx(Vector(2, 0.45f, 0)), fixedBody(Vector(5, 0, 0), PHYS_FixedInSpace);
    UserBody under(Vector(-2, -10, 0));
    iCollisionGeometry* gs = CreateCSphere(&s, 0.5f);
    iCollisionGeometry* gb = CreateCOBB(&bx, Vector(0.5f, 0.5f, 0.5f));
    iCollisionGeometry* gf = CreateCSphere(&fixedBody, 1);
    iCollisionGeometry* gu = CreateCSphere(&under, 0.5f); // far behind the floor: still collides
    space->populateContactList(0);
    int sphere = 0, box = 0, deep = 0;
    for (size_t i = 0; i < space->getNumContacts(); ++i) {
        const CollisionContact& c = space->getContactList()[i];
        EXPECT_TRUE(c.g1 == floor || c.g1 == wall || c.g2 == floor || c.g2 == wall);
        EXPECT_NE(c.g1, gf);
        EXPECT_NE(c.g2, gf);
        iCollisionGeometry* other = c.g1 == floor ? c.g2 : c.g1;
        Vector up = c.g1 == floor ? c.normal : -c.normal;
        if (c.g1 == floor || c.g2 == floor) {
            EXPECT_NEAR(up.y, 1.0f, 1e-6f);
        }
        sphere += other == gs;
        box += other == gb;
        deep += other == gu && c.depth > 10.0f;
    }
    EXPECT_EQ(sphere, 1);
    EXPECT_EQ(box, 4);
    EXPECT_EQ(deep, 1);
    for (iCollisionGeometry* g : {floor, wall, gs, gb, gf, gu}) g->Delete();
}

TEST_F(SpaceTest, CompoundGeometryCollidesThroughItsChildren) {
    UserBody body(Vector(0, 0, 0)), other(Vector(2.0f, 0, 0));
    auto* comp = static_cast<iCCompound*>(CreateCCompound(&body));
    EXPECT_TRUE(comp->addSphere(Vector(-1, 0, 0), 0.5f));
    EXPECT_TRUE(comp->addBox(Vector(1, 0, 0), rotatey(0.3f), Vector(0.5f, 0.5f, 0.5f)));
    EXPECT_FALSE(comp->addSphere(Vector(), -1.0f));
    EXPECT_FALSE(comp->addBox(Vector(), Matrix(2.0f), Vector(1, 1, 1)));
    EXPECT_EQ(comp->getNumChildren(), 2u);
    EXPECT_EQ(comp->getCollisionType(), CT_COMPOUND);
    iCollisionGeometry* s = CreateCSphere(&other, 0.6f);
    space->populateContactList(0);
    ASSERT_GE(space->getNumContacts(), 1u);
    for (size_t i = 0; i < space->getNumContacts(); ++i) {
        EXPECT_EQ(space->getContactList()[i].g1, comp);
        EXPECT_NEAR(space->getContactList()[i].normal.x, 1.0f, 0.2f);
    }
    // Turning the body half a turn brings the sphere child to the other side: still one contact.
    body.place(Vector(0, 0, 0), rotatey(3.1415927f));
    other.place(Vector(-2.0f, 0, 0));
    space->populateContactList(0);
    EXPECT_GE(space->getNumContacts(), 1u);
    other.place(Vector(0, 3, 0));
    space->populateContactList(0);
    EXPECT_EQ(space->getNumContacts(), 0u);
    comp->Delete();
    s->Delete();
}

TEST_F(SpaceTest, QueriesGoThroughTheSpace) {
    UserBody a(Vector(0, 0, 5)), b(Vector(0, 0, 10)), c(Vector(3, 0, 5));
    iCollisionGeometry* ga = CreateCSphere(&a, 1);
    iCollisionGeometry* gb = CreateCOBB(&b, Vector(2, 2, 2));
    iCollisionGeometry* gc = CreateCOBB(&c, Vector(0.5f, 0.5f, 0.5f));
    iCollisionGeometry* floor = CreateCPlane(nullptr, Vector(0, 1, 0), -4.0f);
    RayHit hit;
    ASSERT_TRUE(queriesOf(space)->rayCast(Vector(0, 0, 0), Vector(0, 0, 2), 100, hit));
    EXPECT_EQ(hit.geometry, ga);
    EXPECT_NEAR(hit.distance, 4.0f, 1e-5f);
    EXPECT_NEAR(hit.normal.z, -1.0f, 1e-5f);
    EXPECT_NEAR(hit.point.z, 4.0f, 1e-5f);
    ASSERT_TRUE(queriesOf(space)->rayCast(Vector(0, 0.0f, 20), Vector(0, 0, -1), 100, hit));
    EXPECT_EQ(hit.geometry, gb);
    EXPECT_NEAR(hit.distance, 8.0f, 1e-5f);
    ASSERT_TRUE(queriesOf(space)->rayCast(Vector(3, 10, 5), Vector(0, -1, 0), 100, hit));
    EXPECT_EQ(hit.geometry, gc);
    EXPECT_NEAR(hit.distance, 9.5f, 1e-5f);
    ASSERT_TRUE(queriesOf(space)->rayCast(Vector(9, 10, 5), Vector(0, -1, 0), 100, hit));
    EXPECT_EQ(hit.geometry, floor);
    EXPECT_NEAR(hit.distance, 14.0f, 1e-4f);
    EXPECT_FALSE(queriesOf(space)->rayCast(Vector(9, 10, 5), Vector(0, -1, 0), 13.0f, hit));
    EXPECT_FALSE(queriesOf(space)->rayCast(Vector(9, 10, 5), Vector(0, 0, 0), 13.0f, hit)); // refused
    std::vector<iCollisionGeometry*> out;
    EXPECT_EQ(queriesOf(space)->overlapSphere(Vector(0, 0, 7), 1.2f, out), 2u);
    EXPECT_TRUE(contains(out, ga) && contains(out, gb));
    EXPECT_EQ(queriesOf(space)->overlapAABB(Vector(2.6f, -1, 4), Vector(4, 1, 6), out), 1u);
    EXPECT_TRUE(contains(out, gc));
    EXPECT_EQ(queriesOf(space)->overlapBox(Vector(0, -4.5f, 0), rotatez(0.3f), Vector(1, 0.2f, 1), out), 1u);
    EXPECT_TRUE(contains(out, floor));
    for (iCollisionGeometry* g : {ga, gb, gc, floor}) g->Delete();
}

TEST_F(SpaceTest, FeatureIdsParallelTheContactsAndPersist) {
    UserBody ground(Vector(0, -0.5f, 0), PHYS_FixedInSpace), crate(Vector(0.2f, 0.45f, 0));
    iCollisionGeometry* g = CreateCOBB(&ground, Vector(5, 0.5f, 5));
    iCollisionGeometry* c = CreateCOBB(&crate, Vector(0.5f, 0.5f, 0.5f));
    space->populateContactList(1.0f / 60);
    ASSERT_EQ(space->getNumContacts(), 4u);
    std::vector<unsigned> first(featuresOf(space)->getContactFeatureIds(),
                                featuresOf(space)->getContactFeatureIds() + 4);
    const CollisionContact* storage = space->getContactList();
    crate.place(Vector(0.21f, 0.449f, 0.01f));
    space->populateContactList(1.0f / 60);
    ASSERT_EQ(space->getNumContacts(), 4u);
    EXPECT_EQ(space->getContactList(), storage); // storage reused
    for (int i = 0; i < 4; ++i) EXPECT_EQ(featuresOf(space)->getContactFeatureIds()[i], first[size_t(i)]);
    g->Delete();
    c->Delete();
}

// Removal is O(1) and the lists are cleaned at the next read: what the game reads is exactly the list
// before, less every contact naming a removed geometry, in the same order; the members keep their order.
TEST_F(SpaceTest, RemovedGeometryLeavesExactlyItsContactsAndTheRestInOrder) {
    std::vector<std::unique_ptr<UserBody>> bodies;
    std::vector<iCollisionGeometry*> row;
    for (int i = 0; i < 12; ++i) { // a row of touching unit spheres: contacts i-(i+1)
        bodies.push_back(std::make_unique<UserBody>(Vector(1.8f * float(i), 0, 0)));
        row.push_back(CreateCSphere(bodies.back().get(), 1.0f));
    }
    space->populateContactList(0);
    const std::vector<CollisionContact> before(space->getContactList(),
                                               space->getContactList() + space->getNumContacts());
    ASSERT_EQ(before.size(), 11u);
    std::vector<iCollisionGeometry*> removed = {row[1], row[4], row[5], row[9]};
    row[1]->Delete();
    space->remove(row[4]);
    row[5]->Delete();
    space->remove(row[9]);
    std::vector<CollisionContact> expected;
    for (const CollisionContact& c : before)
        if (!contains(removed, c.g1) && !contains(removed, c.g2)) expected.push_back(c);
    ASSERT_EQ(space->getNumContacts(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(space->getContactList()[i].g1, expected[i].g1);
        EXPECT_EQ(space->getContactList()[i].g2, expected[i].g2);
        EXPECT_EQ(space->getContactList()[i].pos.x, expected[i].pos.x);
    }
    std::vector<iCollisionGeometry*> members(space->getAttachedGeometry().begin(),
                                             space->getAttachedGeometry().end());
    std::vector<iCollisionGeometry*> kept;
    for (iCollisionGeometry* g : row)
        if (!contains(removed, g)) kept.push_back(g);
    EXPECT_EQ(members, kept);
    // Added back, a removed geometry joins at the end and collides again: the next list is a fresh one's.
    EXPECT_TRUE(space->add(row[4]));
    EXPECT_EQ(space->getAttachedGeometry().back(), row[4]);
    space->populateContactList(0);
    size_t naming4 = 0;
    for (size_t i = 0; i < space->getNumContacts(); ++i)
        naming4 += space->getContactList()[i].g1 == row[4] || space->getContactList()[i].g2 == row[4];
    EXPECT_EQ(naming4, 1u);                 // its neighbour 3 (5 is deleted)
    EXPECT_EQ(space->getNumContacts(), 5u); // 2-3, 3-4, 6-7, 7-8, 10-11 (9 is out)
    for (iCollisionGeometry* g : row)
        if (g != row[1] && g != row[5]) g->Delete();
}

// One watcher serves all geometry: a body's death reaches only its own geometries, whatever their number
// (a watcher per geometry made deleting N bodies cost N x geometries).
TEST_F(SpaceTest, GeometryAddsNoBodyWatcherAndABodysDeathUnbindsOnlyItsOwn) {
    UserBody other(Vector(10, 0, 0));
    iCollisionGeometry* first = CreateCSphere(&other, 1.0f); // the index exists from here on
    const size_t watchers = guardian_detail::rigidBodyWatchers().size();
    auto* dying = new UserBody(Vector(0, 0, 0));
    std::vector<iCollisionGeometry*> own, others;
    for (int i = 0; i < 50; ++i) {
        own.push_back(CreateCSphere(dying, 0.5f));
        others.push_back(CreateCOBB(&other, Vector(0.5f, 0.5f, 0.5f)));
    }
    EXPECT_EQ(guardian_detail::rigidBodyWatchers().size(), watchers);
    own[7]->attach(&other); // rebound: no longer the dying body's
    dying->Delete();
    for (size_t i = 0; i < own.size(); ++i) EXPECT_EQ(own[i]->getRigidBody(), i == 7 ? &other : nullptr) << i;
    for (iCollisionGeometry* g : others) EXPECT_EQ(g->getRigidBody(), &other);
    for (iCollisionGeometry* g : own) g->Delete();
    for (iCollisionGeometry* g : others) g->Delete();
    first->Delete();
    EXPECT_EQ(guardian_detail::rigidBodyWatchers().size(), watchers);
}
