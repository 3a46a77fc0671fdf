// BadValuesTest.cpp - impossible sizes are refused, and the narrowphase never indexes out of bounds on a pose
// or size that overflows (issue 11, item 4). Run under ASan for the second half to mean anything.
#include "ManifoldReduce.h"
#include "Narrowphase.h"
#include "PhysicsConstants.h"
#include "iCCompound.h"
#include "iCOBB.h"
#include "iCSphere.h"
#include "iUtilities.h"

#include "ErrorRecorder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {
using Quiet = guardian_test::ErrorRecorder; // tests/ErrorRecorder.h
} // namespace

// Half extents and radii above MAX_SHAPE_SIZE (1e6 m) are refused with error(); the old size is kept.
TEST(BadValues, ShapesAboveTheMaximumSizeAreRefused) {
    Quiet errors;
    EXPECT_EQ(CreateCOBB(nullptr, Vector(3e38f, 1, 1)), nullptr);
    EXPECT_EQ(CreateCOBB(nullptr, Vector(1, 1, 2e6f)), nullptr);
    EXPECT_EQ(CreateCSphere(nullptr, 3e38f), nullptr);
    EXPECT_EQ(errors.count(), 3u);
    iCollisionGeometry* box = CreateCOBB(nullptr, Vector(MAX_SHAPE_SIZE, 1, 1)); // the maximum itself is fine
    iCollisionGeometry* sphere = CreateCSphere(nullptr, 500.0f);
    ASSERT_NE(box, nullptr);
    ASSERT_NE(sphere, nullptr);
    const unsigned long made = errors.count(); // joining no space may be reported
    static_cast<iCOBB*>(box)->setRadius(Vector(1, 3e38f, 1));
    static_cast<iCSphere*>(sphere)->setRadius(1e7f);
    EXPECT_EQ(errors.count(), made + 2);
    EXPECT_EQ(static_cast<iCOBB*>(box)->getRadius(), Vector(MAX_SHAPE_SIZE, 1, 1));
    EXPECT_EQ(static_cast<iCSphere*>(sphere)->getRadius(), 500.0f);
    box->Delete();
    sphere->Delete();
}

// Two boxes of half extent 3e38 (accepted before): every separating-axis overlap is infinite or NaN, which
// left the best axis at index -1. Now no contact is reported and nothing is read out of bounds.
TEST(BadValues, BoxBoxWithOverflowingSizesReportsNoContact) {
    gcol::BoxShape a, b;
    a.halfExtents = b.halfExtents = Vector(3e38f, 3e38f, 3e38f);
    b.centre = Vector(1, 0, 0);
    gcol::ContactManifold m;
    EXPECT_EQ(gcol::collideBoxBox(a, b, m), 0);
    // A pose that overflows: centres 6e38 apart (infinite) and a NaN axis.
    b.centre = Vector(3e38f, 0, 0);
    a.centre = Vector(-3e38f, 0, 0);
    EXPECT_EQ(gcol::collideBoxBox(a, b, m), 0);
    a.centre = Vector();
    b.centre = Vector(std::nanf(""), 0, 0);
    EXPECT_EQ(gcol::collideBoxBox(a, b, m), 0);
}

// Eight candidate points with NaN positions (an overflowed clip): no distance compares greater, which left
// the second pick at index -1. Now the reduction keeps at most 4 points, all taken from the input.
TEST(BadValues, ManifoldReductionOfNaNPointsStaysInBounds) {
    gcol::ContactPoint in[8];
    for (int i = 0; i < 8; ++i) {
        in[i].pos = Vector(std::nanf(""), float(i), 0);
        in[i].depth = 0.1f * float(i);
    }
    gcol::ContactManifold out;
    gcol::reduceManifold(in, 8, Vector(0, 1, 0), out);
    EXPECT_GE(out.count, 1);
    EXPECT_LE(out.count, gcol::kMaxManifoldPoints);
}
