// JointRowsInline.h - the bodies of JointRows.h's rows and blocks, and the small functions joints build
// their rows with: for the files that solve joints. Apart from JointRows.h because Eigen's expression
// templates in them, instantiated in every file that includes it, cost about 0.7 s of compile time a file,
// and most files that reach JointRows.h (through ContactSolver.h and PhysicsScene.h) need only its layouts
// (a member declared inline and used without this header is a compiler warning, an error in our builds, and
// fails to link: none is missed).
#pragma once

#include "JointRows.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace physics {

// Where a frame is now on a solver body.
inline Vec3 worldPoint(const SolverBody& b, const JointFrame& f) { return b.origin + b.rotation * f.point; }

inline Quat worldBasis(const SolverBody& b, const JointFrame& f) { return b.rotation * f.basis; }

inline Mat3 cross(const Vec3& v) {
    Mat3 m;
    m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
    return m;
}

// A one-sided limit row: its impulse only pushes (gap >= 0 kept).
inline void makeLimit(JointRow& r, Real gap) {
    r.kind = RowKind::Limit;
    r.error = gap;
    r.lower = 0;
    r.upper = std::numeric_limits<Real>::infinity();
}

inline void makeEqual(JointRow& r, Real c) {
    r.kind = RowKind::Equal;
    r.error = c;
    r.lower = -std::numeric_limits<Real>::infinity();
    r.upper = std::numeric_limits<Real>::infinity();
}

inline void makeMotor(JointRow& r, Real speed, Real maxImpulse) {
    r.kind = RowKind::Motor;
    r.error = speed;
    r.lower = -maxImpulse;
    r.upper = maxImpulse;
}

// Where a joint's linear rows act when they act at a centre of mass (the weld, the slider, the hinge's
// point): the lighter body's (B's on a tie), so that a small body far out is not turned by its own linear
// rows.
inline bool bIsLighter(const SolverBody& a, const SolverBody& b) { return b.invMass >= a.invMass; }

// The small rotation (axis times angle) that turns frame qA into qB, both world.
inline Vec3 rotationError(const Quat& qA, const Quat& qB) {
    Quat e = qB * qA.conjugate();
    if (e.w() < 0) e.coeffs() = -e.coeffs();
    return 2 * e.vec();
}

// B's turn relative to A about their common x axis (the twist of a swing-twist split), in (-pi, pi].
inline Real twistAngle(const Quat& qA, const Quat& qB) {
    const Quat r = qA.conjugate() * qB; // B in A's joint axes
    Real angle = 2 * std::atan2(r.x(), r.w());
    if (angle > Real(3.14159265358979)) angle -= Real(6.28318530717959);
    if (angle <= -Real(3.14159265358979)) angle += Real(6.28318530717959);
    return angle;
}

inline void JointRow::off() {
    kind = RowKind::Off;
    impulse = 0;
}

inline void JointRow::setLinear(const SolverBody& a, const SolverBody& b, const Vec3& dir, const Vec3& rA,
                                const Vec3& rB) {
    n = dir;
    armA = rA.cross(dir);
    armB = rB.cross(dir);
    setMass(a, b);
}

inline void JointRow::setAngular(const SolverBody& a, const SolverBody& b, const Vec3& axis) {
    n = Vec3::Zero();
    armA = armB = axis;
    setMass(a, b);
}

inline void JointRow::setMass(const SolverBody& a, const SolverBody& b) {
    const Real k = (a.invMass + b.invMass) * n.squaredNorm() + armA.dot(a.invInertia * armA) +
                   armB.dot(b.invInertia * armB);
    mass = k > 0 ? 1 / k : 0;
}

inline Real JointRow::speed(const SolverBody& a, const SolverBody& b) const {
    return n.dot(b.v - a.v) + armB.dot(b.w) - armA.dot(a.w);
}

inline void JointRow::apply(SolverBody& a, SolverBody& b, Real lambda) const {
    a.v -= (a.invMass * lambda) * n;
    a.w -= a.invInertia * (lambda * armA);
    b.v += (b.invMass * lambda) * n;
    b.w += b.invInertia * (lambda * armB);
}

inline void JointRow::solve(SolverBody& a, SolverBody& b, Real bias, const JointSoftness& s) {
    const Real change = -mass * s.massScale * (speed(a, b) + bias) - s.impulseScale * impulse;
    const Real total = std::clamp(impulse + change, lower, upper);
    apply(a, b, total - impulse);
    impulse = total;
}

inline void JointRow::solveLimit(SolverBody& a, SolverBody& b, Real gap, Real h, bool useBias,
                                 const JointSoftness& s) {
    if (gap > 0)
        solve(a, b, gap / h);
    else if (useBias)
        solve(a, b, s.biasRate * gap, s);
    else
        solve(a, b, 0);
}

inline Vec3 PointBlock::speed(const SolverBody& a, const SolverBody& b) const {
    return b.v + b.w.cross(rB) - a.v - a.w.cross(rA);
}

inline void PointBlock::apply(SolverBody& a, SolverBody& b, const Vec3& lambda) const {
    a.v -= a.invMass * lambda;
    a.w -= a.invInertia * rA.cross(lambda);
    b.v += b.invMass * lambda;
    b.w += b.invInertia * rB.cross(lambda);
}

inline void PointBlock::apply(SolverBody& a, SolverBody& b, const Vec3& lambda, Real swingLambda) const {
    const Vec3 turn = swingAxis * swingLambda;
    a.v -= a.invMass * lambda;
    a.w -= a.invInertia * (rA.cross(lambda) + turn);
    b.v += b.invMass * lambda;
    b.w += b.invInertia * (rB.cross(lambda) + turn);
}

inline void PointBlock::warmStart(SolverBody& a, SolverBody& b) const {
    if (swings)
        apply(a, b, impulse, swingImpulse);
    else
        apply(a, b, impulse);
}

inline void PointBlock::solve(SolverBody& a, SolverBody& b, const Vec3& bias, const JointSoftness& s) {
    if (swings) {
        solveSwing(a, b, bias, s); // out of line: the plain solve stays small enough to inline
        return;
    }
    const Vec3 change = -s.massScale * (mass * (speed(a, b) + bias)) - s.impulseScale * impulse;
    apply(a, b, change);
    impulse += change;
}

inline void OrientationBlock::apply(SolverBody& a, SolverBody& b, const Vec3& lambda) const {
    a.w -= a.invInertia * lambda;
    b.w += b.invInertia * lambda;
}

inline void OrientationBlock::solve(SolverBody& a, SolverBody& b, const Vec3& bias, const JointSoftness& s) {
    const Vec3 change = -s.massScale * (mass * (b.w - a.w + bias)) - s.impulseScale * impulse;
    apply(a, b, change);
    impulse += change;
}

} // namespace physics
