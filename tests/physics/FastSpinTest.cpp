// FastSpinTest.cpp - a torque-free body spinning fast about its intermediate axis (issue 14 item 2): its
// kinetic energy never grows, |L| stays put, and the Dzhanibekov flip happens with the analytic period.
//
// The truths are the free rigid body's two invariants, |L| and E = 1/2 L . w (Euler's equations conserve
// both), and the period of its body-frame motion from Landau & Lifshitz, Mechanics, section 37 (Jacobi
// elliptic functions), computed here in double from the initial state alone.
#include "MathEigen.h"
#include "PhysicsTestSupport.h"
#include "iPhysicsSceneSettings.h"
#include "iPhysicsSceneStats.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

using physics_test::SceneHolder;

namespace {

// Principal moments 1, 2, 3 kg m^2: y is the intermediate axis.
const double kI1 = 1, kI2 = 2, kI3 = 3;

struct SpinRun {
    double maxEnergyGrowth = 0;  // max (E - E0) / E0 over the steps (negative: it only fell)
    double maxEnergyLoss = 0;    // max (E0 - E) / E0
    double maxMomentumError = 0; // max | |L| - |L0| | / |L0|
    std::vector<double> flips;   // times (s) at which the body's y axis crossed the plane normal to L
    bool finite = true;
};

// Spins a body of the moments above with w0 (body = world axes at t = 0) for `steps` steps at hz, checking
// after every step. The first step derives L from w; E0 and |L0| are computed from w0 here, in double.
SpinRun spinFast(double w, double hz, Integrator integrator, long steps, double tilt = 1e-3) {
    SceneHolder h(int(hz), integrator);
    settingsOf(h.scene)->setGravity(Vector());
    settingsOf(h.scene)->setMaxStepsPerUpdate(10);
    iRigidBody* b = CreateRigidBody(nullptr);
    RBDynamics& d = b->getDynamics();
    d.setInertiaTensor(Matrix(Vector(float(kI1), float(kI2), float(kI3))));
    const double wx = tilt * w, wy = w, wz = tilt * w;
    d.angularVelocity = Vector(float(wx), float(wy), float(wz));
    const double l0 = std::sqrt(kI1 * kI1 * wx * wx + kI2 * kI2 * wy * wy + kI3 * kI3 * wz * wz);
    const double e0 = 0.5 * (kI1 * wx * wx + kI2 * wy * wy + kI3 * wz * wz);
    SpinRun r;
    double lastAlign = 1;
    for (long n = 1; n <= steps; ++n) {
        h.now = int(std::ceil(double(n) * 1000.0 / hz)); // exactly one step an update
        h.scene->update(h.now);
        const Vector wNow = d.angularVelocity, lNow = d.angularMomentum;
        const double e = 0.5 * (double(wNow.x) * lNow.x + double(wNow.y) * lNow.y + double(wNow.z) * lNow.z);
        const double l = lNow.length();
        if (!std::isfinite(e) || !std::isfinite(l)) {
            r.finite = false;
            break;
        }
        r.maxEnergyGrowth = std::fmax(r.maxEnergyGrowth, (e - e0) / e0);
        r.maxEnergyLoss = std::fmax(r.maxEnergyLoss, (e0 - e) / e0);
        r.maxMomentumError = std::fmax(r.maxMomentumError, std::fabs(l - l0) / l0);
        const double align = dot(d.orientation.direction('y'), lNow) / l;
        if ((align < 0) != (lastAlign < 0)) r.flips.push_back(double(n) / hz);
        lastAlign = align;
    }
    EXPECT_EQ(statsOf(h.scene)->getStepCount(), steps);
    return r;
}

// K(k) by the arithmetic-geometric mean: K = pi / (2 AGM(1, sqrt(1 - k^2))).
double ellipticK(double k2) {
    double a = 1, g = std::sqrt(1 - k2);
    for (int i = 0; i < 40 && std::fabs(a - g) > 1e-15 * a; ++i) {
        const double an = 0.5 * (a + g);
        g = std::sqrt(a * g);
        a = an;
    }
    return M_PI / (2 * a);
}

// Time between two flips of the intermediate axis (half the period of L's body-frame motion), from the
// state w0 = (tilt w, w, tilt w) (Landau & Lifshitz 37.10-37.12; for M^2 < 2 E I2 swap I1 and I3).
double analyticFlipInterval(double w, double tilt) {
    const double wx = tilt * w, wy = w, wz = tilt * w;
    const double m2 = kI1 * kI1 * wx * wx + kI2 * kI2 * wy * wy + kI3 * kI3 * wz * wz;
    const double e2 = kI1 * wx * wx + kI2 * wy * wy + kI3 * wz * wz; // 2E
    double i1 = kI1, i3 = kI3;
    if (m2 < e2 * kI2) std::swap(i1, i3);
    const double lambda = std::sqrt((i3 - kI2) * (m2 - e2 * i1) / (i1 * kI2 * i3));
    const double k2 = (kI2 - i1) * (e2 * i3 - m2) / ((i3 - kI2) * (m2 - e2 * i1));
    return 2 * ellipticK(k2) / lambda;
}

} // namespace

// 10^4 steps at every integrator, rate and spin: the energy never rises more than 1e-4 above its start (a
// float body state rounds E at ~1e-7; the rotation update must not pump energy in), |L| holds to 1e-5 (L
// is integrated: no torque, no change but the w -> L conversion's round-off). Before the fix the energy
// grew by up to 100 % (see the commit that added this test).
TEST(FastSpin, EnergyNeverGrowsAndMomentumHoldsForATorqueFreeIntermediateAxisSpin) {
    for (Integrator i : {INTEGRATOR_ExplicitEuler, INTEGRATOR_SemiImplicitEuler, INTEGRATOR_VelocityVerlet,
                         INTEGRATOR_RK4}) {
        for (double w : {10.0, 100.0, 1000.0}) {
            for (double hz : {60.0, 120.0, 1000.0}) {
                SpinRun r = spinFast(w, hz, i, 10000);
                std::printf(
                    "integrator %d, %5.0f rad/s, %4.0f Hz: energy +%.2e / -%.2e, |L| %.2e, %zu flips\n",
                    int(i), w, hz, r.maxEnergyGrowth, r.maxEnergyLoss, r.maxMomentumError, r.flips.size());
                ASSERT_TRUE(r.finite) << "integrator " << i << " w " << w << " hz " << hz;
                EXPECT_LT(r.maxEnergyGrowth, 1e-4) << "integrator " << i << " w " << w << " hz " << hz;
                EXPECT_LT(r.maxMomentumError, 1e-5) << "integrator " << i << " w " << w << " hz " << hz;
                // The flip takes ~2 ln(1 / tilt) / (0.577 w) (24 ms at 1,000 rad/s): a step that turns the
                // body more than 2 rad cannot resolve it (the measured limit: at 1,000 rad/s and 60 or 120
                // Hz the axis stays along L, energy and |L| held). Everywhere else it must flip.
                if (w / hz < 2.0) {
                    EXPECT_GE(r.flips.size(), 2u) << "integrator " << i << " w " << w << " hz " << hz;
                }
            }
        }
    }
}

// Where the step resolves the motion (under ~0.1 rad of turn a step) the flips come at the analytic
// interval 2 K(k) / lambda, within 1 % for every integrator (measured: 0.03 % to 0.5 %; the kept energy
// keeps the body-frame momentum on its own polhode, so only the phase carries the step's error; before
// the fix the energy drift shortened the interval by up to 93 %). The first crossing depends on where the
// motion starts on its orbit: only the intervals between crossings are compared.
TEST(FastSpin, TheIntermediateAxisFlipsAtTheAnalyticInterval) {
    struct Case {
        double w, hz;
    };
    for (Integrator i : {INTEGRATOR_ExplicitEuler, INTEGRATOR_SemiImplicitEuler, INTEGRATOR_VelocityVerlet,
                         INTEGRATOR_RK4}) {
        for (Case c : {Case{10, 120}, Case{10, 1000}, Case{100, 1000}}) {
            const double tilt = 1e-2;
            SpinRun r = spinFast(c.w, c.hz, i, 10000, tilt);
            const double expected = analyticFlipInterval(c.w, tilt);
            ASSERT_GE(r.flips.size(), 3u) << "integrator " << i << " w " << c.w << " hz " << c.hz;
            const double measured = (r.flips.back() - r.flips.front()) / double(r.flips.size() - 1);
            std::printf("integrator %d, %4.0f rad/s, %4.0f Hz: flip every %.5f s, analytic %.5f s\n", int(i),
                        c.w, c.hz, measured, expected);
            EXPECT_NEAR(measured / expected, 1.0, 0.01)
                << "integrator " << i << " w " << c.w << " hz " << c.hz;
        }
    }
}
