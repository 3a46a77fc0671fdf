// ContinuousTest.cpp - the tunnelling probes: a 0.1 m sphere (and a 0.2 m box) at 10, 100 and 1000 m/s
// against a 1 m box and a plane, at several sample rates, within one populateContactList call. With
// sampling on nothing passes through; with delta = 0 or infinity (discrete) a fast body does.
#include "DefaultSpace.h"
#include "UserBody.h"
#include "iCOBB.h"
#include "iCPlane.h"
#include "iCSphere.h"
#include "iCollisionSpace.h"
#include "iSimpleCollisionSpace.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

const float kDt = 1.0f / 60.0f;

// Runs one step of a mover from `from` to `to` past a fixed 1 m box at the origin; returns the contacts.
size_t probe(bool sphere, size_t samplesPerSecond, const Vector& from, const Vector& to, float delta,
             CollisionContact* first = nullptr, bool moveTheBox = false) {
    iCollisionSpace* space = CreateSimpleCollisionSpace(samplesPerSecond);
    DefaultSpace joins(space); // new geometry joins it
    UserBody wall(Vector(), moveTheBox ? PHYS_Falling : PHYS_FixedInSpace), mover(from);
    iCollisionGeometry* m =
        sphere ? CreateCSphere(&mover, 0.05f) : CreateCOBB(&mover, Vector(0.1f, 0.1f, 0.1f));
    iCollisionGeometry* w = CreateCOBB(&wall, Vector(0.5f, 0.5f, 0.5f));
    space->add(m);
    space->add(w);
    if (moveTheBox) { // the same relative motion, but the box moves and the small body stays
        mover.place(Vector());
        wall.place(-from);
    }
    space->populateContactList(delta);
    EXPECT_EQ(space->getNumContacts(), 0u) << "starts clear";
    if (moveTheBox)
        wall.place(-to);
    else
        mover.place(to);
    space->populateContactList(delta);
    size_t n = space->getNumContacts();
    if (n && first) *first = space->getContactList()[0];
    m->Delete();
    w->Delete();
    space->Delete();
    return n;
}

} // namespace

TEST(Continuous, SmallFastSphereNeverPassesThroughABox) {
    for (float speed : {10.0f, 100.0f, 1000.0f})
        for (size_t sps : {size_t(1), size_t(30), size_t(60), size_t(240)}) {
            // Straight through the middle, from just outside on the left to wherever one frame takes it.
            Vector from(-0.6f, 0.1f, -0.2f), to = from + Vector(speed * kDt, 0, 0);
            CollisionContact c;
            ASSERT_GT(probe(true, sps, from, to, kDt, &c), 0u) << speed << " m/s at " << sps << " samples/s";
            EXPECT_NEAR(c.normal.x, 1.0f, 1e-3f); // from the sphere (g1) toward the box
            EXPECT_GE(c.depth, 0.0f);
            if (speed > 10.0f) { // 10 m/s ends inside the box: a discrete contact at the current pose
                EXPECT_NEAR(c.pos.x, -0.5f, 1e-3f);           // where it first touched
                EXPECT_NEAR(c.depth, to.x - (-0.55f), 1e-2f); // how far it went on
            }
            // Grazing past the corner region misses, as it should.
            EXPECT_EQ(
                probe(true, sps, Vector(-0.6f, 0.56f, 0.56f), Vector(-0.6f + speed * kDt, 0.56f, 0.56f), kDt),
                0u);
            // The box moving instead of the sphere is the same relative motion.
            EXPECT_GT(probe(true, sps, from, to, kDt, nullptr, true), 0u);
        }
}

TEST(Continuous, SmallFastBoxIsSampledFinelyEnough) {
    for (float speed : {10.0f, 100.0f, 1000.0f})
        for (size_t sps : {size_t(30), size_t(60), size_t(240)}) {
            Vector from(-0.7f, 0.2f, 0.3f), to = from + Vector(speed * kDt, 0, 0);
            EXPECT_GT(probe(false, sps, from, to, kDt), 0u) << speed << " m/s at " << sps << " samples/s";
        }
}

TEST(Continuous, DiscreteWhenDeltaIsZeroInfiniteOrNoSampling) {
    Vector from(-0.6f, 0, 0), to(-0.6f + 100.0f * kDt, 0, 0);
    EXPECT_EQ(probe(true, 60, from, to, 0.0f), 0u);
    EXPECT_EQ(probe(true, 60, from, to, INFINITY), 0u);
    EXPECT_EQ(probe(true, 0, from, to, kDt), 0u);
    EXPECT_EQ(probe(false, 60, from - Vector(0.1f, 0, 0), to, 0.0f), 0u);
}

TEST(Continuous, NothingPassesThroughAPlane) {
    for (float speed : {10.0f, 100.0f, 1000.0f})
        for (float delta : {0.0f, kDt}) {
            iCollisionSpace* space = CreateSimpleCollisionSpace(60);
            DefaultSpace joins(space); // new geometry joins it
            UserBody s(Vector(0, 0.06f, 0)), b(Vector(2, 0.11f, 0));
            iCollisionGeometry* floor = CreateCPlane(nullptr, Vector(0, 1, 0), 0.0f);
            iCollisionGeometry* gs = CreateCSphere(&s, 0.05f);
            iCollisionGeometry* gb = CreateCOBB(&b, Vector(0.1f, 0.1f, 0.1f));
            for (iCollisionGeometry* g : {floor, gs, gb}) space->add(g);
            space->populateContactList(delta);
            ASSERT_EQ(space->getNumContacts(), 0u);
            s.place(Vector(0, 0.06f - speed * kDt, 0));
            b.place(Vector(2, 0.11f - speed * kDt, 0));
            space->populateContactList(delta);
            int sphere = 0, box = 0;
            for (size_t i = 0; i < space->getNumContacts(); ++i) {
                const CollisionContact& c = space->getContactList()[i];
                EXPECT_NEAR((c.g1 == floor ? c.normal : -c.normal).y, 1.0f, 1e-5f);
                sphere += c.g1 == gs || c.g2 == gs;
                box += c.g1 == gb || c.g2 == gb;
            }
            EXPECT_EQ(sphere, 1) << speed;
            EXPECT_GE(box, 1) << speed;
            for (iCollisionGeometry* g : {floor, gs, gb}) g->Delete();
            space->Delete();
        }
}

TEST(Continuous, SphereAgainstFastSphere) {
    iCollisionSpace* space = CreateSimpleCollisionSpace(60);
    DefaultSpace joins(space); // new geometry joins it
    UserBody a(Vector(-5, 0, 0)), b(Vector(0, 0, 0));
    iCollisionGeometry* ga = CreateCSphere(&a, 0.05f);
    iCollisionGeometry* gb = CreateCSphere(&b, 0.05f);
    space->add(ga);
    space->add(gb);
    space->populateContactList(kDt);
    a.place(Vector(5, 0.02f, 0)); // 600 m/s, passes 0.02 m off centre
    space->populateContactList(kDt);
    ASSERT_EQ(space->getNumContacts(), 1u);
    EXPECT_GT(space->getContactList()[0].normal.x, 0.9f);
    ga->Delete();
    gb->Delete();
    space->Delete();
}

TEST(Continuous, ASpinningPlankIsSampledThroughItsTurn) {
    // A 2 m plank, 4 cm thick, turns 90 degrees about z in one step. A small fixed box at 45 degrees is clear
    // of it at both ends of the step and inside its path halfway: slerp sampling finds it.
    iCollisionSpace* space = CreateSimpleCollisionSpace(60);
    DefaultSpace joins(space); // new geometry joins it
    UserBody plank(Vector(0, 0, 0)), post(Vector(0.42f, 0.42f, 0), PHYS_FixedInSpace);
    iCollisionGeometry* gp = CreateCOBB(&plank, Vector(1, 0.02f, 0.2f));
    iCollisionGeometry* gb = CreateCOBB(&post, Vector(0.1f, 0.1f, 0.1f));
    space->add(gp);
    space->add(gb);
    space->populateContactList(kDt);
    ASSERT_EQ(space->getNumContacts(), 0u);
    plank.place(Vector(), rotatez(1.5707963f));
    space->populateContactList(0.0f); // discrete: clear at the end pose too
    ASSERT_EQ(space->getNumContacts(), 0u);
    plank.place(Vector(), Matrix(1));
    space->populateContactList(kDt);
    plank.place(Vector(), rotatez(1.5707963f));
    space->populateContactList(kDt);
    EXPECT_GT(space->getNumContacts(), 0u);
    gp->Delete();
    gb->Delete();
    space->Delete();
}
