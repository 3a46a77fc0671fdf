// GatherReadsTest.cpp - what a space's call reads of the bodies (SpaceGather.cpp): a geometry that kept its
// body since the last call reads that body's dynamics through the pointer found then, without asking the body
// (a cache line a geometry in a large scene); a geometry bound anew asks again, even when the new body lies
// at the dead one's address with its dynamics elsewhere in it.
#include "DefaultSpace.h"
#include "UserBody.h"
#include "iCOBB.h"
#include "iOctreeCollisionSpace.h"
#include "iSimpleCollisionSpace.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <new>
#include <vector>

namespace {

using MakeSpace = iCollisionSpace* (*)();
iCollisionSpace* readsSimpleSpace() { return CreateSimpleCollisionSpace(); }
iCollisionSpace* readsOctreeSpace() { return CreateOctreeCollisionSpace(); }

// A row of unit boxes 3 m apart, each touching none; and one more overlapping the first by 0.1 m.
void stillCallAsksNoBody(MakeSpace make) {
    iCollisionSpace* space = make();
    std::vector<UserBody*> bodies;
    std::vector<iCollisionGeometry*> boxes;
    {
        DefaultSpace joins(space);
        for (int i = 0; i < 20; ++i) {
            bodies.push_back(new UserBody(Vector(3.0f * float(i), 0, 0)));
            boxes.push_back(CreateCOBB(bodies.back(), Vector(0.5f, 0.5f, 0.5f)));
        }
        bodies.push_back(new UserBody(Vector(0.9f, 0, 0)));
        boxes.push_back(CreateCOBB(bodies.back(), Vector(0.5f, 0.5f, 0.5f)));
    }
    space->populateContactList(0.0f);
    const size_t touching = space->getNumContacts();
    ASSERT_GT(touching, 0u); // the last box overlaps the first by 0.1 m
    UserBody::reads = 0;
    space->populateContactList(0.0f);
    EXPECT_EQ(UserBody::reads, 0u) << "a call where no geometry changed body asked a body for its dynamics";
    EXPECT_EQ(space->getNumContacts(), touching);
    // The pose is still read every call, through the kept pointer: a box moved away stops touching.
    bodies.back()->place(Vector(0.0f, 5.0f, 0));
    space->populateContactList(0.0f);
    EXPECT_EQ(space->getNumContacts(), 0u);
    EXPECT_EQ(UserBody::reads, 0u);
    for (iCollisionGeometry* g : boxes) g->Delete();
    for (UserBody* b : bodies) b->Delete();
    space->Delete();
}

// A game's body whose dynamics lie 512 bytes into it (UserBody's lie near its start).
class PaddedBody final : public iRigidBody {
public:
    explicit PaddedBody(const Vector& position) { m_dynamics.position = position; }
    ~PaddedBody() { rigidBodyDestroyed(this); }
    iRigidBody* clone() const override { return nullptr; }
    void attach(iFrame*) override {}
    void attachListener(iCollisionListener*) override {}
    void detachListener(const iCollisionListener*) override {}
    void restore(int) override {}
    std::vector<iCollisionListener*>& getListeners() override { return m_listeners; }
    iFrame* getFrame() override { return nullptr; }
    RBDynamics& getDynamics() override { return m_dynamics; }
    const RBDynamics& getDynamics() const override { return m_dynamics; }
    void setDynamics(const RBDynamics& d) override { m_dynamics = d; }
    void reset(int) override {}
    void suspend() const override {}
    void release() const override {}
    void Delete() const override {}
    unsigned char padding[512] = {}; // (public: nothing reads it)

private:
    RBDynamics m_dynamics;
    std::vector<iCollisionListener*> m_listeners;
};

// A box bound to a body that dies; a body of another class is built at the same address, far away, and the
// box bound to it: the call must read the new body's pose, not the old body's place in memory (which now
// holds the new body's padding, or its dynamics' old values).
void bodyAtTheSameAddressIsReadAfresh(MakeSpace make) {
    iCollisionSpace* space = make();
    alignas(64) static unsigned char storage[sizeof(UserBody) + sizeof(PaddedBody)];
    UserBody* first = new (storage) UserBody(Vector(0, 0, 0));
    UserBody* ground = new UserBody(Vector(0.9f, 0, 0));
    iCollisionGeometry *box, *other;
    {
        DefaultSpace joins(space);
        box = CreateCOBB(first, Vector(0.5f, 0.5f, 0.5f));
        other = CreateCOBB(ground, Vector(0.5f, 0.5f, 0.5f));
    }
    space->populateContactList(0.0f);
    ASSERT_GT(space->getNumContacts(), 0u);
    iRigidBody* const firstBody = first;
    first->~UserBody(); // tells the spaces (rigidBodyDestroyed): the box is unbound
    PaddedBody* second = new (storage) PaddedBody(Vector(50.0f, 0, 0));
    ASSERT_EQ(static_cast<iRigidBody*>(second), firstBody)
        << "the test needs the second body at the first one's address";
    box->attach(second);
    space->populateContactList(0.0f);
    EXPECT_EQ(space->getNumContacts(), 0u) << "the box was posed from the dead body's dynamics";
    second->getDynamics().position = Vector(0.2f, 0, 0); // back onto the other box
    space->populateContactList(0.0f);
    EXPECT_GT(space->getNumContacts(), 0u);
    box->Delete();
    other->Delete();
    second->~PaddedBody();
    ground->Delete();
    space->Delete();
}

} // namespace

TEST(GatherReads, SimpleSpaceStillCallAsksNoBody) { stillCallAsksNoBody(readsSimpleSpace); }
TEST(GatherReads, OctreeSpaceStillCallAsksNoBody) { stillCallAsksNoBody(readsOctreeSpace); }
TEST(GatherReads, SimpleSpaceReadsABodyBuiltAtTheSameAddressAfresh) {
    bodyAtTheSameAddressIsReadAfresh(readsSimpleSpace);
}
TEST(GatherReads, OctreeSpaceReadsABodyBuiltAtTheSameAddressAfresh) {
    bodyAtTheSameAddressIsReadAfresh(readsOctreeSpace);
}
