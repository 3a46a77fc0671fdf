// SetupOrderTest.cpp - whole scenes set up out of the seed's order (scene, then space, then geometry), and a
// game's own iRigidBody among simulated bodies.
#include "../collision/UserBody.h"
#include "SceneFixture.h"
#include "iCOBB.h"
#include "iCSphere.h"
#include "iCollisionSpace.h"
#include "iUtilities.h"

#include <gtest/gtest.h>

using resolution_test::SceneFixture;

namespace {
void quiet(const wchar_t*) {}
} // namespace

// A ball's geometry made before the space exists joins none (it would fall through the floor): that is
// reported at creation. Added to the space explicitly, the ball (radius 0.5) comes to rest on the ground:
// centre at y = 0.5, within 1 cm.
TEST(SetupOrder, GeometryMadeBeforeTheSpaceIsReportedAndRestsOnceAdded) {
    ErrorHandler previous = setErrorHandler(&quiet);
    iPhysicsScene* scene = CreatePhysicsScene(nullptr);
    scene->update(0);
    setDefaultCollisionSpace(nullptr);
    iPhysicsFrame* ball = CreatePhysicsFrame();
    ball->getDynamics()->position = Vector(0, 2, 0);
    unsigned long errors = errorCount();
    iCollisionGeometry* shape = CreateCSphere(ball->getRB(), 0.5f);
    EXPECT_EQ(errorCount(), errors + 1);
    EXPECT_EQ(shape->getSpace(), nullptr);
    {
        World world(scene); // the space, now the scene's and the default
        world.ground(0.0f);
        EXPECT_TRUE(world.space()->add(shape));
        for (int now = 16; now <= 3000; now += 16) scene->update(now);
        EXPECT_NEAR(ball->getDynamics()->position.y, 0.5f, 0.01f);
        EXPECT_EQ(errorCount(), errors + 1);
        shape->Delete();
    }
    ball->Delete();
    scene->Delete();
    setErrorHandler(previous);
}

// The scene refuses a game's own iRigidBody (it cannot integrate what it did not make), but the body's
// geometry in the scene's space is an immovable obstacle: a ball (radius 0.5) dropped on a game-owned box
// (top at y = 1) comes to rest on it, its centre at y = 1.5 within 1 cm, and the box does not move.
TEST(SetupOrder, SimulatedBallRestsOnAGameOwnedBox) {
    ErrorHandler previous = setErrorHandler(&quiet);
    {
        SceneFixture f;
        UserBody box(Vector(0, 0.5f, 0));
        iCollisionGeometry* boxShape = CreateCOBB(&box, Vector(1, 0.5f, 1));
        ASSERT_EQ(boxShape->getSpace(), f.world->space());
        unsigned long errors = errorCount();
        EXPECT_FALSE(f.scene->add(&box));
        EXPECT_EQ(errorCount(), errors + 1);
        RBDynamics* ball = f.world->sphere(Vector(0, 3, 0), 0.5f, 1.0f)->getDynamics();
        float lowest = 3.0f;
        f.seconds(3.0f, [&] { lowest = std::fmin(lowest, ball->position.y); });
        EXPECT_NEAR(ball->position.y, 1.5f, 0.01f);
        // It lands at sqrt(2 g 1.5) = 5.4 m/s: the step that finds the contact may carry it up to v dt = 9 cm
        // in, never through.
        EXPECT_GT(lowest, 1.5f - std::sqrt(2 * resolution_test::kG * 1.5f) / 60);
        EXPECT_LT(ball->velocity.length(), 0.01f);
        EXPECT_EQ(box.getDynamics().position, Vector(0, 0.5f, 0));
        EXPECT_EQ(box.getDynamics().velocity, Vector());
        EXPECT_EQ(box.getDynamics().orientation, Matrix(1));
        boxShape->Delete();
    }
    setErrorHandler(previous);
}
