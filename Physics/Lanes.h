// Lanes.h - four Reals side by side, one per lane, for the contact solver's wide rows (ContactBlocks.h): four
// manifolds are solved at once, each lane doing exactly the arithmetic the scalar code does for one.
// With float and SSE2 (every x86-64) a Lanes is one SSE register; otherwise (a double build, another CPU)
// it is a plain array the compiler may vectorise itself. Either way each lane rounds as the scalar code
// would: the same operations in the same order, no fused multiply-add. Lanes3 is a vector per lane, with the
// few vector operations the blocks need, each in Eigen's order.
#pragma once

#include "MathBridge.h"

#if defined(__SSE2__) && !GUARDIAN_REAL_IS_DOUBLE
#define GUARDIAN_SSE_LANES 1
#include <xmmintrin.h>
#else
#define GUARDIAN_SSE_LANES 0
#endif

namespace physics {

constexpr int kLanes = 4;

#if GUARDIAN_SSE_LANES

// Stored as four floats (a lane is read and written in place when rows are packed); the arithmetic loads
// them into one register, where the compiler keeps them.
struct Lanes {
    alignas(16) float f[4];
    Lanes() : f{0, 0, 0, 0} {}
    explicit Lanes(__m128 x) { _mm_store_ps(f, x); }
    explicit Lanes(float x) : f{x, x, x, x} {}
    __m128 v() const { return _mm_load_ps(f); }
    float lane(int i) const { return f[i]; }
    void setLane(int i, float x) { f[i] = x; }
};
// A lane mask: all bits set where a comparison holds.
using LaneMask = Lanes;

inline Lanes operator+(Lanes a, Lanes b) { return Lanes(_mm_add_ps(a.v(), b.v())); }
inline Lanes operator-(Lanes a, Lanes b) { return Lanes(_mm_sub_ps(a.v(), b.v())); }
inline Lanes operator*(Lanes a, Lanes b) { return Lanes(_mm_mul_ps(a.v(), b.v())); }
inline Lanes operator/(Lanes a, Lanes b) { return Lanes(_mm_div_ps(a.v(), b.v())); }
inline Lanes operator-(Lanes a) { return Lanes(_mm_xor_ps(a.v(), _mm_set1_ps(-0.0f))); }
// std::max(a, b) lane by lane, the same operand returned on ties.
inline Lanes maxOf(Lanes a, Lanes b) { return Lanes(_mm_max_ps(b.v(), a.v())); }
inline LaneMask less(Lanes a, Lanes b) { return Lanes(_mm_cmplt_ps(a.v(), b.v())); }
inline LaneMask andMask(LaneMask a, LaneMask b) { return Lanes(_mm_and_ps(a.v(), b.v())); }
inline LaneMask orMask(LaneMask a, LaneMask b) { return Lanes(_mm_or_ps(a.v(), b.v())); }
// where ? yes : no, lane by lane.
inline Lanes select(LaneMask where, Lanes yes, Lanes no) {
    return Lanes(_mm_or_ps(_mm_and_ps(where.v(), yes.v()), _mm_andnot_ps(where.v(), no.v())));
}

#else

struct Lanes {
    Real v[kLanes];
    Lanes() : v{0, 0, 0, 0} {}
    explicit Lanes(Real x) : v{x, x, x, x} {}
    Real lane(int i) const { return v[i]; }
    void setLane(int i, Real x) { v[i] = x; }
};
struct LaneMask {
    bool v[kLanes];
};

#define GUARDIAN_LANEWISE(expr)                                                                              \
    Lanes r;                                                                                                 \
    for (int i = 0; i < kLanes; ++i) r.v[i] = (expr);                                                        \
    return r
inline Lanes operator+(Lanes a, Lanes b) { GUARDIAN_LANEWISE(a.v[i] + b.v[i]); }
inline Lanes operator-(Lanes a, Lanes b) { GUARDIAN_LANEWISE(a.v[i] - b.v[i]); }
inline Lanes operator*(Lanes a, Lanes b) { GUARDIAN_LANEWISE(a.v[i] * b.v[i]); }
inline Lanes operator/(Lanes a, Lanes b) { GUARDIAN_LANEWISE(a.v[i] / b.v[i]); }
inline Lanes operator-(Lanes a) { GUARDIAN_LANEWISE(-a.v[i]); }
inline Lanes maxOf(Lanes a, Lanes b) { GUARDIAN_LANEWISE(a.v[i] < b.v[i] ? b.v[i] : a.v[i]); }
#undef GUARDIAN_LANEWISE
#define GUARDIAN_MASKWISE(expr)                                                                              \
    LaneMask r;                                                                                              \
    for (int i = 0; i < kLanes; ++i) r.v[i] = (expr);                                                        \
    return r
inline LaneMask less(Lanes a, Lanes b) { GUARDIAN_MASKWISE(a.v[i] < b.v[i]); }
inline LaneMask andMask(LaneMask a, LaneMask b) { GUARDIAN_MASKWISE(a.v[i] && b.v[i]); }
inline LaneMask orMask(LaneMask a, LaneMask b) { GUARDIAN_MASKWISE(a.v[i] || b.v[i]); }
#undef GUARDIAN_MASKWISE
inline Lanes select(LaneMask where, Lanes yes, Lanes no) {
    Lanes r;
    for (int i = 0; i < kLanes; ++i) r.v[i] = where.v[i] ? yes.v[i] : no.v[i];
    return r;
}

#endif

// std::clamp(x, lo, hi) lane by lane (x < lo ? lo : hi < x ? hi : x).
inline Lanes clampOf(Lanes x, Lanes lo, Lanes hi) {
    return select(less(x, lo), lo, select(less(hi, x), hi, x));
}

// Three Lanes: one vector per lane.
struct Lanes3 {
    Lanes x, y, z;
};
inline Lanes3 operator+(const Lanes3& a, const Lanes3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Lanes3 operator-(const Lanes3& a, const Lanes3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Lanes3 operator*(Lanes s, const Lanes3& a) { return {s * a.x, s * a.y, s * a.z}; }
// The dot product in the order Eigen's Vec3 dot adds: x + (y + z).
inline Lanes dot(const Lanes3& a, const Lanes3& b) { return a.x * b.x + (a.y * b.y + a.z * b.z); }

// Lane `lane` of l set to v.
inline void setLanes3(Lanes3& l, int lane, const Vec3& v) {
    l.x.setLane(lane, v.x());
    l.y.setLane(lane, v.y());
    l.z.setLane(lane, v.z());
}

// The cross product in Eigen's order.
inline Lanes3 crossLanes(const Lanes3& a, const Lanes3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// q v q^-1 as Eigen's Quaternion::_transformVector computes it.
inline Lanes3 rotateLanes(const Lanes3& qv, const Lanes& qw, const Lanes3& v) {
    Lanes3 uv = crossLanes(qv, v);
    uv = uv + uv;
    return (v + qw * uv) + crossLanes(qv, uv);
}

#if GUARDIAN_SSE_LANES
// Four 4-Real rows (x, y, z, 0) as three Lanes of x, y and z.
inline Lanes3 gatherRows(const float* r0, const float* r1, const float* r2, const float* r3) {
    __m128 a = _mm_load_ps(r0), b = _mm_load_ps(r1), c = _mm_load_ps(r2), d = _mm_load_ps(r3);
    _MM_TRANSPOSE4_PS(a, b, c, d);
    return Lanes3{Lanes(a), Lanes(b), Lanes(c)};
}
inline void scatterRows(const Lanes3& l, float* r0, float* r1, float* r2, float* r3) {
    __m128 a = l.x.v(), b = l.y.v(), c = l.z.v(), d = _mm_setzero_ps();
    _MM_TRANSPOSE4_PS(a, b, c, d);
    _mm_store_ps(r0, a);
    _mm_store_ps(r1, b);
    _mm_store_ps(r2, c);
    _mm_store_ps(r3, d);
}
#else
inline Lanes3 gatherRows(const Real* r0, const Real* r1, const Real* r2, const Real* r3) {
    const Real* rows[4] = {r0, r1, r2, r3};
    Lanes3 l;
    for (int i = 0; i < kLanes; ++i) {
        l.x.v[i] = rows[i][0];
        l.y.v[i] = rows[i][1];
        l.z.v[i] = rows[i][2];
    }
    return l;
}
inline void scatterRows(const Lanes3& l, Real* r0, Real* r1, Real* r2, Real* r3) {
    Real* rows[4] = {r0, r1, r2, r3};
    for (int i = 0; i < kLanes; ++i) {
        rows[i][0] = l.x.v[i];
        rows[i][1] = l.y.v[i];
        rows[i][2] = l.z.v[i];
        rows[i][3] = 0;
    }
}
#endif

} // namespace physics
