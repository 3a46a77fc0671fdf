// VectorRegister.h - a Vector into and out of an SSE register (x, y, z, 0) in the two pieces its copies are
// stored in (the first eight bytes, then the last four). A load right after a store is forwarded from the
// store only when it lies within one store; a sixteen-byte load of a Vector just written in pieces waits for
// them to reach the cache (a third of gathering a moved box went in such waits, perf). Code that writes a
// Vector and soon reads it back into a register goes through these on both sides.
#pragma once

#include "MathDeclarations.h"

#if defined(__SSE2__)
#include <emmintrin.h>

namespace gcol {

inline __m128 load3(const Vector& v) {
    const __m128 xy = _mm_loadl_pi(_mm_setzero_ps(), reinterpret_cast<const __m64*>(&v.x));
    return _mm_movelh_ps(xy, _mm_load_ss(&v.z));
}

inline void store3(Vector& v, __m128 xyz) {
    _mm_storel_pi(reinterpret_cast<__m64*>(&v.x), xyz);
    _mm_store_ss(&v.z, _mm_movehl_ps(xyz, xyz));
}

// Bit for bit.
inline bool sameBits3(__m128 a, __m128 b) {
    return _mm_movemask_epi8(_mm_cmpeq_epi32(_mm_castps_si128(a), _mm_castps_si128(b))) == 0xFFFF;
}

} // namespace gcol

#endif
