// BodyFactorTest.cpp - the scaled spin coordinates of the contact sweeps (ContactBlocks.h, BodyFactor):
// against a brute-force product, L L^T is the body's world inverse inertia and its solves undo its
// products; a body that must not turn in a sweep gets L = 0; a spinning immovable one's row speeds keep
// the bits of r x d . w.
#include "ContactBlocks.h"
#include "SolverRows.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using physics::BodyFactor;
using physics::Mat3;
using physics::Real;
using physics::SolverBody;
using physics::Vec3;

namespace {

RBDynamics g_factorRoot; // any non-null root: a body with a root and an inverse mass is movable

Vec3 randomVector(std::mt19937& rng, float scale) {
    std::uniform_real_distribution<float> u(-scale, scale);
    return Vec3(u(rng), u(rng), u(rng));
}

// A world inverse inertia as the solver makes one: R diag(1/I) R^T, principal moments 10^-2..10^2 kg m^2
// (a thin rod's ratio of 10^4 included).
Mat3 randomInverseInertia(std::mt19937& rng) {
    std::uniform_real_distribution<float> exponent(-2, 2);
    Vec3 moments(std::pow(10.0f, exponent(rng)), std::pow(10.0f, exponent(rng)),
                 std::pow(10.0f, exponent(rng)));
    Mat3 r = Eigen::Quaternionf(Eigen::Vector4f::Random().normalized()).toRotationMatrix();
    return r * moments.cwiseInverse().asDiagonal() * r.transpose();
}

SolverBody movableBody(const Mat3& invInertia) {
    SolverBody b;
    b.root = &g_factorRoot;
    b.invMass = 1;
    b.invInertia = invInertia;
    return b;
}

// |x - y| within tol of |y|, in the metric of the largest entry.
void expectClose(const Vec3& x, const Vec3& y, float tol, int trial) {
    EXPECT_LE((x - y).norm(), tol * std::max(Real(1e-6f), y.norm())) << "trial " << trial;
}

} // namespace

TEST(BodyFactor, ItsSquareIsTheInverseInertiaAndItsSolvesUndoItsProducts) {
    std::mt19937 rng(2026);
    std::srand(7); // Eigen's Random
    for (int trial = 0; trial < 200; ++trial) {
        const Mat3 a = randomInverseInertia(rng);
        const BodyFactor f = BodyFactor::of(movableBody(a));
        ASSERT_TRUE(f.turns);
        const Vec3 x = randomVector(rng, 3);
        expectClose(f.times(f.timesT(x)), a * x, 1e-5f, trial); // L L^T x = I^-1 x
        expectClose(f.solve(f.times(x)), x, 1e-5f, trial);
        expectClose(f.solveT(f.timesT(x)), x, 1e-5f, trial);
        // What the sweeps rely on: s . u = (r x d) . w, with s = L^T (r x d) and u = L^-1 w.
        const Vec3 arm = randomVector(rng, 2), w = randomVector(rng, 10);
        EXPECT_NEAR(f.timesT(arm).dot(f.solve(w)), arm.dot(w), 1e-4f * arm.norm() * w.norm()) << trial;
    }
}

TEST(BodyFactor, ABodyThatMayNotTurnInASweepGetsNone) {
    // Rotation locked (a zero inverse tensor): nothing turns it.
    const BodyFactor locked = BodyFactor::of(movableBody(Mat3::Zero()));
    EXPECT_FALSE(locked.turns);
    EXPECT_EQ(locked.timesT(Vec3(1, 2, 3)), Vec3::Zero());
    EXPECT_EQ(locked.times(Vec3(1, 2, 3)), Vec3::Zero());
    // The static world and a fixed body at rest: their rows' spin terms are zero, so what the rows add to
    // their lane within a block comes back into no speed.
    SolverBody still;
    still.root = &g_factorRoot; // infinite mass: invMass 0
    const BodyFactor f = BodyFactor::of(still);
    EXPECT_FALSE(f.turns);
    EXPECT_EQ(f.timesT(Vec3(1, 2, 3)), Vec3::Zero());
    EXPECT_EQ(BodyFactor::of(SolverBody{}).timesT(Vec3(1, 2, 3)), Vec3::Zero());
}

TEST(BodyFactor, ASpinningKinematicBodysRowSpeedKeepsItsBits) {
    std::mt19937 rng(11);
    for (int trial = 0; trial < 100; ++trial) {
        SolverBody kinematic;
        kinematic.root = &g_factorRoot;
        kinematic.w = randomVector(rng, 20);
        const BodyFactor f = BodyFactor::of(kinematic);
        EXPECT_FALSE(f.turns);
        const Vec3 arm = randomVector(rng, 5);
        const Vec3 s = f.timesT(arm), u = f.solve(kinematic.w);
        // A power-of-two scale: the products are the world ones, bit for bit.
        EXPECT_EQ(s.x() * u.x(), arm.x() * kinematic.w.x()) << trial;
        EXPECT_EQ(s.dot(u), arm.dot(kinematic.w)) << trial;
        // What a row adds to its lane comes back into its speed scaled by 2^-40.
        EXPECT_LE(s.squaredNorm(), arm.squaredNorm() * 1e-12f) << trial;
    }
}
