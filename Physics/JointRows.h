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
//
// Here the layouts; the members' bodies and the helpers joints build rows with are in JointRowsInline.h (for
// the files that solve joints), the blocks' effective masses in JointRows.cpp.
#pragma once

#include "SolverData.h"

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

    inline void off();
    // A linear row along n between world points with arms rA, rB from the centres of mass.
    inline void setLinear(const SolverBody& a, const SolverBody& b, const Vec3& dir, const Vec3& rA,
                          const Vec3& rB);
    // An angular row about axis.
    inline void setAngular(const SolverBody& a, const SolverBody& b, const Vec3& axis);
    inline void setMass(const SolverBody& a, const SolverBody& b);
    inline Real speed(const SolverBody& a, const SolverBody& b) const;
    inline void apply(SolverBody& a, SolverBody& b, Real lambda) const;
    // One solve toward Cdot = -bias, softly (massScale, impulseScale), the total kept in [lower, upper].
    inline void solve(SolverBody& a, SolverBody& b, Real bias, const JointSoftness& s = JointSoftness{});
    // A one-sided limit whose gap (>= 0: that far from the limit) shrinks as Cdot < 0: the gap may close
    // within the sub-step (speculative); past the limit, the push-out pass corrects it softly.
    inline void solveLimit(SolverBody& a, SolverBody& b, Real gap, Real h, bool useBias,
                           const JointSoftness& s);
};

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
    inline Vec3 speed(const SolverBody& a, const SolverBody& b) const;
    inline void apply(SolverBody& a, SolverBody& b, const Vec3& lambda) const;
    // With a swing: lambda and its u-part.
    inline void apply(SolverBody& a, SolverBody& b, const Vec3& lambda, Real swingLambda) const;
    inline void warmStart(SolverBody& a, SolverBody& b) const;
    inline void solve(SolverBody& a, SolverBody& b, const Vec3& bias,
                      const JointSoftness& s = JointSoftness{});
    void solveSwing(SolverBody& a, SolverBody& b, const Vec3& bias, const JointSoftness& s); // JointRows.cpp
};

// The relative rotation held: Cdot = wB - wA; the error is the rotation vector taking A's frame to B's.
struct OrientationBlock {
    Mat3 mass = Mat3::Zero();
    Vec3 impulse = Vec3::Zero(), saved = Vec3::Zero();

    void setMass(const SolverBody& a, const SolverBody& b); // JointRows.cpp
    inline void apply(SolverBody& a, SolverBody& b, const Vec3& lambda) const;
    inline void solve(SolverBody& a, SolverBody& b, const Vec3& bias,
                      const JointSoftness& s = JointSoftness{});
};

} // namespace physics
