// InertiaTest.cpp - the inertia helpers against closed-form tensors and the parallel-axis theorem.
#include "MathDefinitions.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace {

// n^3 equal point masses at the centres of a regular grid filling a box of half extents h, centred at c.
std::vector<PointMass> boxGrid(int n, const Vector& h, const Vector& c, float totalMass) {
    std::vector<PointMass> pts;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                Vector u((i + 0.5f) / n, (j + 0.5f) / n, (k + 0.5f) / n); // cell centres in [0,1]
                Vector p(c.x + h.x * (2 * u.x - 1), c.y + h.y * (2 * u.y - 1), c.z + h.z * (2 * u.z - 1));
                pts.push_back({p, totalMass / float(n * n * n)});
            }
    return pts;
}

} // namespace

TEST(Inertia, BoxAndSphereClosedForms) {
    // Solid box 2 x 4 x 6 m (half extents 1, 2, 3), 12 kg: Ixx = m/12 (b^2 + c^2) = (16 + 36) = 52.
    Matrix box = getBoxInertiaTensor(12.0f, Vector(1, 2, 3));
    EXPECT_NEAR(box.m11, 52.0f, 1e-4f);
    EXPECT_NEAR(box.m22, 40.0f, 1e-4f); // (4 + 36)
    EXPECT_NEAR(box.m33, 20.0f, 1e-4f); // (4 + 16)
    EXPECT_EQ(box.m12, 0.0f);
    EXPECT_EQ(box.m44, 1.0f);
    Matrix sphere = getSphereInertiaTensor(5.0f, 2.0f); // 2/5 m r^2 = 8
    EXPECT_NEAR(sphere.m11, 8.0f, 1e-5f);
    EXPECT_NEAR(sphere.m22, 8.0f, 1e-5f);
    EXPECT_NEAR(sphere.m33, 8.0f, 1e-5f);
}

TEST(Inertia, TenThousandPointsFillingABoxGiveTheBoxTensorWithin2Percent) {
    Vector h(0.5f, 1.5f, 2.0f);
    std::vector<PointMass> pts = boxGrid(22, h, Vector(), 7.0f); // 10,648 points
    Matrix fromPoints = getInertiaTensor(pts.data(), pts.size());
    Matrix exact = getBoxInertiaTensor(7.0f, h);
    EXPECT_NEAR(fromPoints.m11, exact.m11, 0.02f * exact.m11);
    EXPECT_NEAR(fromPoints.m22, exact.m22, 0.02f * exact.m22);
    EXPECT_NEAR(fromPoints.m33, exact.m33, 0.02f * exact.m33);
    EXPECT_NEAR(fromPoints.m12, 0.0f, 1e-3f * exact.m11);
}

TEST(Inertia, PointTensorIsAboutTheCentreOfMassNotTheOrigin) {
    // The same box moved 10 m away from the local origin has the same tensor about its own COM (the
    // original helper measured from the origin and "returned exaggerated results").
    Vector h(1, 1, 1), offset(10, -4, 3);
    std::vector<PointMass> centred = boxGrid(12, h, Vector(), 2.0f);
    std::vector<PointMass> moved = boxGrid(12, h, offset, 2.0f);
    Matrix a = getInertiaTensor(centred.data(), centred.size());
    Matrix b = getInertiaTensor(moved.data(), moved.size());
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(a(r, c), b(r, c), 1e-3f);
    Vector com = getCentreOfMass(moved.data(), moved.size());
    EXPECT_NEAR(com.x, 10.0f, 1e-4f);
    EXPECT_NEAR(com.y, -4.0f, 1e-4f);
}

TEST(Inertia, TwoPointDumbbellMatchesHandComputation) {
    // Two 1 kg points at x = +-1: I about the COM is diag(0, 2, 2); off-diagonal zero.
    PointMass pts[2] = {{Vector(1, 5, 0), 1.0f}, {Vector(-1, 5, 0), 1.0f}};
    Matrix i = getInertiaTensor(pts, 2);
    EXPECT_NEAR(i.m11, 0.0f, 1e-6f);
    EXPECT_NEAR(i.m22, 2.0f, 1e-6f);
    EXPECT_NEAR(i.m33, 2.0f, 1e-6f);
    // A diagonal pair gives the products of inertia: points at (1,1,0), (-1,-1,0): Ixy = -sum m x y = -2.
    PointMass diag[2] = {{Vector(1, 1, 0), 1.0f}, {Vector(-1, -1, 0), 1.0f}};
    Matrix d = getInertiaTensor(diag, 2);
    EXPECT_NEAR(d.m12, -2.0f, 1e-6f);
    EXPECT_NEAR(d.m21, -2.0f, 1e-6f);
    EXPECT_NEAR(d.m33, 4.0f, 1e-6f);
    EXPECT_EQ(getInertiaTensor(nullptr, 3).m11, 0.0f); // null input: a zero tensor, no crash
}
