// IntegratorAccuracyTest.cpp - each integrator against closed-form motion: projectile, quadratic drag,
// mass-spring. Tolerances are derived in the comments (float has eps = 1.19e-7).
#include "PhysicsTestSupport.h"
#include "iForceGenerator.h"
#include "iPhysicsSceneHooks.h"
#include "iPhysicsSceneSettings.h"
#include "iPhysicsSceneStats.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>

using physics_test::SceneHolder;

namespace {

const Vector X0(1, 2, 3), V0(3, 5, -2);
const Vector G(0, -9.81f, 0);

// Position error after exactly 1 s of free flight, against x0 + v0 t + g t^2 / 2.
Vector projectileError(int hz, Integrator integrator) {
    SceneHolder h(hz, integrator);
    iRigidBody* b = CreateRigidBody(nullptr);
    b->getDynamics().position = X0;
    b->getDynamics().velocity = V0;
    h.run(1000);
    EXPECT_EQ(statsOf(h.scene)->getStepCount(), hz); // 1000 ms is exactly hz steps (integer clock)
    Vector exact = X0 + V0 + G * 0.5f;
    return b->getDynamics().position - exact;
}

} // namespace

// Verlet and RK4 are exact for constant acceleration: only float round-off remains. Bound: each step
// rounds about four additions at magnitude <= 8 (half an ulp, 4.8e-7, each), and the rounding of v feeds x,
// so n steps stay under n * 4 * 8 * eps = n * 3.8e-6; at 120 steps that is 4.6e-4, a hundredth of the
// Euler error at the same rate (g t dt / 2 = 0.041).
TEST(IntegratorAccuracy, VerletAndRK4AreExactForAProjectile) {
    for (Integrator i : {INTEGRATOR_VelocityVerlet, INTEGRATOR_RK4}) {
        for (int hz : {60, 120}) {
            Vector e = projectileError(hz, i);
            float bound = hz * 4 * 8 * FLT_EPSILON;
            EXPECT_LT(e.length(), bound) << "integrator " << i << " at " << hz << " Hz";
        }
    }
}

// Euler variants: the exact sums give x_n = x0 + v0 t + g t^2 / 2 +- g t dt / 2 (semi-implicit: +, it uses
// the updated velocity; explicit: -). First order: halving dt halves the error, ratio 2 (float noise above
// is < 5e-4 of an error of 0.04, so the ratio is 2 within 0.01).
TEST(IntegratorAccuracy, EulerErrorsAreFirstOrderInTheStep) {
    for (Integrator i : {INTEGRATOR_SemiImplicitEuler, INTEGRATOR_ExplicitEuler}) {
        Vector e60 = projectileError(60, i);
        Vector e120 = projectileError(120, i);
        float sign = i == INTEGRATOR_SemiImplicitEuler ? 1.0f : -1.0f;
        EXPECT_NEAR(e60.y, sign * 0.5f * G.y / 60.0f, 1e-3f) << "integrator " << i;
        EXPECT_NEAR(e60.y / e120.y, 2.0f, 0.01f) << "integrator " << i;
        EXPECT_NEAR(e60.x, 0.0f, 1e-4f); // no acceleration along x: exact
    }
}

// Quadratic drag F = -1/2 rho Cd A |v| v (rho 1.2; A = pi, a body without geometry being the unit sphere its
// inertia assumes): falling from rest the speed tends to
// sqrt(2 m g / (rho Cd A)), reached to 1e-12 after 6 s (the time constant v_t / g is 0.45 s). Each
// integrator's fixed point of dv/dt = 0 is the exact terminal speed, so 0.5% is a loose, honest bound.
TEST(IntegratorAccuracy, QuadraticDragReachesTheAnalyticTerminalVelocity) {
    for (Integrator i : {INTEGRATOR_ExplicitEuler, INTEGRATOR_SemiImplicitEuler, INTEGRATOR_VelocityVerlet,
                         INTEGRATOR_RK4}) {
        SceneHolder h(60, i);
        iRigidBody* b = CreateRigidBody(nullptr);
        b->getDynamics().mass = 2.0f;
        b->getDynamics().dragCoefficient = 0.8f;
        h.run(6000);
        float terminal = std::sqrt(2.0f * 2.0f * 9.81f / (1.2f * 0.8f * 3.14159265f));
        EXPECT_NEAR(-b->getDynamics().velocity.y, terminal, 0.005f * terminal) << "integrator " << i;
    }
}

namespace {

// F = -k x towards the origin, evaluated at every integrator stage.
struct Spring final : iForceGenerator {
    float k;
    explicit Spring(float stiffness) : k(stiffness) {}
    void addForces(const iRigidBody*, const RigidBodyState& s, Vector& force, Vector&) override {
        force += s.position * -k;
    }
};

struct SpringRun {
    float maxEnergyError = 0; // max |E - E0| / E0 over the run
    float finalEnergyRatio = 0;
    float finalX = 0;
};

// m = 2, k = 2: omega = sqrt(k/m) = 1 rad/s, period 2 pi. From x = 1 at rest, x(t) = cos t.
SpringRun runSpring(Integrator integrator, double periods) {
    SceneHolder h(60, integrator);
    settingsOf(h.scene)->setGravity(Vector());
    settingsOf(h.scene)->setMaxStepsPerUpdate(1000);
    iRigidBody* b = CreateRigidBody(nullptr);
    RBDynamics& d = b->getDynamics();
    d.mass = 2.0f;
    d.position = Vector(1, 0, 0);
    Spring spring(2.0f);
    hooksOf(h.scene)->addForceGenerator(b, &spring);
    auto energy = [&] {
        return 0.5f * d.mass * d.velocity.lengthSquared() + 0.5f * spring.k * d.position.lengthSquared();
    };
    const float e0 = energy();
    SpringRun r;
    // Whole milliseconds cannot hit 2 pi n exactly; run the steps for the nearest whole step count.
    const long long steps = std::llround(periods * 2.0 * M_PI * 60.0);
    for (long long n = 0; n < steps; ++n) {
        h.now += n % 3 == 2 ? 16 : 17; // 17, 17, 16 ms: exactly one step per update at 60 Hz
        h.scene->update(h.now);
        r.maxEnergyError = std::fmax(r.maxEnergyError, std::fabs(energy() - e0) / e0);
    }
    EXPECT_EQ(statsOf(h.scene)->getStepCount(), steps);
    r.finalEnergyRatio = energy() / e0;
    // x at the time actually simulated (steps / 60 s), analytic cos(omega t).
    r.finalX = d.position.x - float(std::cos(double(steps) / 60.0));
    hooksOf(h.scene)->removeForceGenerator(b, &spring);
    return r;
}

} // namespace

// Symplectic Euler conserves a modified energy H~ = H - (dt/2) k x v; since |k x v| <= omega E, H stays
// within omega dt / 2 = 0.83% of E0 (60 Hz, omega = 1) when starting at x v = 0: under 1% for 100 periods.
// Verlet's deviation is O((omega dt)^2), RK4's drift O((omega dt)^5) a step: both far below 1%.
TEST(IntegratorAccuracy, SpringEnergyStaysWithinOnePercentOverAHundredPeriods) {
    for (Integrator i : {INTEGRATOR_SemiImplicitEuler, INTEGRATOR_VelocityVerlet, INTEGRATOR_RK4}) {
        SpringRun r = runSpring(i, 100);
        EXPECT_LT(r.maxEnergyError, 0.01f) << "integrator " << i;
    }
}

// The oscillation frequency is sqrt(k/m). Checked a quarter period past 100 periods, where x = cos t
// crosses zero with slope -1, so the x error is the phase error itself. Verlet's phase error is
// omega^3 dt^2 t / 24 = 7.3e-3 rad at t = 630 s (so |x error| < 0.0085 with round-off); RK4's is ~1e-9
// rad, round-off over 37,700 steps dominates and stays well under 1e-3.
TEST(IntegratorAccuracy, SpringOscillatesAtTheAnalyticFrequency) {
    float verlet = runSpring(INTEGRATOR_VelocityVerlet, 100.25).finalX;
    EXPECT_LT(std::fabs(verlet), 0.0085f);
    EXPECT_GT(std::fabs(verlet), 0.003f); // the predicted O(dt^2) phase error is really there
    EXPECT_LT(std::fabs(runSpring(INTEGRATOR_RK4, 100.25).finalX), 1e-3f);
}

// Explicit Euler multiplies the energy by exactly (1 + (omega dt)^2) every step: it visibly gains energy,
// by the analytic factor (within 1%, float round-off over 37,700 steps).
TEST(IntegratorAccuracy, ExplicitEulerGainsEnergyOnASpring) {
    SpringRun r = runSpring(INTEGRATOR_ExplicitEuler, 100);
    const long long steps = std::llround(100 * 2.0 * M_PI * 60.0);
    double expected = std::pow(1.0 + 1.0 / 3600.0, double(steps));
    EXPECT_GT(r.finalEnergyRatio, 2.0f);
    EXPECT_NEAR(r.finalEnergyRatio / expected, 1.0, 0.01);
}

namespace {
// A rotational damper: torque = -c w, from the trial state's angular velocity.
struct Damper final : iForceGenerator {
    float c;
    explicit Damper(float coefficient) : c(coefficient) {}
    void addForces(const iRigidBody*, const RigidBodyState& s, Vector&, Vector& torque) override {
        torque += s.angularVelocity * -c;
    }
};
} // namespace

// I w' = -c w: w(t) = w0 exp(-c t / I). With I = 0.5 kg m^2 and c = 0.5 N m s, w falls to 1/e in 1 s. The
// Euler variants give (1 - dt c / I)^60 = 0.3648 at 60 Hz, 0.8 % under e^-1; Verlet and RK4 are closer.
// A generator that read no angular velocity (or a zero one) would leave the spin as it was.
TEST(IntegratorAccuracy, AGeneratorReadingTheSpinDampsItAtTheAnalyticRate) {
    for (Integrator i : {INTEGRATOR_ExplicitEuler, INTEGRATOR_SemiImplicitEuler, INTEGRATOR_VelocityVerlet,
                         INTEGRATOR_RK4}) {
        SceneHolder h(60, i);
        settingsOf(h.scene)->setGravity(Vector());
        iRigidBody* b = CreateRigidBody(nullptr);
        RBDynamics& d = b->getDynamics();
        d.setInertiaTensor(Matrix(0.5f));
        d.angularVelocity = Vector(0, 2, 0);
        Damper damper(0.5f);
        hooksOf(h.scene)->addForceGenerator(b, &damper);
        h.run(1000);
        EXPECT_NEAR(d.angularVelocity.y / 2.0f, std::exp(-1.0f), 0.01f) << i;
        EXPECT_NEAR(d.angularVelocity.x, 0.0f, 1e-6f) << i;
        hooksOf(h.scene)->removeForceGenerator(b, &damper);
    }
}
