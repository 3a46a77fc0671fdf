// BoxAxes.h - a box's three unit axes at a rotation (its rows, each normalised as Vector::normalize does),
// a box shape's world bounds, and a sphere or box that sits at its body's origin placed at a pose: what every
// moved box costs a space's gathering, once per box and call. On
// SSE2 the three components go side by side; each lane does the scalar operations in their order (x x + y y
// + z z, one square root, one division a component; h.x |a0| + h.y |a1| + h.z |a2|), so the bits are the
// same as the scalar code's.
#pragma once

#include "MathDeclarations.h"
#include "Shapes.h"
#include "VectorRegister.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace gcol {

inline void unitAxes(const Matrix& r, Vector axis[3]) {
#if defined(__SSE2__)
    const float* m = r.data(); // row i at m + 4 i
    __m128 x = _mm_loadu_ps(m), y = _mm_loadu_ps(m + 4), z = _mm_loadu_ps(m + 8), w = _mm_setzero_ps();
    _MM_TRANSPOSE4_PS(x, y, z, w); // x: the three rows' x (and 0 in lane 3), y and z alike
    const __m128 length =
        _mm_sqrt_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(x, x), _mm_mul_ps(y, y)), _mm_mul_ps(z, z)));
    const __m128 positive = _mm_cmpgt_ps(length, _mm_setzero_ps()); // else the zero vector (NaN too)
    x = _mm_and_ps(positive, _mm_div_ps(x, length));
    y = _mm_and_ps(positive, _mm_div_ps(y, length));
    z = _mm_and_ps(positive, _mm_div_ps(z, length));
    w = _mm_setzero_ps();
    _MM_TRANSPOSE4_PS(x, y, z, w); // back to one row an axis
    store3(axis[0], x);
    store3(axis[1], y);
    store3(axis[2], z);
#else
    axis[0] = r.direction('x').normalize();
    axis[1] = r.direction('y').normalize();
    axis[2] = r.direction('z').normalize();
#endif
}

// gcol::shapeAabb of a box, written out: boxProjectedRadius along a world axis is h.x |axis[0] . e| +
// h.y |axis[1] . e| + h.z |axis[2] . e|, and for finite axes |axis . e_x| is exactly |axis.x| (the other
// products are zeros, which leave a sum as it is but for the sign of a zero, and fabs drops that). The
// same bits, without the multiplications by 0 and 1.
inline void boxBounds(const BoxShape& b, Aabb& out) {
    const Vector& h = b.halfExtents;
#if defined(__SSE2__)
    // (The shape was most likely written just now: read as it was written, VectorRegister.h.)
    const __m128 magnitude = _mm_castsi128_ps(_mm_set1_epi32(0x7FFFFFFF));
    const __m128 a0 = _mm_and_ps(magnitude, load3(b.axis[0]));
    const __m128 a1 = _mm_and_ps(magnitude, load3(b.axis[1]));
    const __m128 a2 = _mm_and_ps(magnitude, load3(b.axis[2]));
    const __m128 e =
        _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_set1_ps(h.x), a0), _mm_mul_ps(_mm_set1_ps(h.y), a1)),
                   _mm_mul_ps(_mm_set1_ps(h.z), a2));
    const __m128 c = load3(b.centre);
    store3(out.min, _mm_sub_ps(c, e));
    store3(out.max, _mm_add_ps(c, e));
#else
    const Vector &a0 = b.axis[0], &a1 = b.axis[1], &a2 = b.axis[2];
    const Vector e(h.x * std::fabs(a0.x) + h.y * std::fabs(a1.x) + h.z * std::fabs(a2.x),
                   h.x * std::fabs(a0.y) + h.y * std::fabs(a1.y) + h.z * std::fabs(a2.y),
                   h.x * std::fabs(a0.z) + h.y * std::fabs(a1.z) + h.z * std::fabs(a2.z));
    out.min = b.centre - e;
    out.max = b.centre + e;
#endif
}

// A sphere or box at its body's origin with the body's axes (CSphere, COBB: CollisionGeometry::
// centredOnBody) placed at the body pose (origin, row-vector rotation r); its kind and size are left as
// they are. Their writeWorldShapes is this, so a space may move a shape it holds without the geometry.
inline void placeAtBody(WorldShape& s, const Vector& origin, const Matrix& r) {
    if (s.kind == ShapeKind::Sphere) {
        s.sphere.centre = origin;
    } else if (s.kind == ShapeKind::Box) {
        s.box.centre = origin;
        unitAxes(r, s.box.axis);
    }
}

} // namespace gcol
