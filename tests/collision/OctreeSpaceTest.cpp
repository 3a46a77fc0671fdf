// OctreeSpaceTest.cpp - what the octree space keeps between calls: with nothing moved a call makes no tree
// query and gives the same contacts in the same order; a body that stays inside its fat box makes none
// either; one that leaves it makes exactly one; pairs are dropped once the fat boxes part. The counter is
// the internal TreeBroadphase's, reached through the space's class (a test-only path).
#include "DefaultSpace.h"
#include "SimpleCollisionSpace.h"
#include "TreeBroadphase.h"
#include "UserBody.h"
#include "iCOBB.h"
#include "iCSphere.h"
#include "iOctreeCollisionSpace.h"

#include <gtest/gtest.h>

#include <memory>
#include <vector>

namespace {

TreeBroadphase& treeOf(iCollisionSpace* space) {
    return dynamic_cast<TreeBroadphase&>(dynamic_cast<SimpleCollisionSpace*>(space)->broadphase());
}

std::vector<CollisionContact> contactsOf(iCollisionSpace* space) {
    const CollisionContact* c = space->getContactList();
    return std::vector<CollisionContact>(c, c + space->getNumContacts());
}

bool same(const std::vector<CollisionContact>& a, const std::vector<CollisionContact>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (a[i].g1 != b[i].g1 || a[i].g2 != b[i].g2 || a[i].pos != b[i].pos || a[i].normal != b[i].normal ||
            a[i].depth != b[i].depth)
            return false;
    return true;
}

struct Grid {
    iCollisionSpace* space = CreateOctreeCollisionSpace();
    std::vector<std::unique_ptr<UserBody>> bodies;
    std::vector<iCollisionGeometry*> geoms;
    explicit Grid(int n) {
        DefaultSpace joins(space);
        for (int i = 0; i < n; ++i) { // a 10 x 10 x n/100 lattice 0.9 m apart: each touches its neighbours
            bodies.emplace_back(
                new UserBody(Vector(float(i % 10) * 0.9f, float(i / 10 % 10) * 0.9f, float(i / 100) * 0.9f)));
            geoms.push_back(i % 2 ? static_cast<iCollisionGeometry*>(CreateCSphere(bodies.back().get(), 0.5f))
                                  : CreateCOBB(bodies.back().get(), Vector(0.5f, 0.5f, 0.5f)));
        }
    }
    ~Grid() {
        for (iCollisionGeometry* g : geoms) g->Delete();
        space->Delete();
    }
};

} // namespace

TEST(OctreeSpace, NothingMovedMeansNoTreeQueryAndTheSameContacts) {
    Grid grid(1000);
    grid.space->populateContactList(1.0f / 60.0f);
    const std::vector<CollisionContact> first = contactsOf(grid.space);
    ASSERT_GT(first.size(), 1000u);
    const size_t queries = treeOf(grid.space).treeQueries();
    EXPECT_EQ(queries, 1000u); // each new proxy looked once
    for (int k = 0; k < 3; ++k) {
        grid.space->populateContactList(1.0f / 60.0f);
        EXPECT_EQ(treeOf(grid.space).treeQueries(), queries);
        EXPECT_TRUE(same(contactsOf(grid.space), first)) << "call " << k;
    }
}

TEST(OctreeSpace, OnlyABodyThatLeftItsFatBoxQueriesTheTree) {
    Grid grid(500);
    grid.space->populateContactList(1.0f / 60.0f);
    size_t queries = treeOf(grid.space).treeQueries();
    // Within the margin: no query.
    grid.bodies[17]->getDynamics().position.y += 0.5f * TreeBroadphase::kMargin;
    grid.space->populateContactList(1.0f / 60.0f);
    EXPECT_EQ(treeOf(grid.space).treeQueries(), queries);
    // Out of it: that proxy alone.
    grid.bodies[17]->getDynamics().position.y += 2.0f * TreeBroadphase::kMargin;
    grid.space->populateContactList(1.0f / 60.0f);
    EXPECT_EQ(treeOf(grid.space).treeQueries(), queries + 1);
    EXPECT_TRUE(treeOf(grid.space).tree().valid());
}

TEST(OctreeSpace, APairIsDroppedOnceTheFatBoxesPart) {
    iCollisionSpace* space = CreateOctreeCollisionSpace();
    DefaultSpace joins(space);
    UserBody a(Vector(0, 0, 0)), b(Vector(0.9f, 0, 0));
    iCollisionGeometry* ga = CreateCSphere(&a, 0.5f);
    iCollisionGeometry* gb = CreateCSphere(&b, 0.5f);
    space->populateContactList(0.0f);
    EXPECT_EQ(space->getNumContacts(), 1u);
    EXPECT_EQ(treeOf(space).pairCount(), 1u);
    b.getDynamics().position.x = 1.05f; // apart, fat boxes still overlapping: the pair is kept, no contact
    space->populateContactList(0.0f);
    EXPECT_EQ(space->getNumContacts(), 0u);
    EXPECT_EQ(treeOf(space).pairCount(), 1u);
    b.getDynamics().position.x = 10.0f;
    space->populateContactList(0.0f);
    EXPECT_EQ(space->getNumContacts(), 0u);
    EXPECT_EQ(treeOf(space).pairCount(), 0u);
    gb->Delete(); // leaves: its proxy goes, and a new geometry reuses the slot without inheriting a pair
    iCollisionGeometry* gc = CreateCSphere(&b, 0.5f);
    b.getDynamics().position.x = 0.5f;
    space->populateContactList(0.0f);
    EXPECT_EQ(space->getNumContacts(), 1u);
    EXPECT_EQ(treeOf(space).tree().leafCount(), 2);
    ga->Delete();
    gc->Delete();
    space->Delete();
}
