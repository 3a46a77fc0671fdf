// ContactEventsTest.cpp - collision filters and contact events in the collision package alone: layers,
// masks and sensors against brute force in both spaces (FilterDifferential.h), the octree space beside the
// simple one with filters, and contact events: no flicker across held calls, observers that go (destroyed
// without detaching: never called; under ASan a call would be a use-after-free), bodies and geometry that go.
#include "ErrorRecorder.h"
#include "FilterDifferential.h"
#include "iCollisionEvents.h"
#include "iCollisionListener.h"
#include "iOctreeCollisionSpace.h"
#include "iSimpleCollisionSpace.h"

#include <vector>

namespace {
using spacediff::Scene;
iCollisionSpace* makeSimple() { return CreateSimpleCollisionSpace(); }
iCollisionSpace* makeOctree() { return CreateOctreeCollisionSpace(); }

// Every call, in order: 'b', 'p' or 'e', with the pair.
struct Sequence final : ContactObserver {
    std::string kinds;
    std::vector<ContactPair> pairs;
    void onBegin(const ContactPair& p) override { add('b', p); }
    void onPersist(const ContactPair& p) override { add('p', p); }
    void onEnd(const ContactPair& p) override { add('e', p); }
    void add(char k, const ContactPair& p) {
        kinds += k;
        pairs.push_back(p);
    }
};

// Two unit spheres on the x axis: touching when their centres are under 2 m apart.
struct TwoBalls {
    iCollisionSpace* space = CreateSimpleCollisionSpace(0);
    UserBody a{Vector(0, 0, 0)}, b{Vector(1.5f, 0, 0)};
    iCollisionGeometry *ga, *gb;
    TwoBalls() {
        DefaultSpace joins(space);
        ga = CreateCSphere(&a, 1.0f);
        gb = CreateCSphere(&b, 1.0f);
    }
    ~TwoBalls() {
        if (ga) ga->Delete();
        if (gb) gb->Delete();
        if (space) space->Delete();
    }
    void at(float x) { b.getDynamics().position = Vector(x, 0, 0); }
};

// The same two touching spheres, the second one's body on the heap: a test deletes it (and sets b to
// nullptr).
struct BallAndMortalBall {
    iCollisionSpace* space = CreateSimpleCollisionSpace(0);
    DefaultSpace joins{space};
    UserBody a;
    UserBody* b = new UserBody(Vector(1.5f, 0, 0));
    iCollisionGeometry* ga = CreateCSphere(&a, 1.0f);
    iCollisionGeometry* gb = CreateCSphere(b, 1.0f);
    ~BallAndMortalBall() {
        ga->Delete();
        gb->Delete();
        delete b;
        space->Delete();
    }
};
} // namespace

TEST(ContactEvents, FiltersAndSensorsAgainstBruteForceSimple) {
    for (Scene scene : {Scene::Dense, Scene::Mixed, Scene::MostlyFixed})
        for (unsigned seed = 1; seed <= 3; ++seed)
            spacediff::checkFiltersAgainstBruteForce(makeSimple, scene, seed, 250);
}
TEST(ContactEvents, FiltersAndSensorsAgainstBruteForceOctree) {
    for (Scene scene : {Scene::Dense, Scene::Mixed, Scene::MostlyFixed})
        for (unsigned seed = 1; seed <= 3; ++seed)
            spacediff::checkFiltersAgainstBruteForce(makeOctree, scene, seed, 250);
}
TEST(ContactEvents, OctreeEqualsSimpleWithFilters) {
    for (Scene scene : {Scene::Sparse, Scene::Dense, Scene::Mixed})
        for (unsigned seed = 1; seed <= 2; ++seed)
            spacediff::checkAgainstReference(makeOctree, makeSimple, scene, seed, 150, 40, true);
}

// Layer rule on one pair, both ways round: a mask that leaves out the other's layer on either side is enough.
TEST(ContactEvents, LayerRuleNeedsBothSides) {
    TwoBalls t;
    iCollisionFilter *fa = filterOf(t.ga), *fb = filterOf(t.gb);
    ASSERT_TRUE(fa && fb);
    EXPECT_EQ(fa->getLayer(), 1u);
    EXPECT_EQ(fa->getMask(), 0xFFFFFFFFu);
    fa->setLayer(2);
    fb->setLayer(4);
    for (std::uint32_t maskA : {0u, 4u, 0xFFu})
        for (std::uint32_t maskB : {0u, 2u, 0xFFu}) {
            fa->setMask(maskA);
            fb->setMask(maskB);
            t.space->populateContactList(0);
            EXPECT_EQ(t.space->getNumContacts() > 0, (maskA & 4u) != 0 && (maskB & 2u) != 0)
                << maskA << " " << maskB;
        }
}

// A clone filters as its original.
TEST(ContactEvents, CloneKeepsTheFilter) {
    TwoBalls t;
    filterOf(t.ga)->setLayer(8);
    filterOf(t.ga)->setMask(3);
    filterOf(t.ga)->setSensor(true);
    DefaultSpace joins(t.space);
    iCollisionGeometry* c = t.ga->clone();
    EXPECT_EQ(filterOf(c)->getLayer(), 8u);
    EXPECT_EQ(filterOf(c)->getMask(), 3u);
    EXPECT_TRUE(filterOf(c)->isSensor());
    c->Delete();
}

// Events held over several calls (a scene's steps) and delivered once: a pair counts as touching when it
// touched in any call since the last delivery, so a touch inside a frame is one begin, then one end.
TEST(ContactEvents, HeldCallsDoNotFlicker) {
    TwoBalls t;
    Sequence seq;
    ASSERT_TRUE(contactEventsOf(t.space)->addObserver(&seq));
    iCollisionEvents* ev = eventsOf(t.space);
    ev->holdEvents(true);
    auto frame = [&](std::initializer_list<float> xs) {
        seq.kinds.clear();
        for (float x : xs) {
            t.at(x);
            t.space->populateContactList(1.0f / 180.0f);
        }
        ev->deliverEvents();
        return seq.kinds;
    };
    EXPECT_EQ(frame({3, 3, 3}), "");
    EXPECT_EQ(frame({3, 1.9f, 3}), "b"); // touched in the middle call only
    EXPECT_EQ(frame({3, 3, 3}), "e");
    EXPECT_EQ(frame({1.9f, 2.5f, 1.9f}), "b"); // apart in the middle: still one pair, no end
    EXPECT_EQ(frame({1.9f, 1.8f, 1.7f}), "p");
    EXPECT_EQ(frame({}), "p"); // an update without a step: still touching
    EXPECT_EQ(frame({3}), "e");
    contactEventsOf(t.space)->removeObserver(&seq);
}

// The observer destroyed without removeObserver is never called again: its destructor detached it. It had
// heard onBegin, so it was attached and the pair goes on touching (the kept observer hears onPersist).
TEST(ContactEvents, ObserverDestroyedWithoutDetachingIsNeverCalled) {
    TwoBalls t;
    Sequence kept;
    auto* doomed = new Sequence;
    contactEventsOf(t.space)->addObserver(&kept);
    contactEventsOf(t.space)->addObserver(doomed);
    t.space->populateContactList(0);
    EXPECT_EQ(doomed->kinds, "b");
    delete doomed; // no removeObserver
    t.space->populateContactList(0);
    t.at(3);
    t.space->populateContactList(0);
    EXPECT_EQ(kept.kinds, "bpe");
    EXPECT_TRUE(contactEventsOf(t.space)->removeObserver(&kept));
}

// A space deleted first detaches its observers: the observer's destructor later does not reach it.
TEST(ContactEvents, ObserverOutlivesItsSpace) {
    auto* seq = new Sequence;
    {
        TwoBalls t;
        contactEventsOf(t.space)->addObserver(seq);
        t.space->populateContactList(0);
        t.ga->Delete();
        t.gb->Delete();
        t.ga = t.gb = nullptr;
        t.space->Delete();
        t.space = nullptr;
    }
    EXPECT_EQ(seq->kinds, "b");
    delete seq; // under ASan: a use-after-free if it still named the space
}

// An observer that destroys itself, and one that deletes a geometry, during a call: safe; the other
// observer still hears the call; the deleted geometry's pair ends at the next delivery, naming it nullptr.
TEST(ContactEvents, ObserversMayDeleteThemselvesAndGeometry) {
    TwoBalls t;
    struct SelfDestruct final : ContactObserver {
        void onBegin(const ContactPair&) override { delete this; }
    };
    struct DeletesB final : ContactObserver {
        iCollisionGeometry** g;
        void onBegin(const ContactPair&) override {
            (*g)->Delete();
            *g = nullptr;
        }
    };
    Sequence seq;
    DeletesB deleter;
    deleter.g = &t.gb;
    contactEventsOf(t.space)->addObserver(new SelfDestruct);
    contactEventsOf(t.space)->addObserver(&deleter);
    contactEventsOf(t.space)->addObserver(&seq);
    t.space->populateContactList(0);
    EXPECT_EQ(seq.kinds, "b");
    t.space->populateContactList(0);
    ASSERT_EQ(seq.kinds, "be");
    const ContactPair& end = seq.pairs[1];
    EXPECT_TRUE((end.geometryA == nullptr) != (end.geometryB == nullptr)); // b's geometry left, a's did not
    EXPECT_TRUE(end.bodyA == &t.b || end.bodyB == &t.b);                   // the body is still alive
    contactEventsOf(t.space)->removeObserver(&deleter);
    contactEventsOf(t.space)->removeObserver(&seq);
}

// A body destroyed while touching: its pair ends with that body named nullptr.
TEST(ContactEvents, DestroyedBodyEndsItsPair) {
    BallAndMortalBall t;
    Sequence seq;
    contactEventsOf(t.space)->addObserver(&seq);
    t.space->populateContactList(0);
    delete t.b;
    t.b = nullptr;
    t.space->populateContactList(0);
    ASSERT_EQ(seq.kinds, "be");
    EXPECT_TRUE((seq.pairs[1].bodyA == nullptr) != (seq.pairs[1].bodyB == nullptr));
    EXPECT_TRUE(seq.pairs[1].bodyA == &t.a || seq.pairs[1].bodyB == &t.a);
    contactEventsOf(t.space)->removeObserver(&seq);
}

// A body deleted by a HitWall listener, in the call whose contact events follow the listeners: that
// delivery never hands the observer the dead body (it ends the pair naming it nullptr, at the next call), and
// a new body made at once in its place (perhaps at its address) begins a pair of its own.
TEST(ContactEvents, BodyDeletedByAListenerIsNeverHandedToAnObserver) {
    BallAndMortalBall t;
    Sequence seq;
    contactEventsOf(t.space)->addObserver(&seq);
    t.space->populateContactList(0); // begins
    struct Deleter final : iCollisionListener {
        UserBody** body;
        void HitWall(iRigidBody*, Vector, Vector) override {
            delete *body;
            *body = nullptr;
        }
    } deleter;
    deleter.body = &t.b;
    const iRigidBody* dead = t.b;
    const size_t before = seq.pairs.size();
    t.a.attachListener(&deleter);
    t.space->populateContactList(0); // the listener deletes b before this call's events are delivered
    t.a.detachListener(&deleter);
    ASSERT_EQ(t.b, nullptr);
    for (size_t i = before; i < seq.pairs.size(); ++i) // handed after b died: never b
        EXPECT_TRUE(seq.pairs[i].bodyA != dead && seq.pairs[i].bodyB != dead) << seq.kinds;
    t.b = new UserBody(Vector(1.5f, 0, 0)); // in b's place (the allocator may give it b's address)
    t.gb->Delete();
    t.gb = CreateCSphere(t.b, 1.0f);
    t.space->populateContactList(0);
    ASSERT_GE(seq.kinds.size(), 3u);
    EXPECT_EQ(seq.kinds.substr(seq.kinds.size() - 2), "eb")
        << seq.kinds; // b's pair ends, the new one's begins
    const ContactPair& end = seq.pairs[seq.pairs.size() - 2];
    EXPECT_TRUE((end.bodyA == nullptr) != (end.bodyB == nullptr));
    const ContactPair& begin = seq.pairs.back();
    EXPECT_TRUE(begin.bodyA == t.b || begin.bodyB == t.b);
    contactEventsOf(t.space)->removeObserver(&seq);
}

// An observer that deletes a body during a delivery: the calls after it in that delivery do not name it.
TEST(ContactEvents, BodyDeletedByAnObserverIsNotNamedLaterInThatDelivery) {
    BallAndMortalBall t;
    struct DeletesB final : ContactObserver {
        UserBody** body;
        void onBegin(const ContactPair&) override {
            delete *body;
            *body = nullptr;
        }
    } deleter;
    deleter.body = &t.b;
    const iRigidBody* dead = t.b;
    Sequence after; // attached after the deleter: hears the same begin, after b died
    contactEventsOf(t.space)->addObserver(&deleter);
    contactEventsOf(t.space)->addObserver(&after);
    t.space->populateContactList(0);
    ASSERT_EQ(t.b, nullptr);
    ASSERT_EQ(after.kinds, "b");
    EXPECT_TRUE(after.pairs[0].bodyA != dead && after.pairs[0].bodyB != dead);
    contactEventsOf(t.space)->removeObserver(&deleter);
    contactEventsOf(t.space)->removeObserver(&after);
}

// An observer attached while a pair touches hears onBegin first, then what the others hear.
TEST(ContactEvents, LateObserverHearsBeginFirst) {
    TwoBalls t;
    Sequence early, late;
    contactEventsOf(t.space)->addObserver(&early);
    t.space->populateContactList(0);
    contactEventsOf(t.space)->addObserver(&late);
    t.space->populateContactList(0);
    t.at(3);
    t.space->populateContactList(0);
    EXPECT_EQ(early.kinds, "bpe");
    EXPECT_EQ(late.kinds, "be");
}

TEST(ContactEvents, BadObserversRefused) {
    TwoBalls t;
    guardian_test::ErrorRecorder errors;
    Sequence seq;
    EXPECT_FALSE(contactEventsOf(t.space)->addObserver(nullptr));
    EXPECT_TRUE(contactEventsOf(t.space)->addObserver(&seq));
    EXPECT_FALSE(contactEventsOf(t.space)->addObserver(&seq));
    EXPECT_EQ(errors.count(), 2u);
    EXPECT_TRUE(contactEventsOf(t.space)->removeObserver(&seq));
    EXPECT_FALSE(contactEventsOf(t.space)->removeObserver(&seq));
}
