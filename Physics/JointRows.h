// JointRows.h - the building blocks joints are made of, as velocity constraints between two solver bodies:
// a point block (3 rows: two anchors together), an orientation block (3 rows: relative rotation held), and a
// one-dimensional row (a limit, a motor, an axis kept, a distance).
//
// A row's velocity is Cdot = n . (vB - vA) + armB . wB - armA . wA (n zero for an angular row). Its effective
// mass is 1 / K with K = (mA^-1 + mB^-1) |n|^2 + armA . IA^-1 armA + armB . IB^-1 armB. Each solve adds
//   lambda = -m (Cdot + bias) (rigid; Catto, "Iterative Dynamics with Temporal Coherence", GDC 2005),
// clamped so that the row's accumulated impulse stays within [lower, upper]. The bias corrects drift softly
// in the solver's push-out pass only (like the contacts' push out: moved by, then forgotten), so a joint
// never gains energy from its own correction. A limit is a one-sided row whose gap (how far from the limit)
// may close within the sub-step and no more (speculative, as the contacts' kept points).
// Blocks solve their three rows at once (K is 3x3), which converges where three rows one at a time would
// not (a chain of links: Jolt's PointConstraintPart and RotationEulerConstraintPart).
#pragma once

#include "SolverData.h"

#include <algorithm>
#include <limits>

namespace physics {

// The soft correction of a position error C: velocity target bias = biasRate C, the solve's mass scaled by
// massScale, and impulseScale of the accumulated impulse taken back (Catto, "Soft Step"; the contacts' own).
struct JointSoftness {
    Real biasRate = 0, massScale = 1, impulseScale = 0;
};

// A joint's anchor and axes on one body, in its root's frame (relative to the root's origin); the world's in
// world coordinates.
struct JointFrame {
    Vec3 point = Vec3::Zero();
    Quat basis = Quat::Identity(); // x is the joint's axis (hinge, slider, twist), y and z across it
};

// Where a frame is now on a solver body.
inline Vec3 worldPoint(const SolverBody& b, const JointFrame& f) { return b.origin + b.rotation * f.point; }
inline Quat worldBasis(const SolverBody& b, const JointFrame& f) { return b.rotation * f.basis; }

inline Mat3 cross(const Vec3& v) {
    Mat3 m;
    m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
    return m;
}

// What a row does with its error (set by its joint's prepare): nothing; hold C = error at 0; keep a gap =
// error >= 0 (a limit); drive Cdot to a target speed = error within [lower, upper] (a motor).
enum class RowKind : unsigned char { Off, Equal, Limit, Motor };

struct JointRow {
    RowKind kind = RowKind::Off;
    Real error = 0;
    Vec3 n = Vec3::Zero(), armA = Vec3::Zero(), armB = Vec3::Zero();
    Real mass = 0;
    Real impulse = 0, saved = 0; // accumulated this sub-step; before the push out
    Real lower = -std::numeric_limits<Real>::infinity(), upper = std::numeric_limits<Real>::infinity();

    void off() {
        kind = RowKind::Off;
        impulse = 0;
    }
    // A linear row along n between world points with arms rA, rB from the centres of mass.
    void setLinear(const SolverBody& a, const SolverBody& b, const Vec3& dir, const Vec3& rA,
                   const Vec3& rB) {
        n = dir;
        armA = rA.cross(dir);
        armB = rB.cross(dir);
        setMass(a, b);
    }
    // An angular row about axis.
    void setAngular(const SolverBody& a, const SolverBody& b, const Vec3& axis) {
        n = Vec3::Zero();
        armA = armB = axis;
        setMass(a, b);
    }
    void setMass(const SolverBody& a, const SolverBody& b) {
        const Real k = (a.invMass + b.invMass) * n.squaredNorm() + armA.dot(a.invInertia * armA) +
                       armB.dot(b.invInertia * armB);
        mass = k > 0 ? 1 / k : 0;
    }
    Real speed(const SolverBody& a, const SolverBody& b) const {
        return n.dot(b.v - a.v) + armB.dot(b.w) - armA.dot(a.w);
    }
    void apply(SolverBody& a, SolverBody& b, Real lambda) const {
        a.v -= (a.invMass * lambda) * n;
        a.w -= a.invInertia * (lambda * armA);
        b.v += (b.invMass * lambda) * n;
        b.w += b.invInertia * (lambda * armB);
    }
    // One solve toward Cdot = -bias, softly (massScale, impulseScale), the total kept in [lower, upper].
    void solve(SolverBody& a, SolverBody& b, Real bias, const JointSoftness& s = JointSoftness{}) {
        const Real change = -mass * s.massScale * (speed(a, b) + bias) - s.impulseScale * impulse;
        const Real total = std::clamp(impulse + change, lower, upper);
        apply(a, b, total - impulse);
        impulse = total;
    }
    // A one-sided limit whose gap (>= 0: that far from the limit) shrinks as Cdot < 0: the gap may close
    // within the sub-step (speculative); past the limit, the push-out pass corrects it softly.
    void solveLimit(SolverBody& a, SolverBody& b, Real gap, Real h, bool useBias, const JointSoftness& s) {
        if (gap > 0)
            solve(a, b, gap / h);
        else if (useBias)
            solve(a, b, s.biasRate * gap, s);
        else
            solve(a, b, 0);
    }
};

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

// The anchors pB and pA together: C = pB - pA, Cdot = vB + wB x rB - vA - wA x rA.
//
// A hinge's point acts at the lighter body's centre of mass instead (setSwingArms: that body's arm is zero):
// Cdot gains u (axis . (wB - wA)), u = axis x (the anchor from that centre), the point's motion as the body
// turns about the free axis; its turn across the axis is then the hinge's angular rows' alone. K is then
// D + c u u^T (c = axis . I^-1 axis of the light body) with D the rest, and a small body far out makes c
// |u|^2 many orders above D: K^-1 is applied as D^-1 less its rank-one part (Sherman-Morrison), and each
// solve's u-part, the one that turns the light body, is worked out in closed form and kept apart within the
// sub-step (swingImpulse), as float cannot resolve it from the impulse (a 4 cm box hinged 20 m out from a
// 1 t one flew off). Each prepare takes it anew from the impulse, along the u of the new poses.
struct PointBlock {
    Vec3 rA = Vec3::Zero(), rB = Vec3::Zero();
    Mat3 mass = Mat3::Zero(); // K^-1; with a swing, D^-1
    Vec3 impulse = Vec3::Zero(), saved = Vec3::Zero();
    bool swings = false;
    Vec3 swing = Vec3::Zero(), swingAxis = Vec3::Zero(), swingMass = Vec3::Zero(); // u, the axis, D^-1 u
    Real swingScale = 0, swingDenominator = 1;                                     // c, 1 + c u . D^-1 u
    Real swingImpulse = 0, savedSwing = 0;                                         // u . impulse
    // c |u|^2 against D along u: above about 10^7 float no longer resolves the light body's turn (measured:
    // a 0.1 kg, 4 cm box hinged 70 m out from a spinning 1 t box, 1.8 10^7, strayed 9 mm; at 100 m it flew).
    Real swingCondition = 0;

    void setArms(const SolverBody& a, const SolverBody& b, const Vec3& armA,
                 const Vec3& armB); // JointRows.cpp
    // The point at the light body's centre of mass (its arm zero), the other's arm reaching it.
    void setSwingArms(const SolverBody& a, const SolverBody& b, bool lightIsB, const Vec3& arm,
                      const Vec3& swingArm, const Vec3& axis); // JointRows.cpp
    // Cdot without the swing (a swinging block's own is solveSwing's).
    Vec3 speed(const SolverBody& a, const SolverBody& b) const {
        return b.v + b.w.cross(rB) - a.v - a.w.cross(rA);
    }
    void apply(SolverBody& a, SolverBody& b, const Vec3& lambda) const {
        a.v -= a.invMass * lambda;
        a.w -= a.invInertia * rA.cross(lambda);
        b.v += b.invMass * lambda;
        b.w += b.invInertia * rB.cross(lambda);
    }
    // With a swing: lambda and its u-part.
    void apply(SolverBody& a, SolverBody& b, const Vec3& lambda, Real swingLambda) const {
        const Vec3 turn = swingAxis * swingLambda;
        a.v -= a.invMass * lambda;
        a.w -= a.invInertia * (rA.cross(lambda) + turn);
        b.v += b.invMass * lambda;
        b.w += b.invInertia * (rB.cross(lambda) + turn);
    }
    void warmStart(SolverBody& a, SolverBody& b) const {
        if (swings)
            apply(a, b, impulse, swingImpulse);
        else
            apply(a, b, impulse);
    }
    void solve(SolverBody& a, SolverBody& b, const Vec3& bias, const JointSoftness& s = JointSoftness{}) {
        if (swings) {
            solveSwing(a, b, bias, s); // out of line: the plain solve stays small enough to inline
            return;
        }
        const Vec3 change = -s.massScale * (mass * (speed(a, b) + bias)) - s.impulseScale * impulse;
        apply(a, b, change);
        impulse += change;
    }
    void solveSwing(SolverBody& a, SolverBody& b, const Vec3& bias, const JointSoftness& s); // JointRows.cpp
};

// The relative rotation held: Cdot = wB - wA; the error is the rotation vector taking A's frame to B's.
struct OrientationBlock {
    Mat3 mass = Mat3::Zero();
    Vec3 impulse = Vec3::Zero(), saved = Vec3::Zero();

    void setMass(const SolverBody& a, const SolverBody& b); // JointRows.cpp
    void apply(SolverBody& a, SolverBody& b, const Vec3& lambda) const {
        a.w -= a.invInertia * lambda;
        b.w += b.invInertia * lambda;
    }
    void solve(SolverBody& a, SolverBody& b, const Vec3& bias, const JointSoftness& s = JointSoftness{}) {
        const Vec3 change = -s.massScale * (mass * (b.w - a.w + bias)) - s.impulseScale * impulse;
        apply(a, b, change);
        impulse += change;
    }
};

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

} // namespace physics
