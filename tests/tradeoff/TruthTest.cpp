// TruthTest.cpp - the closed-form answers bench_tradeoff measures the engine against (Truth.h), checked
// against values worked by hand and against a fine numerical integration of each scene's equations of
// motion written here (RK4 at 1e-4 s or finer), never against the engine.
#include "Truth.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace tradeoff;

namespace {

// Integrates the 1-D system x'' = a(x, v) from (x, v) over t with classical RK4 at step h.
void integrate(double& x, double& v, double t, double h, const std::function<double(double, double)>& a) {
    const int n = int(std::round(t / h));
    for (int i = 0; i < n; ++i) {
        const double k1x = v, k1v = a(x, v);
        const double k2x = v + 0.5 * h * k1v, k2v = a(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
        const double k3x = v + 0.5 * h * k2v, k3v = a(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
        const double k4x = v + h * k3v, k4v = a(x + h * k3x, v + h * k3v);
        x += h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
        v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    }
}

} // namespace

TEST(TradeoffTruth, ProjectileIsX0PlusV0TPlusHalfGTSquared) {
    // By hand at t = 2 s: x = 1 + 3*2 = 7, y = 2 + 8*2 - 9.81*4/2 = -1.62, z = 3 + 1*2 = 5.
    const Vec3d p = projectileAt({1, 2, 3}, {3, 8, 1}, {0, -9.81, 0}, 2.0);
    EXPECT_NEAR(p.x, 7.0, 1e-12);
    EXPECT_NEAR(p.y, -1.62, 1e-12);
    EXPECT_NEAR(p.z, 5.0, 1e-12);
}

TEST(TradeoffTruth, DragFallMatchesNumericalIntegration) {
    // m v' = m g - 1/2 rho Cd A v^2 (falling: v > 0 downward), rho = 1.2.
    for (double area : {1.0, 0.25})
        for (double cd : {0.1, 0.5, 2.0}) {
            double x = 0, v = 0;
            integrate(x, v, 2.0, 1e-4,
                      [cd, area](double, double vel) { return 9.81 - 0.5 * 1.2 * cd * area * vel * vel; });
            EXPECT_NEAR(dragFallDistance(1.0, cd, area, 9.81, 2.0), x, 1e-9) << "Cd " << cd << " A " << area;
        }
    EXPECT_NEAR(dragFallDistance(1.0, 0.0, 1.0, 9.81, 2.0), 19.62, 1e-12); // no drag: g t^2 / 2
}

TEST(TradeoffTruth, OrbitIsCircularUnderItsInverseSquareField) {
    // Integrate the 2-D inverse-square orbit from the truth's start state and compare after 1.5 periods.
    const double r = 0.5, T = 1.0, gm = orbitGM(r, T), h = 1e-5;
    double x = r, y = 0, vx = 0, vy = 2 * kPi * r / T;
    auto acc = [gm](double px, double py, double& ax, double& ay) {
        const double d = std::sqrt(px * px + py * py);
        ax = -gm * px / (d * d * d);
        ay = -gm * py / (d * d * d);
    };
    for (int i = 0; i < int(1.5 * T / h + 0.5); ++i) { // velocity Verlet, fine steps
        double ax, ay;
        acc(x, y, ax, ay);
        vx += 0.5 * h * ax;
        vy += 0.5 * h * ay;
        x += h * vx;
        y += h * vy;
        acc(x, y, ax, ay);
        vx += 0.5 * h * ax;
        vy += 0.5 * h * ay;
    }
    const Vec3d truth = orbitAt({0, 0, 0}, r, T, 1.5 * T);
    EXPECT_NEAR(truth.x, -0.5, 1e-12); // half way round after 1.5 periods
    EXPECT_NEAR(truth.y, 0.0, 1e-12);
    EXPECT_NEAR(x, truth.x, 1e-6);
    EXPECT_NEAR(y, truth.y, 1e-6);
}

TEST(TradeoffTruth, SpringMatchesNumericalIntegration) {
    const double k = 4 * kPi * kPi, m = 1.0;
    double x = 0.5, v = 0;
    integrate(x, v, 2.3, 1e-4, [k, m](double pos, double) { return -k / m * pos; });
    EXPECT_NEAR(springAt(0.5, k, m, 2.3), x, 1e-9);
    EXPECT_NEAR(springAt(0.5, k, m, 1.0), 0.5, 1e-12); // one period: back where it started
}

TEST(TradeoffTruth, ReboundStoppingAndRolling) {
    // Rebound: impact speed sqrt(2 g h), leaves at e times it, rises v^2 / (2 g).
    const double g = 9.81, h = 2.0, e = 0.8, out = e * std::sqrt(2 * g * h);
    EXPECT_NEAR(reboundHeight(e, h), out * out / (2 * g), 1e-12);
    // Stopping: integrate v' = -mu g until v = 0.
    double x = 0, v = 4.0;
    const double mu = 0.65, dt = 1e-6;
    while (v > 0) {
        const double nv = std::max(0.0, v - mu * g * dt);
        x += 0.5 * (v + nv) * dt;
        v = nv;
    }
    EXPECT_NEAR(stoppingDistance(4.0, mu, g), x, 1e-5);
    // Rolling: a solid sphere (I = 2/5 m r^2) sliding at v0 without spin; friction mu m g slows it and
    // spins it up until v = w r.
    const double r = 0.5, v0 = 5.0;
    double vel = v0, w = 0;
    while (vel > w * r) {
        vel -= mu * g * dt;
        w += mu * g * r / (0.4 * r * r) * dt;
    }
    EXPECT_NEAR(rollingSpeed(v0), vel, 1e-4);
}

TEST(TradeoffTruth, BoxSpinEnergyAndCombineRules) {
    // A cube of side a = 2h has I = m a^2 / 6 about every axis: spinning at 3 rad/s, E = 1/2 I 9.
    const double m = 2.0, hh = 0.5, a = 2 * hh;
    EXPECT_NEAR(boxSpinEnergy(m, hh, hh, hh, {3, 0, 0}), 0.5 * (m * a * a / 6) * 9, 1e-12);
    EXPECT_NEAR(boxSpinEnergy(m, hh, hh, hh, {0, 0, 3}), 0.5 * (m * a * a / 6) * 9, 1e-12);
    // README: friction sums by default; the other rules are their names.
    EXPECT_DOUBLE_EQ(combine(0, 0.4, 0.25), 0.65);
    EXPECT_DOUBLE_EQ(combine(1, 0.4, 0.25), 0.325);
    EXPECT_DOUBLE_EQ(combine(2, 0.4, 0.25), 0.4);
    EXPECT_DOUBLE_EQ(combine(3, 0.4, 0.25), 0.25);
    EXPECT_DOUBLE_EQ(combine(4, 0.4, 0.25), 0.1);
    EXPECT_DOUBLE_EQ(combine(5, 0.4, 0.1), 0.2);
}
