// SetupOrderTest.cpp - a geometry made while no default collision space is set joins no space: each factory
// reports it with error() at once, and the geometry still works once added to a space explicitly.
#include "UserBody.h"
#include "iCCompound.h"
#include "iCOBB.h"
#include "iCPlane.h"
#include "iCSphere.h"
#include "iCollisionSpace.h"
#include "iSimpleCollisionSpace.h"
#include "iUtilities.h"

#include <gtest/gtest.h>

namespace {
void quiet(const wchar_t*) {}
} // namespace

// Sphere (radius 1) at the origin, box (half size 1) at x = 1.5: the box's face is at x = 0.5, so they
// overlap by 0.5 m along +x.
TEST(SetupOrder, GeometryMadeWithoutADefaultSpaceIsReportedAndCanBeAddedLater) {
    ErrorHandler previous = setErrorHandler(&quiet);
    setDefaultCollisionSpace(nullptr);
    UserBody a(Vector(0, 0, 0)), b(Vector(1.5f, 0, 0));
    unsigned long errors = errorCount();
    iCollisionGeometry* sphere = CreateCSphere(&a, 1.0f);
    EXPECT_EQ(errorCount(), errors + 1);
    iCollisionGeometry* box = CreateCOBB(&b, Vector(1, 1, 1));
    EXPECT_EQ(errorCount(), errors + 2);
    iCollisionGeometry* plane = CreateCPlane(nullptr, Vector(0, 1, 0), -5.0f);
    EXPECT_EQ(errorCount(), errors + 3);
    iCollisionGeometry* compound = CreateCCompound(&a);
    EXPECT_EQ(errorCount(), errors + 4);
    for (iCollisionGeometry* g : {sphere, box, plane, compound}) EXPECT_EQ(g->getSpace(), nullptr);

    iCollisionSpace* space = CreateSimpleCollisionSpace();
    EXPECT_TRUE(space->add(sphere));
    EXPECT_TRUE(space->add(box));
    space->populateContactList(0);
    ASSERT_EQ(space->getNumContacts(), 1u);
    EXPECT_NEAR(space->getContactList()[0].depth, 0.5f, 1e-5f);
    EXPECT_NEAR(space->getContactList()[0].normal.x, 1.0f, 1e-6f);

    // With a default space set, the factories join it and report nothing; a bodiless geometry is legal.
    setDefaultCollisionSpace(space);
    iCollisionGeometry* joined = CreateCSphere(nullptr, 1.0f);
    EXPECT_EQ(joined->getSpace(), space);
    EXPECT_EQ(errorCount(), errors + 4);

    for (iCollisionGeometry* g : {sphere, box, plane, compound, joined}) g->Delete();
    setDefaultCollisionSpace(nullptr);
    space->Delete();
    setErrorHandler(previous);
}
