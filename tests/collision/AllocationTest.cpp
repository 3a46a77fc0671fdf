// AllocationTest.cpp - after warm-up, populateContactList does not allocate, in the simple space and in the
// octree space (whose tree nodes, proxies and pair set are reused): the contact list, the working arrays and
// the listener snapshot keep their storage between calls. Counted by the test program's
// counting operator new (tests/CountingNew.h).
#include "CountingNew.h"
#include "DefaultSpace.h"
#include "UserBody.h"
#include "iCOBB.h"
#include "iCSphere.h"
#include "iCollisionListener.h"
#include "iCollisionSpace.h"
#include "iOctreeCollisionSpace.h"
#include "iSimpleCollisionSpace.h"

#include <gtest/gtest.h>

#include <memory>
#include <vector>

namespace {
struct Counter final : iCollisionListener {
    int hits = 0;
    void HitWall(iRigidBody*, Vector, Vector) override { ++hits; }
};
} // namespace

namespace {

void populateDoesNotAllocateAfterWarmUp(iCollisionSpace* space) {
    DefaultSpace joins(space); // new geometry joins it
    std::vector<std::unique_ptr<UserBody>> bodies;
    std::vector<iCollisionGeometry*> geoms;
    Counter counter;
    for (int i = 0; i < 200; ++i) {
        bodies.emplace_back(
            new UserBody(Vector(float(i % 10) * 0.9f, float(i / 10 % 10) * 0.9f, float(i / 100) * 0.9f)));
        bodies.back()->attachListener(&counter);
        iCollisionGeometry* g = i % 2 ? CreateCSphere(bodies.back().get(), 0.5f)
                                      : CreateCOBB(bodies.back().get(), Vector(0.5f, 0.5f, 0.5f));
        space->add(g);
        geoms.push_back(g);
    }
    // Every body jumps back and forth: the sampled and swept paths run too.
    auto step = [&](int k) {
        for (size_t i = 0; i < bodies.size(); ++i)
            bodies[i]->getDynamics().position.x += (i % 2 ? 0.6f : -0.6f) * (k % 2 ? 1.0f : -1.0f);
        space->populateContactList(1.0f / 60.0f);
    };
    for (int k = 0; k < 4; ++k) step(k);
    ASSERT_GT(space->getNumContacts(), 0u);
    long before = guardian_test::allocationCount();
    ASSERT_GT(before, 0) << "the counting operator new is in use";
    for (int k = 4; k < 14; ++k) step(k);
    long during = guardian_test::allocationCount() - before;
    EXPECT_EQ(during, 0);
    EXPECT_GT(counter.hits, 0);
    for (iCollisionGeometry* g : geoms) g->Delete();
    space->Delete();
}

} // namespace

TEST(Allocation, PopulateDoesNotAllocateAfterWarmUp) {
    populateDoesNotAllocateAfterWarmUp(CreateSimpleCollisionSpace(60));
}
TEST(Allocation, OctreePopulateDoesNotAllocateAfterWarmUp) {
    populateDoesNotAllocateAfterWarmUp(CreateOctreeCollisionSpace(60));
}
