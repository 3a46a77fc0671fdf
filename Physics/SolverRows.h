// SolverRows.h - helpers shared by the solver's files: the relative speed along a contact's normal, an
// impulse along it, and where a body-local anchor is now.
#pragma once

#include "SolverData.h"

namespace physics {

inline bool movable(const SolverBody& b) { return b.root && b.invMass > 0.0f; }

// The relative velocity of b against a at the point, along its normal (row: the point's normal row).
inline Real normalSpeed(const SolverBody& a, const SolverBody& b, const ManifoldPoint& p,
                        const NormalRow& row) {
    return p.normal.dot(b.v - a.v) + row.armB.dot(b.w) - row.armA.dot(a.w);
}

// An impulse along the normal: on b, and its opposite on a.
inline void applyNormalImpulse(SolverBody& a, SolverBody& b, const ManifoldPoint& p, const NormalRow& row,
                               Real impulse) {
    a.v -= (a.invMass * impulse) * p.normal;
    a.w -= impulse * row.turnA;
    b.v += (b.invMass * impulse) * p.normal;
    b.w += impulse * row.turnB;
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
inline Real separation(const SolverBody& a, const SolverBody& b, const ManifoldPoint& p) {
    return p.normal.dot(worldPoint(b, p.anchorB) - worldPoint(a, p.anchorA));
}

} // namespace physics
