// Lanes.h - kLanes Reals side by side, one per lane, for the contact solver's wide rows (ContactBlocks.h):
// that many manifolds are solved at once, each lane doing exactly the arithmetic the scalar code does for
// one. With float and SSE2 (every x86-64) a Lanes is one SSE register of four; in a build for AVX (-mavx,
// GUARDIAN_AVX) one 256-bit register of eight, which halves the solver's instructions per manifold; in a
// double build with SSE2 two registers of two doubles; otherwise (another CPU) a plain array of four the
// compiler may vectorise itself. Either way each lane rounds as the scalar code would: the same operations in
// the same order, no fused multiply-add, so every width gives the same bits (the determinism hashes hold for
// all of them; the double build has its own).
#pragma once

#include "MathBridge.h"

#if defined(__SSE2__) && !GUARDIAN_REAL_IS_DOUBLE
#define GUARDIAN_SSE_LANES 1
#include <xmmintrin.h>
#if defined(__AVX__) // a build for AVX (-mavx, -march=native): eight lanes, one 256-bit register
#define GUARDIAN_AVX_LANES 1
#include <immintrin.h>
#else
#define GUARDIAN_AVX_LANES 0
#endif
#else
#define GUARDIAN_SSE_LANES 0
#define GUARDIAN_AVX_LANES 0
#endif
#if defined(__SSE2__) && GUARDIAN_REAL_IS_DOUBLE
#define GUARDIAN_DOUBLE_LANES 1
#include <emmintrin.h>
#else
#define GUARDIAN_DOUBLE_LANES 0
#endif

// A function the sweeps' hot loops always inline, whatever the compiler's own weighing says.
#if defined(__GNUC__) || defined(__clang__)
#define GUARDIAN_ALWAYS_INLINE inline __attribute__((always_inline))
#elif defined(_MSC_VER)
#define GUARDIAN_ALWAYS_INLINE __forceinline
#else
#define GUARDIAN_ALWAYS_INLINE inline
#endif

namespace physics {

#if GUARDIAN_AVX_LANES
constexpr int kLanes = 8;
#else
constexpr int kLanes = 4;
#endif

#if GUARDIAN_SSE_LANES

#if GUARDIAN_AVX_LANES
using LaneRegister = __m256;
#define GUARDIAN_LANE_OP(name) _mm256_##name
#else
using LaneRegister = __m128;
#define GUARDIAN_LANE_OP(name) _mm_##name
#endif

// Stored as kLanes floats (a lane is read and written in place when rows are packed); the arithmetic loads
// them into one register, where the compiler keeps them.
struct Lanes {
    alignas(4 * kLanes) float f[kLanes];
    Lanes() : f{} {}
    explicit Lanes(LaneRegister x) { GUARDIAN_LANE_OP(store_ps)(f, x); }
    explicit Lanes(float x) { GUARDIAN_LANE_OP(store_ps)(f, GUARDIAN_LANE_OP(set1_ps)(x)); }
    LaneRegister v() const { return GUARDIAN_LANE_OP(load_ps)(f); }
    float lane(int i) const { return f[i]; }
    void setLane(int i, float x) { f[i] = x; }
};
// A lane mask: all bits set where a comparison holds.
using LaneMask = Lanes;

GUARDIAN_ALWAYS_INLINE Lanes operator+(Lanes a, Lanes b) {
    return Lanes(GUARDIAN_LANE_OP(add_ps)(a.v(), b.v()));
}
GUARDIAN_ALWAYS_INLINE Lanes operator-(Lanes a, Lanes b) {
    return Lanes(GUARDIAN_LANE_OP(sub_ps)(a.v(), b.v()));
}
GUARDIAN_ALWAYS_INLINE Lanes operator*(Lanes a, Lanes b) {
    return Lanes(GUARDIAN_LANE_OP(mul_ps)(a.v(), b.v()));
}
GUARDIAN_ALWAYS_INLINE Lanes operator/(Lanes a, Lanes b) {
    return Lanes(GUARDIAN_LANE_OP(div_ps)(a.v(), b.v()));
}
GUARDIAN_ALWAYS_INLINE Lanes operator-(Lanes a) {
    return Lanes(GUARDIAN_LANE_OP(xor_ps)(a.v(), GUARDIAN_LANE_OP(set1_ps)(-0.0f)));
}
// std::max(a, b) lane by lane, the same operand returned on ties.
GUARDIAN_ALWAYS_INLINE Lanes maxOf(Lanes a, Lanes b) { return Lanes(GUARDIAN_LANE_OP(max_ps)(b.v(), a.v())); }
#if GUARDIAN_AVX_LANES
GUARDIAN_ALWAYS_INLINE LaneMask less(Lanes a, Lanes b) {
    return Lanes(_mm256_cmp_ps(a.v(), b.v(), _CMP_LT_OS));
}
#else
GUARDIAN_ALWAYS_INLINE LaneMask less(Lanes a, Lanes b) { return Lanes(_mm_cmplt_ps(a.v(), b.v())); }
#endif
GUARDIAN_ALWAYS_INLINE LaneMask andMask(LaneMask a, LaneMask b) {
    return Lanes(GUARDIAN_LANE_OP(and_ps)(a.v(), b.v()));
}
GUARDIAN_ALWAYS_INLINE LaneMask orMask(LaneMask a, LaneMask b) {
    return Lanes(GUARDIAN_LANE_OP(or_ps)(a.v(), b.v()));
}
// where ? yes : no, lane by lane.
GUARDIAN_ALWAYS_INLINE Lanes select(LaneMask where, Lanes yes, Lanes no) {
    return Lanes(GUARDIAN_LANE_OP(or_ps)(GUARDIAN_LANE_OP(and_ps)(where.v(), yes.v()),
                                         GUARDIAN_LANE_OP(andnot_ps)(where.v(), no.v())));
}
#undef GUARDIAN_LANE_OP

#elif GUARDIAN_DOUBLE_LANES

// A double build on SSE2: four doubles in two 128-bit registers, each the IEEE operation of the scalar code
// (the plain array below, left to the compiler, took a 210-box pyramid's step 1.9x float's time).
static_assert(kLanes == 4, "a double build's Lanes are two registers of two");
struct Lanes {
    alignas(16) double v[kLanes];
    Lanes() : v{0, 0, 0, 0} {}
    Lanes(__m128d lo, __m128d hi) {
        _mm_store_pd(v, lo);
        _mm_store_pd(v + 2, hi);
    }
    explicit Lanes(double x) : v{x, x, x, x} {}
    __m128d lo() const { return _mm_load_pd(v); }
    __m128d hi() const { return _mm_load_pd(v + 2); }
    double lane(int i) const { return v[i]; }
    void setLane(int i, double x) { v[i] = x; }
};
// A lane mask: all bits set where a comparison holds.
using LaneMask = Lanes;

#define GUARDIAN_PAIRWISE(op) return Lanes(op(a.lo(), b.lo()), op(a.hi(), b.hi()))
GUARDIAN_ALWAYS_INLINE Lanes operator+(Lanes a, Lanes b) { GUARDIAN_PAIRWISE(_mm_add_pd); }
GUARDIAN_ALWAYS_INLINE Lanes operator-(Lanes a, Lanes b) { GUARDIAN_PAIRWISE(_mm_sub_pd); }
GUARDIAN_ALWAYS_INLINE Lanes operator*(Lanes a, Lanes b) { GUARDIAN_PAIRWISE(_mm_mul_pd); }
GUARDIAN_ALWAYS_INLINE Lanes operator/(Lanes a, Lanes b) { GUARDIAN_PAIRWISE(_mm_div_pd); }
GUARDIAN_ALWAYS_INLINE Lanes operator-(Lanes a) {
    const Lanes b(-0.0);
    GUARDIAN_PAIRWISE(_mm_xor_pd);
}
// std::max(a, b) lane by lane, the same operand returned on ties.
GUARDIAN_ALWAYS_INLINE Lanes maxOf(Lanes a, Lanes b) {
    return Lanes(_mm_max_pd(b.lo(), a.lo()), _mm_max_pd(b.hi(), a.hi()));
}
GUARDIAN_ALWAYS_INLINE LaneMask less(Lanes a, Lanes b) { GUARDIAN_PAIRWISE(_mm_cmplt_pd); }
GUARDIAN_ALWAYS_INLINE LaneMask andMask(LaneMask a, LaneMask b) { GUARDIAN_PAIRWISE(_mm_and_pd); }
GUARDIAN_ALWAYS_INLINE LaneMask orMask(LaneMask a, LaneMask b) { GUARDIAN_PAIRWISE(_mm_or_pd); }
#undef GUARDIAN_PAIRWISE
GUARDIAN_ALWAYS_INLINE Lanes select(LaneMask where, Lanes yes, Lanes no) {
    return Lanes(_mm_or_pd(_mm_and_pd(where.lo(), yes.lo()), _mm_andnot_pd(where.lo(), no.lo())),
                 _mm_or_pd(_mm_and_pd(where.hi(), yes.hi()), _mm_andnot_pd(where.hi(), no.hi())));
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
GUARDIAN_ALWAYS_INLINE Lanes operator+(Lanes a, Lanes b) { GUARDIAN_LANEWISE(a.v[i] + b.v[i]); }
GUARDIAN_ALWAYS_INLINE Lanes operator-(Lanes a, Lanes b) { GUARDIAN_LANEWISE(a.v[i] - b.v[i]); }
GUARDIAN_ALWAYS_INLINE Lanes operator*(Lanes a, Lanes b) { GUARDIAN_LANEWISE(a.v[i] * b.v[i]); }
GUARDIAN_ALWAYS_INLINE Lanes operator/(Lanes a, Lanes b) { GUARDIAN_LANEWISE(a.v[i] / b.v[i]); }
GUARDIAN_ALWAYS_INLINE Lanes operator-(Lanes a) { GUARDIAN_LANEWISE(-a.v[i]); }
GUARDIAN_ALWAYS_INLINE Lanes maxOf(Lanes a, Lanes b) { GUARDIAN_LANEWISE(a.v[i] < b.v[i] ? b.v[i] : a.v[i]); }
#undef GUARDIAN_LANEWISE
#define GUARDIAN_MASKWISE(expr)                                                                              \
    LaneMask r;                                                                                              \
    for (int i = 0; i < kLanes; ++i) r.v[i] = (expr);                                                        \
    return r
GUARDIAN_ALWAYS_INLINE LaneMask less(Lanes a, Lanes b) { GUARDIAN_MASKWISE(a.v[i] < b.v[i]); }
GUARDIAN_ALWAYS_INLINE LaneMask andMask(LaneMask a, LaneMask b) { GUARDIAN_MASKWISE(a.v[i] && b.v[i]); }
GUARDIAN_ALWAYS_INLINE LaneMask orMask(LaneMask a, LaneMask b) { GUARDIAN_MASKWISE(a.v[i] || b.v[i]); }
#undef GUARDIAN_MASKWISE
GUARDIAN_ALWAYS_INLINE Lanes select(LaneMask where, Lanes yes, Lanes no) {
    Lanes r;
    for (int i = 0; i < kLanes; ++i) r.v[i] = where.v[i] ? yes.v[i] : no.v[i];
    return r;
}

#endif

// The Lanes whose lane l is f(l), made in registers. Written a lane at a time into a Lanes' floats and then
// read as one register, the read waits for the writes to reach the cache (narrow stores cannot be forwarded
// to a wider load): preparing the rows waited so on every vector it gathered (perf, two boxes resting on the
// ground: half of preparing's samples, the step 1 % faster without; a heavy box on a light one: 5.4 -> 4.6 %
// of the step).
template <class F> GUARDIAN_ALWAYS_INLINE Lanes lanesOf(F f) {
#if GUARDIAN_AVX_LANES
    return Lanes(_mm256_setr_ps(f(0), f(1), f(2), f(3), f(4), f(5), f(6), f(7)));
#elif GUARDIAN_SSE_LANES
    return Lanes(_mm_setr_ps(f(0), f(1), f(2), f(3)));
#else
    Lanes r;
    for (int i = 0; i < kLanes; ++i) r.v[i] = f(i);
    return r;
#endif
}

// std::clamp(x, lo, hi) lane by lane (x < lo ? lo : hi < x ? hi : x).
GUARDIAN_ALWAYS_INLINE Lanes clampOf(Lanes x, Lanes lo, Lanes hi) {
    return select(less(x, lo), lo, select(less(hi, x), hi, x));
}

// Three Lanes: one vector per lane.
struct Lanes3 {
    Lanes x, y, z;
};
GUARDIAN_ALWAYS_INLINE Lanes3 operator+(const Lanes3& a, const Lanes3& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
GUARDIAN_ALWAYS_INLINE Lanes3 operator-(const Lanes3& a, const Lanes3& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
GUARDIAN_ALWAYS_INLINE Lanes3 operator*(Lanes s, const Lanes3& a) { return {s * a.x, s * a.y, s * a.z}; }
// The dot product in the order Eigen's Vec3 dot adds: x + (y + z).
GUARDIAN_ALWAYS_INLINE Lanes dot(const Lanes3& a, const Lanes3& b) {
    return a.x * b.x + (a.y * b.y + a.z * b.z);
}

// Lane `lane` of l set to v.
GUARDIAN_ALWAYS_INLINE void setLanes3(Lanes3& l, int lane, const Vec3& v) {
    l.x.setLane(lane, v.x());
    l.y.setLane(lane, v.y());
    l.z.setLane(lane, v.z());
}

// The cross product in Eigen's order.
GUARDIAN_ALWAYS_INLINE Lanes3 crossLanes(const Lanes3& a, const Lanes3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// q v q^-1 as Eigen's Quaternion::_transformVector computes it.
GUARDIAN_ALWAYS_INLINE Lanes3 rotateLanes(const Lanes3& qv, const Lanes& qw, const Lanes3& v) {
    Lanes3 uv = crossLanes(qv, v);
    uv = uv + uv;
    return (v + qw * uv) + crossLanes(qv, uv);
}

// kLanes 4-Real rows (x, y, z, 0), one per lane, as three Lanes of x, y and z; and back.
#if GUARDIAN_SSE_LANES
namespace lanes_detail {
// Four rows as the x, y and z of four lanes (SSE: one 4x4 transpose).
GUARDIAN_ALWAYS_INLINE void gather4(const float* const* r, __m128& x, __m128& y, __m128& z) {
    __m128 a = _mm_load_ps(r[0]), b = _mm_load_ps(r[1]), c = _mm_load_ps(r[2]), d = _mm_load_ps(r[3]);
    _MM_TRANSPOSE4_PS(a, b, c, d);
    x = a;
    y = b;
    z = c;
}
GUARDIAN_ALWAYS_INLINE void scatter4(__m128 a, __m128 b, __m128 c, float* const* r) {
    __m128 d = _mm_setzero_ps();
    _MM_TRANSPOSE4_PS(a, b, c, d);
    _mm_store_ps(r[0], a);
    _mm_store_ps(r[1], b);
    _mm_store_ps(r[2], c);
    _mm_store_ps(r[3], d);
}
} // namespace lanes_detail
GUARDIAN_ALWAYS_INLINE Lanes3 gatherRows(const float* const* rows) {
    __m128 x, y, z;
    lanes_detail::gather4(rows, x, y, z);
#if GUARDIAN_AVX_LANES
    __m128 x1, y1, z1;
    lanes_detail::gather4(rows + 4, x1, y1, z1);
    return Lanes3{Lanes(_mm256_insertf128_ps(_mm256_castps128_ps256(x), x1, 1)),
                  Lanes(_mm256_insertf128_ps(_mm256_castps128_ps256(y), y1, 1)),
                  Lanes(_mm256_insertf128_ps(_mm256_castps128_ps256(z), z1, 1))};
#else
    return Lanes3{Lanes(x), Lanes(y), Lanes(z)};
#endif
}
GUARDIAN_ALWAYS_INLINE void scatterRows(const Lanes3& l, float* const* rows) {
#if GUARDIAN_AVX_LANES
    const __m256 x = l.x.v(), y = l.y.v(), z = l.z.v();
    lanes_detail::scatter4(_mm256_castps256_ps128(x), _mm256_castps256_ps128(y), _mm256_castps256_ps128(z),
                           rows);
    lanes_detail::scatter4(_mm256_extractf128_ps(x, 1), _mm256_extractf128_ps(y, 1),
                           _mm256_extractf128_ps(z, 1), rows + 4);
#else
    lanes_detail::scatter4(l.x.v(), l.y.v(), l.z.v(), rows);
#endif
}
#elif GUARDIAN_DOUBLE_LANES
// Two rows' (x, y) and (z, 0) halves as two lanes of x, y and z (SSE2: 2x2 transposes); and back.
GUARDIAN_ALWAYS_INLINE Lanes3 gatherRows(const double* const* rows) {
    __m128d x[2], y[2], z[2];
    for (int k = 0; k < 2; ++k) {
        const double *a = rows[2 * k], *b = rows[2 * k + 1];
        const __m128d axy = _mm_load_pd(a), bxy = _mm_load_pd(b);
        x[k] = _mm_unpacklo_pd(axy, bxy);
        y[k] = _mm_unpackhi_pd(axy, bxy);
        z[k] = _mm_unpacklo_pd(_mm_load_pd(a + 2), _mm_load_pd(b + 2));
    }
    return Lanes3{Lanes(x[0], x[1]), Lanes(y[0], y[1]), Lanes(z[0], z[1])};
}
GUARDIAN_ALWAYS_INLINE void scatterRows(const Lanes3& l, double* const* rows) {
    const __m128d x[2] = {l.x.lo(), l.x.hi()}, y[2] = {l.y.lo(), l.y.hi()}, z[2] = {l.z.lo(), l.z.hi()};
    const __m128d zero = _mm_setzero_pd();
    for (int k = 0; k < 2; ++k) {
        double *a = rows[2 * k], *b = rows[2 * k + 1];
        _mm_store_pd(a, _mm_unpacklo_pd(x[k], y[k]));
        _mm_store_pd(b, _mm_unpackhi_pd(x[k], y[k]));
        _mm_store_pd(a + 2, _mm_unpacklo_pd(z[k], zero));
        _mm_store_pd(b + 2, _mm_unpackhi_pd(z[k], zero));
    }
}
#else
GUARDIAN_ALWAYS_INLINE Lanes3 gatherRows(const Real* const* rows) {
    Lanes3 l;
    for (int i = 0; i < kLanes; ++i) {
        l.x.v[i] = rows[i][0];
        l.y.v[i] = rows[i][1];
        l.z.v[i] = rows[i][2];
    }
    return l;
}
GUARDIAN_ALWAYS_INLINE void scatterRows(const Lanes3& l, Real* const* rows) {
    for (int i = 0; i < kLanes; ++i) {
        rows[i][0] = l.x.v[i];
        rows[i][1] = l.y.v[i];
        rows[i][2] = l.z.v[i];
        rows[i][3] = 0;
    }
}
#endif

} // namespace physics
