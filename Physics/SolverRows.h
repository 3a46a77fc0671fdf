// SolverRows.h - the solver's inner-loop helpers, shared by its files: a contact row's direction, the
// relative speed along it, an impulse along it, and where a body-local anchor is now.
#pragma once

#include "ContactManifold.h"

namespace physics {

inline bool movable(const SolverBody& b) { return b.root && b.invMass > 0.0f; }

// Row 0 is the normal, rows 1 and 2 the tangents; the row is a template argument so that the hot loops
// compile without a branch per impulse.
template <int Row> const Vec3& direction(const ContactPoint& p) {
    if constexpr (Row == 0)
        return p.normal;
    else
        return p.tangent[Row - 1];
}

// The relative velocity of b against a at the point, along a row's direction.
template <int Row>
inline Real relativeSpeed(const SolverBody& a, const SolverBody& b, const ContactPoint& p) {
    return direction<Row>(p).dot(b.v - a.v) + narrow(p.armB[Row]).dot(b.w) - narrow(p.armA[Row]).dot(a.w);
}

// An impulse along a row's direction: on b, and its opposite on a.
template <int Row>
inline void applyImpulse(SolverBody& a, SolverBody& b, const ContactPoint& p, Real impulse) {
    const Vec3& d = direction<Row>(p);
    a.v -= (a.invMass * impulse) * d;
    a.w -= impulse * narrow(p.turnA[Row]);
    b.v += (b.invMass * impulse) * d;
    b.w += impulse * narrow(p.turnB[Row]);
}

// Where an anchor was at the step's start, where the contacts were found.
inline Vec3 startPoint(const SolverBody& b, const Vec3& anchor) {
    return b.root ? Vec3(b.startRotation * anchor + b.startOrigin) : anchor;
}

// Where an anchor is now (the static world's anchors are world points).
inline Vec3 worldPoint(const SolverBody& b, const Vec3& anchor) {
    return b.root ? Vec3(b.rotation * anchor + b.origin) : anchor;
}

// The point's separation along its normal now (negative: overlap).
inline Real separation(const SolverBody& a, const SolverBody& b, const ContactPoint& p) {
    return p.normal.dot(worldPoint(b, p.anchorB) - worldPoint(a, p.anchorA));
}

} // namespace physics
