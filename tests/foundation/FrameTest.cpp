// FrameTest.cpp - frame hierarchies: world transforms through parents, and attaching that keeps the pose.
#include "Frame.h"
#include "MathExpect.h"

#include <gtest/gtest.h>

#include <limits>

using foundation_test::expectNear;
using foundation_test::kPi;

TEST(Frame, GrandchildWorldPositionComposesThroughTheChain) {
    Frame root, child, grandchild;
    child.attachTo(&root); // all at identity: attaching changes nothing
    grandchild.attachTo(&child);
    // Now set each T relative to its parent.
    root.setTransform(rotatey(kPi / 2) * translation(10, 0, 0)); // local +x points along world -z
    child.setTransform(translation(2, 0, 0));
    grandchild.setTransform(rotatez(kPi / 2) * translation(0, 3, 0));
    // By hand: the child origin (2,0,0) in root space turns to (0,0,-2) and moves to (10,0,-2); the
    // grandchild's (0,3,0) in child space is unchanged by the root's turn about y: (10,3,-2).
    expectNear(grandchild.position(), Vector(10, 3, -2), 1e-5f);
    // Its local x axis: rotatez(90) sends x to y; the root's turn about y leaves y alone.
    expectNear(grandchild.orientation('x'), Vector(0, 1, 0), 1e-5f);
    // And its local z axis: unchanged by rotatez, then the root's y turn sends z to +x.
    expectNear(grandchild.orientation('z'), Vector(1, 0, 0), 1e-5f);
    expectNear(grandchild.world().position(), grandchild.position(), 1e-6f);
}

TEST(Frame, AttachToKeepsTheWorldPoseAndDetachKeepsItToo) {
    Frame parent, f;
    parent.translate(5, 1, 0);
    parent.rotatex(0.3f);
    f.translate(1, 2, 3);
    f.rotatez(0.4f);
    Matrix before = f.world();
    f.attachTo(&parent);
    EXPECT_EQ(f.parent(), &parent);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(f.world()(r, c), before(r, c), 1e-5f);
    parent.translate(0, 10, 0); // the child now follows its parent
    expectNear(f.position(), before.position() + Vector(0, 10, 0), 1e-5f);
    Vector moved = f.position();
    f.attachTo(nullptr);
    expectNear(f.position(), moved, 1e-5f);
}

TEST(Frame, AttachingToADescendantIsRefused) {
    unsigned long errorsBefore = errorCount();
    ErrorHandler old = setErrorHandler([](const wchar_t*) {});
    Frame a, b;
    b.attachTo(&a);
    a.attachTo(&b); // would make a cycle
    a.attachTo(&a);
    setErrorHandler(old);
    EXPECT_EQ(a.parent(), nullptr);
    EXPECT_EQ(errorCount(), errorsBefore + 2);
}

TEST(Frame, NonFiniteTransformIsRefused) {
    ErrorHandler old = setErrorHandler([](const wchar_t*) {});
    Frame f;
    f.translate(1, 2, 3);
    Matrix bad = translation(0, 0, 0);
    bad.m42 = std::numeric_limits<float>::quiet_NaN();
    f.setTransform(bad);
    setErrorHandler(old);
    expectNear(f.position(), Vector(1, 2, 3), 0);
}
