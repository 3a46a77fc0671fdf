// Integrators.cpp - explicit Euler, semi-implicit Euler, velocity Verlet and RK4 on (x, v, q, L).
//
// Linear: dx/dt = v, dv/dt = a(state). Angular: dL/dt = torque(state), w = R I^-1 R^T L, dq/dt = 1/2 (0, w)
// q. Integrating L rather than w makes the gyroscopic term w x (I w) implicit in the model: with no torque, L
// is constant and only the rotation moves. Every rotation taken at constant L then keeps the kinetic energy
// 1/2 L . w it started with (keepRotationalEnergy), so a free body's |L| and E are both conserved.
#include "Integrators.h"

#include "MathEigen.h"
#include "RigidBody.h"
#include "iForceGenerator.h"

#include <cmath>

namespace physics {

Quat rotateBy(const Quat& q, const Vec3& omega, Real dt) {
    Real angle = omega.norm() * dt;
    if (!(angle > 0.0f)) return q;
    return (Quat(Eigen::AngleAxis<Real>(angle, omega / omega.norm())) * q).normalized();
}

Derivative evaluate(const Composite& c, const MotionState& s, Real t, bool withOmega) {
    Derivative d;
    Mat3 r = s.q.toRotationMatrix();
    bool dragged = false; // (a part's drag with dragK 0 is 0 whatever the velocity)
    for (const CompositePart& p : c.parts) dragged = dragged || (c.drag && p.dragK > 0.0f);
    const bool omegaUsed = withOmega || dragged || c.hasGenerators;
    d.omega =
        c.rotationLocked || !omegaUsed ? Vec3(Vec3::Zero()) : Vec3(r * c.invInertia * r.transpose() * s.L);
    Vec3 force = Vec3::Zero(), torque = Vec3::Zero();
    for (const CompositePart& p : c.parts) {
        Vec3 arm = r * p.offset;
        Vec3 vp = s.v + d.omega.cross(arm);
        Vec3 f = p.constForce; // quadratic drag at the part's COM (switched off: not evaluated)
        if (c.drag) f -= p.dragK * vp.norm() * vp;
        Vec3 tau = p.constTorque;
        if (p.body && !p.body->generators().empty()) {
            RigidBodyState state;
            state.position = toVector(s.x + arm);
            state.velocity = toVector(vp);
            state.orientation = toOrientation(Mat3(r * p.relRot));
            state.angularVelocity = toVector(d.omega);
            state.time = t;
            Vector gf, gt;
            std::vector<iForceGenerator*>& gens = p.body->generators();
            for (size_t i = 0; i < gens.size(); ++i) gens[i]->addForces(p.body, state, gf, gt);
            f += toEigen(gf);
            tau += toEigen(gt);
        }
        force += f;
        if (!c.rotationLocked) torque += tau + arm.cross(f); // a locked body's momentum stays zero
    }
    d.acceleration = c.gravity + force * c.invMass;
    d.torque = torque;
    return d;
}

namespace {

// Turns q by the angular velocity of momentum L taken at the half-step rotation (explicit midpoint on the
// rotation group). w = R I^-1 R^T L depends on the rotation itself; using the start-of-step w makes a free
// asymmetric body drift in energy at first order (1.7% over 10 s at 120 Hz in the torque-free test), the
// midpoint makes it second order. One extra tensor rotation a body-step.
Quat rotateMidpoint(const Composite& c, const Quat& q, const Vec3& L, Real dt) {
    // No angular momentum, no turn: each rotateBy below would find a zero angle (or a NaN one) and return q
    // as it is, after two tensor rotations (most of a falling body's integration when it does not spin).
    if (L.isZero(0)) return q;
    Quat half = rotateBy(q, worldInverseInertia(c, q) * L, 0.5f * dt);
    return rotateBy(q, worldInverseInertia(c, half) * L, dt);
}

// The smallest rotation taking the direction of `from` to that of `to` (Eigen's FromTwoVectors, written out:
// Eigen's solves an SVD for opposite vectors, and instantiating it took 13 s of every build of this file).
Eigen::Quaterniond shortestArc(const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
    const Eigen::Vector3d a = from.normalized(), b = to.normalized();
    const double c = b.dot(a);
    if (c < -1 + 1e-12) { // opposite: a half turn about any axis perpendicular to both
        Eigen::Vector3d other = std::fabs(a.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
        const Eigen::Vector3d axis = a.cross(other).normalized();
        return Eigen::Quaterniond(0, axis.x(), axis.y(), axis.z());
    }
    const double s = std::sqrt((1 + c) * 2);
    const Eigen::Vector3d v = a.cross(b) * (1 / s);
    return Eigen::Quaterniond(0.5 * s, v.x(), v.y(), v.z());
}

// Turns q, the end of a rotation step taken from qStart at constant momentum L, so that the body-frame
// momentum b = R^T L lies where it started on the energy ellipsoid: 1/2 b . I^-1 b = E(qStart). |b| = |L|
// already, so b is moved within its sphere along the energy's gradient (Newton steps, at most a quarter of
// |L| each, in double) and R is turned by the smallest rotation taking the new b to the old. The free
// rigid body conserves both |L| and E; a rotation step alone conserves only |L|, and its energy error
// grows when the body turns far in one step (at 100 rad/s and 120 Hz the intermediate-axis spin gained
// 100 %, drifting to the lightest axis). The kept energy makes the body-frame momentum stay on its own
// polhode, whatever the step: the orbit is exact, only its phase carries the integrator's error.
Quat keepRotationalEnergy(const Composite& c, const Quat& qStart, const Quat& q, const Vec3& L) {
    if (L.isZero(0)) return q; // no energy to keep: the test on the target below returns q as it is
    using V = Eigen::Vector3d;
    const Eigen::Matrix3d a = c.invInertia.cast<double>();
    const V l = L.cast<double>();
    // Unit in double: a float quaternion's |q|^2 = 1 +- 1e-7 would scale b, and the energy would walk by
    // that much a step (9e-5 over 10^4 steps at 10 rad/s and 1,000 Hz, against 2e-7 normalised).
    const V start = qStart.cast<double>().normalized().conjugate() * l;
    const V end = q.cast<double>().normalized().conjugate() * l;
    const double target = start.dot(a * start), r2 = end.squaredNorm(); // 2E, |L|^2
    if (!(r2 > 0) || !(target > 0)) return q;
    const double r = std::sqrt(r2);
    V b = end;
    for (int i = 0; i < 24; ++i) {
        const V ab = a * b;
        const double twoE = b.dot(ab), error = twoE - target;
        if (!(std::fabs(error) > 1e-12 * target)) break;
        const V g = ab - (twoE / r2) * b; // d(b.Ab)/dt along b + t g is 2 |g|^2
        const double g2 = g.squaredNorm();
        if (!(g2 > 1e-24 * target * target / r2)) break; // on a principal axis: nowhere to go
        double t = -error / (2 * g2);
        const double move = std::fabs(t) * std::sqrt(g2);
        if (move > 0.25 * r) t *= 0.25 * r / move;
        b = (b + t * g).normalized() * r;
    }
    return (q * Quat(shortestArc(b, end).cast<Real>())).normalized();
}

void explicitEuler(const Composite& c, MotionState& s, Real dt, bool turn) {
    Derivative d = evaluate(c, s, 0);
    s.x += s.v * dt; // the old velocity: this is what makes it "explicit" (and energy-gaining)
    s.v += d.acceleration * dt;
    if (c.rotationLocked) return;
    if (turn) s.q = keepRotationalEnergy(c, s.q, rotateBy(s.q, d.omega, dt), s.L);
    s.L += d.torque * dt;
}

void semiImplicitEuler(const Composite& c, MotionState& s, Real dt, bool turn) {
    Derivative d = evaluate(c, s, 0, false);
    s.v += d.acceleration * dt; // velocities first ...
    s.L += d.torque * dt;
    s.x += s.v * dt; // ... then positions with the new velocities (symplectic)
    if (!c.rotationLocked && turn) s.q = keepRotationalEnergy(c, s.q, rotateMidpoint(c, s.q, s.L, dt), s.L);
}

void velocityVerlet(const Composite& c, MotionState& s, Real dt, bool turn) {
    // Kick-drift-kick. A velocity-dependent force (drag) at the second kick is taken at the half-step
    // velocity, the usual explicit approximation; position-only forces keep the scheme exact to O(dt^2).
    Derivative d0 = evaluate(c, s, 0, false);
    Real h = 0.5f * dt;
    s.x += s.v * dt + d0.acceleration * (h * dt);
    s.v += d0.acceleration * h;
    s.L += d0.torque * h;
    if (!c.rotationLocked && turn) s.q = keepRotationalEnergy(c, s.q, rotateMidpoint(c, s.q, s.L, dt), s.L);
    Derivative d1 = evaluate(c, s, dt, false);
    s.v += d1.acceleration * h;
    s.L += d1.torque * h;
}

// q + dq/dt * h, renormalised (the quaternion's own RK stages).
Quat advanceQuat(const Quat& q, const Vec3& omega, Real h) {
    Quat w(0.0f, omega.x(), omega.y(), omega.z());
    Quat dq = w * q;
    return Quat(q.w() + 0.5f * h * dq.w(), q.x() + 0.5f * h * dq.x(), q.y() + 0.5f * h * dq.y(),
                q.z() + 0.5f * h * dq.z())
        .normalized();
}

MotionState stage(const MotionState& s, const MotionState& from, const Derivative& d, Real h) {
    MotionState out;
    out.x = s.x + from.v * h;
    out.v = s.v + d.acceleration * h;
    out.L = s.L + d.torque * h;
    out.q = advanceQuat(s.q, d.omega, h);
    return out;
}

void rungeKutta4(const Composite& c, MotionState& s, Real dt, bool turn) {
    Real h = 0.5f * dt;
    Derivative k1 = evaluate(c, s, 0);
    MotionState s2 = stage(s, s, k1, h);
    Derivative k2 = evaluate(c, s2, h);
    MotionState s3 = stage(s, s2, k2, h);
    Derivative k3 = evaluate(c, s3, h);
    MotionState s4 = stage(s, s3, k3, dt);
    Derivative k4 = evaluate(c, s4, dt);
    Real w = dt / 6.0f;
    s.x += (s.v + 2.0f * s2.v + 2.0f * s3.v + s4.v) * w;
    s.v += (k1.acceleration + 2.0f * k2.acceleration + 2.0f * k3.acceleration + k4.acceleration) * w;
    s.L += (k1.torque + 2.0f * k2.torque + 2.0f * k3.torque + k4.torque) * w;
    if (c.rotationLocked || !turn) return; // never turns, or turned by the caller
    // dq/dt = 1/2 (0, w) q, averaged over the four stages.
    Quat sum(0, 0, 0, 0);
    const MotionState* states[] = {&s, &s2, &s3, &s4};
    const Derivative* ks[] = {&k1, &k2, &k3, &k4};
    const Real weights[] = {1, 2, 2, 1};
    for (int i = 0; i < 4; ++i) {
        Quat dq = Quat(0.0f, ks[i]->omega.x(), ks[i]->omega.y(), ks[i]->omega.z()) * states[i]->q;
        sum.coeffs() += weights[i] * dq.coeffs();
    }
    const Quat start = s.q;
    s.q.coeffs() += (0.5f * w) * sum.coeffs();
    s.q.normalize();
    // A torque-free step (L unchanged) is a free rotation: its energy is kept. Under torque the stages'
    // momenta differ and RK4's own fourth-order energy stands.
    if (k1.torque.isZero(0) && k2.torque.isZero(0) && k3.torque.isZero(0) && k4.torque.isZero(0))
        s.q = keepRotationalEnergy(c, start, s.q, s.L);
}

} // namespace

bool rotationIrrelevant(const Composite& c) {
    if (c.parts.size() != 1 || c.hasGenerators || !c.parts[0].offset.isZero(0)) return false;
    const Mat3& a = c.invInertia;
    return a(0, 1) == 0 && a(0, 2) == 0 && a(1, 0) == 0 && a(1, 2) == 0 && a(2, 0) == 0 && a(2, 1) == 0 &&
           a(0, 0) == a(1, 1) && a(1, 1) == a(2, 2);
}

void integrate(Integrator which, const Composite& c, MotionState& s, Real dt, const Vec3& kinematicOmega,
               bool turn) {
    if (c.kinematic) { // immovable by forces: constant velocities, exact for every integrator
        s.x += s.v * dt;
        s.q = rotateBy(s.q, kinematicOmega, dt);
        return;
    }
    switch (which) {
    case INTEGRATOR_ExplicitEuler:
        explicitEuler(c, s, dt, turn);
        break;
    case INTEGRATOR_VelocityVerlet:
        velocityVerlet(c, s, dt, turn);
        break;
    case INTEGRATOR_RK4:
        rungeKutta4(c, s, dt, turn);
        break;
    default:
        semiImplicitEuler(c, s, dt, turn);
        break;
    }
}

} // namespace physics
