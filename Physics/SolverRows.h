// SolverRows.h - the solver's inner-loop helpers, shared by its files: a contact row's direction, the
// relative speed along it, an impulse along it, and where a body-local anchor is now.
#pragma once

#include "ContactManifold.h"

// The 4-wide SSE sum is for float rows; a double build (GUARDIAN_DOUBLE) takes the plain scalar sum.
#if defined(__SSE2__) && !GUARDIAN_REAL_IS_DOUBLE
#define GUARDIAN_SSE_ROWS 1
#include <xmmintrin.h>
#else
#define GUARDIAN_SSE_ROWS 0
#endif

// The inner loops' helpers: asked to be inlined, for the manifold's velocities to stay in registers (the
// compiler declines on its own, as they are called from several places).
#if defined(__GNUC__) || defined(__clang__)
#define GUARDIAN_HOT inline __attribute__((always_inline))
#else
#define GUARDIAN_HOT inline
#endif

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

// (x0 + x1 + x2) + (y0 + y1 + y2) - (z0 + z1 + z2), each sum in the order Eigen's Vec3 dot adds (x0 + (x1 +
// x2)), so that the 4-wide rows give the same bits as the Vec3 arithmetic the solver was tuned with: three
// sums at once, lanes transposed.
GUARDIAN_HOT Real sumOfDots(const Vec4& x, const Vec4& y, const Vec4& z) {
#if GUARDIAN_SSE_ROWS
    __m128 r0 = _mm_loadu_ps(x.data()), r1 = _mm_loadu_ps(y.data()), r2 = _mm_loadu_ps(z.data()),
           r3 = _mm_setzero_ps();
    _MM_TRANSPOSE4_PS(r0, r1, r2, r3); // r_i = (x_i, y_i, z_i, 0)
    const __m128 sums = _mm_add_ps(r0, _mm_add_ps(r1, r2));
    alignas(16) float out[4];
    _mm_store_ps(out, sums);
    return out[0] + out[1] - out[2];
#else
    return (x[0] + (x[1] + x[2])) + (y[0] + (y[1] + y[2])) - (z[0] + (z[1] + z[2]));
#endif
}

// The velocities of a manifold's two bodies while its points are solved, 4-wide: copied in once and back
// once, so that they stay in registers. (Through two SolverBody references that might alias, with Vec3
// components shuffled in and out, a row took ~105 instructions in the awake pyramid's inner loop.)
struct PairVelocity {
    Vec4 va, wa, vb, wb;
    Real ima, imb;
    PairVelocity(const SolverBody& a, const SolverBody& b)
        : va(wide(a.v)), wa(wide(a.w)), vb(wide(b.v)), wb(wide(b.w)), ima(a.invMass), imb(b.invMass) {}
    // An immovable body (the static world, fixed, kinematic) is never written: what it gained was 0 x
    // impulse, which is its own velocity again, except when an impulse is not finite (a NaN the game wrote
    // with validation switched off), which would pass through it to everything else on the same ground.
    void store(SolverBody& a, SolverBody& b) const {
        if (ima > 0) {
            a.v = narrow(va);
            a.w = narrow(wa);
        }
        if (imb > 0) {
            b.v = narrow(vb);
            b.w = narrow(wb);
        }
    }
    template <int Row> GUARDIAN_HOT Real speed(const ContactPoint& p) const {
        return sumOfDots(p.dir[Row].cwiseProduct(vb - va), p.armB[Row].cwiseProduct(wb),
                         p.armA[Row].cwiseProduct(wa));
    }
    template <int Row> GUARDIAN_HOT void apply(const ContactPoint& p, Real impulse) {
        va -= (ima * impulse) * p.dir[Row];
        wa -= impulse * p.turnA[Row];
        vb += (imb * impulse) * p.dir[Row];
        wb += impulse * p.turnB[Row];
    }
};

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
