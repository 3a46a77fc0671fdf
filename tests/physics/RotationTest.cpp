// RotationTest.cpp - free rotation of an asymmetric body (conservation, the intermediate-axis flip) and
// impulses at an offset point, against closed-form rigid-body mechanics.
#include "MathEigen.h"
#include "PhysicsTestSupport.h"
#include "iPhysicsSceneSettings.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

using physics_test::SceneHolder;

namespace {

// Principal moments 1, 2, 3 kg m^2 (an asymmetric body, axes x < y < z).
const Matrix INERTIA(Vector(1, 2, 3));

struct FreeSpin {
    float maxMomentumError = 0; // max | |L| - |L0| | / |L0|
    float maxEnergyError = 0;   // max |E - E0| / E0, E = 1/2 w . L
    float minAxisAlignment = 1; // min over time of (body axis . L / |L|) for the axis spun about
    bool staysOrthonormal = true;
};

// Torque-free motion from angular velocity w0 (world = body axes at t = 0) for `ms`, at 120 Hz.
FreeSpin spin(const Vector& w0, char axis, Integrator integrator, int ms) {
    SceneHolder h(120, integrator);
    settingsOf(h.scene)->setGravity(Vector());
    iRigidBody* b = CreateRigidBody(nullptr);
    RBDynamics& d = b->getDynamics();
    d.setInertiaTensor(INERTIA);
    d.angularVelocity = w0;
    FreeSpin r;
    float l0 = 0, e0 = 0;
    for (int t = 0; t < ms; t += 10) {
        h.run(10);
        float l = d.angularMomentum.length();
        float e = 0.5f * dot(d.angularVelocity, d.angularMomentum);
        if (t == 0) { // the scene derived L from w on the first step
            Vector lExact = w0 * INERTIA;
            l0 = lExact.length();
            e0 = 0.5f * dot(w0, lExact);
        }
        r.maxMomentumError = std::fmax(r.maxMomentumError, std::fabs(l - l0) / l0);
        r.maxEnergyError = std::fmax(r.maxEnergyError, std::fabs(e - e0) / e0);
        r.minAxisAlignment =
            std::fmin(r.minAxisAlignment, dot(d.orientation.direction(axis), d.angularMomentum) / l);
        r.staysOrthonormal = r.staysOrthonormal && isRotation(d.orientation, 1e-5f);
    }
    return r;
}

} // namespace

// With no torque, L (world) is constant and so is the kinetic energy 1/2 w . L. Integrating L directly
// keeps |L| to float round-off (1e-4 asked); the energy is carried by the orientation update.
TEST(Rotation, TorqueFreeAsymmetricBodyConservesMomentumAndEnergy) {
    for (Integrator i : {INTEGRATOR_SemiImplicitEuler, INTEGRATOR_VelocityVerlet, INTEGRATOR_RK4}) {
        FreeSpin r = spin(Vector(1.0f, 0.7f, 0.4f), 'z', i, 10000);
        EXPECT_LT(r.maxMomentumError, 1e-4f) << "integrator " << i;
        EXPECT_LT(r.maxEnergyError, 0.01f) << "integrator " << i;
        EXPECT_TRUE(r.staysOrthonormal) << "integrator " << i;
    }
}

// Dzhanibekov: a spin about the intermediate axis is unstable. Perturbations grow at
// w sqrt((I2 - I1)(I3 - I2) / (I1 I3)) = 3 * 0.577 = 1.7 /s, so 0.01 rad/s grows to a flip in ~3.5 s:
// within 10 s the y axis turns against L. Spins about the smallest and largest axes stay put.
TEST(Rotation, IntermediateAxisFlipsAndTheOthersAreStable) {
    FreeSpin mid = spin(Vector(0.01f, 3.0f, 0.01f), 'y', INTEGRATOR_Default, 10000);
    EXPECT_LT(mid.minAxisAlignment, -0.9f);
    FreeSpin minor = spin(Vector(3.0f, 0.01f, 0.01f), 'x', INTEGRATOR_Default, 10000);
    EXPECT_GT(minor.minAxisAlignment, 0.99f);
    FreeSpin major = spin(Vector(0.01f, 0.01f, 3.0f), 'z', INTEGRATOR_Default, 10000);
    EXPECT_GT(major.minAxisAlignment, 0.99f);
}

// J at r from the COM: dv = J / m and dw = I_world^-1 (r x J), with I_world^-1 = R I^-1 R^T for the
// column-vector rotation R; computed here with Eigen directly from the axis-angle, not through RBDynamics.
TEST(Rotation, ImpulseAtAnOffsetPointChangesLinearAndAngularVelocity) {
    RBDynamics d;
    d.mass = 2.0f;
    d.setInertiaTensor(getBoxInertiaTensor(2.0f, Vector(0.5f, 1.0f, 1.5f)));
    const Vector axis = Vector(1, 2, 3).normalize();
    d.orientation = rotate(axis, 0.7f);
    d.position = Vector(4, -1, 2);
    d.velocity = Vector(0.5f, 0, 0);
    const Vector j(1, 2, -1), r(0.3f, -0.5f, 0.2f);
    d.ApplyImpulse(j, d.position + r);

    EXPECT_NEAR(d.velocity.x, 0.5f + 0.5f, 1e-6f);
    EXPECT_NEAR(d.velocity.y, 1.0f, 1e-6f);
    EXPECT_NEAR(d.velocity.z, -0.5f, 1e-6f);

    Eigen::Matrix3f rot = Eigen::AngleAxisf(0.7f, Eigen::Vector3f(axis.x, axis.y, axis.z)).toRotationMatrix();
    Eigen::Matrix3f inv = Eigen::Vector3f(3.0f / (2.0f * (1.0f + 2.25f)), 3.0f / (2.0f * (0.25f + 2.25f)),
                                          3.0f / (2.0f * (0.25f + 1.0f)))
                              .asDiagonal();
    Eigen::Vector3f dw = rot * inv * rot.transpose() *
                         Eigen::Vector3f(r.y * j.z - r.z * j.y, r.z * j.x - r.x * j.z, r.x * j.y - r.y * j.x);
    EXPECT_NEAR(d.angularVelocity.x, dw.x(), 1e-5f);
    EXPECT_NEAR(d.angularVelocity.y, dw.y(), 1e-5f);
    EXPECT_NEAR(d.angularVelocity.z, dw.z(), 1e-5f);
    // A point moving with the body: v + w x (p - c).
    Vector p = d.position + Vector(0, 1, 0);
    Vector expected = d.velocity + cross(d.angularVelocity, Vector(0, 1, 0));
    Vector got = d.getVelocityAtWorldPoint(p);
    EXPECT_NEAR((got - expected).length(), 0.0f, 1e-6f);
}
