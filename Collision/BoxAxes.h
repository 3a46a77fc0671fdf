// BoxAxes.h - a box's three unit axes at a rotation (its rows, each normalised as Vector::normalize does):
// what every box shape is built from, once per box and call in a space's gathering of moved boxes. On SSE2
// the three lengths, square roots and divisions go side by side; each lane does the scalar operations in
// their order (x x + y y + z z, one square root, one division a component), so the bits are the same.
#pragma once

#include "MathDeclarations.h"

#if defined(__SSE2__)
#include <xmmintrin.h>
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
    alignas(16) float rows[3][4];
    _mm_store_ps(rows[0], x);
    _mm_store_ps(rows[1], y);
    _mm_store_ps(rows[2], z);
    for (int i = 0; i < 3; ++i) axis[i] = Vector(rows[i][0], rows[i][1], rows[i][2]);
#else
    axis[0] = r.direction('x').normalize();
    axis[1] = r.direction('y').normalize();
    axis[2] = r.direction('z').normalize();
#endif
}

} // namespace gcol
