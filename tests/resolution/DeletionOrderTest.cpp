// DeletionOrderTest.cpp - collision spaces and geometries deleted before (or while) the scene uses them: the
// scene forgets a deleted space (collisionSpaceDestroyed, iCollisionSpace.h) and reads the contact list again
// after its force generators ran. Under ASan each test failed in af411e1 (a use-after-free at
// PhysicsScene.cpp:302 or in the contact resolution) and passes now.
#include "iCSphere.h"
#include "iCollisionListener.h"
#include "iCollisionSpace.h"
#include "iForceGenerator.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneHooks.h"
#include "iPhysicsSceneSettings.h"
#include "iRigidBody.h"
#include "iSimpleCollisionSpace.h"
#include "iUtilities.h"

#include <gtest/gtest.h>

#include <functional>

namespace {

struct Once final : iForceGenerator {
    std::function<void()> fn;
    int calls = 0;
    void addForces(const iRigidBody*, const RigidBodyState&, Vector&, Vector&) override {
        if (calls++ == 0) fn();
    }
};

// Two unit spheres 1.5 m apart along x, at rest, no gravity: they overlap by 0.5 m and only contact
// resolution can move them apart.
struct Overlap {
    iPhysicsScene* scene = CreatePhysicsScene(nullptr);
    iCollisionSpace* space = CreateSimpleCollisionSpace(0);
    iRigidBody* a;
    iRigidBody* b;
    iCollisionGeometry* ga;
    iCollisionGeometry* gb;
    Overlap() {
        settingsOf(scene)->setGravity(Vector());
        scene->setNewGlobalCollisionSpace(space);
        a = CreateRigidBody(nullptr);
        b = CreateRigidBody(nullptr);
        a->getDynamics().position = Vector(0, 0, 0);
        b->getDynamics().position = Vector(1.5f, 0, 0);
        ga = CreateCSphere(a, 1.0f);
        gb = CreateCSphere(b, 1.0f);
        scene->update(0);
    }
    float gap() const { return b->getDynamics().position.x - a->getDynamics().position.x; }
};

} // namespace

// PhysicsScene.cpp:302 (af411e1): the space deleted before the scene that collides in it.
TEST(DeletionOrder, SpaceDeletedBeforeTheScene) {
    Overlap o;
    o.space->Delete(); // the geometries leave it and stay usable; the scene forgets it
    o.scene->update(100);
    EXPECT_FLOAT_EQ(o.gap(), 1.5f); // no space: no contacts, nothing pushed them apart
    EXPECT_EQ(o.ga->getSpace(), nullptr);
    // A new space works as before: the overlap is resolved.
    iCollisionSpace* fresh = CreateSimpleCollisionSpace(0);
    o.scene->setNewGlobalCollisionSpace(fresh);
    fresh->add(o.ga);
    fresh->add(o.gb);
    o.scene->update(1000);
    // The soft push out (capped at 3 m/s) has taken most of the 0.5 m overlap away in 0.9 s.
    EXPECT_GT(o.gap(), 1.8f);
    o.scene->Delete();
    fresh->Delete();
    o.ga->Delete();
    o.gb->Delete();
}

// A force generator deletes the space after the step gathered its contacts: the contacts went with it and
// are not resolved (the same step's contacts are never read from freed memory).
TEST(DeletionOrder, ForceGeneratorDeletesTheSpaceMidStep) {
    Overlap o;
    Once gen;
    gen.fn = [&] { o.space->Delete(); };
    ASSERT_TRUE(hooksOf(o.scene)->addForceGenerator(o.a, &gen));
    o.scene->update(17); // one step
    EXPECT_EQ(gen.calls > 0, true);
    EXPECT_FLOAT_EQ(o.gap(), 1.5f);
    o.scene->Delete();
    o.ga->Delete();
    o.gb->Delete();
}

// A force generator deletes a geometry that is in this step's contact list: the space drops its contacts and
// the scene resolves what is left (nothing here).
TEST(DeletionOrder, ForceGeneratorDeletesAGeometryInContact) {
    Overlap o;
    Once gen;
    gen.fn = [&] {
        o.gb->Delete();
        EXPECT_EQ(o.space->getNumContacts(), 0u);
    };
    ASSERT_TRUE(hooksOf(o.scene)->addForceGenerator(o.a, &gen));
    o.scene->update(17);
    EXPECT_GT(gen.calls, 0);
    EXPECT_FLOAT_EQ(o.gap(), 1.5f);
    o.scene->Delete();
    o.ga->Delete();
    o.space->Delete();
}

// Found by the fuzzer (seeds 1000..): a listener, called while the scene's step gathered contacts, set the
// scene's space to nullptr; the step then read the contact list through the null pointer. (Listeners now hear
// HitWall after the steps; a space without iCollisionEvents still calls them mid-step.)
TEST(DeletionOrder, ListenerClearsTheScenesSpaceMidStep) {
    struct Clearer final : iCollisionListener {
        iPhysicsScene* scene = nullptr;
        int calls = 0;
        void HitWall(iRigidBody*, Vector, Vector) override {
            ++calls;
            scene->setNewGlobalCollisionSpace(nullptr);
        }
    } clearer;
    Overlap o;
    clearer.scene = o.scene;
    o.a->attachListener(&clearer);
    // One step: the overlap is resolved a little; after the step the listener hears of it (HitWall comes once
    // a frame, after the steps) and clears the space.
    o.scene->update(17);
    EXPECT_EQ(clearer.calls, 1);
    const float after = o.gap();
    EXPECT_GT(after, 1.5f);
    o.scene->update(100); // no space: nothing more happens (the push out leaves no velocity)
    EXPECT_EQ(clearer.calls, 1);
    EXPECT_FLOAT_EQ(o.gap(), after);
    o.scene->Delete();
    o.ga->Delete();
    o.gb->Delete();
    o.space->Delete();
}
