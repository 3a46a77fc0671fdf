// MathExpect.h - what the foundation tests share: pi as a float and element-wise near-equality of the
// course math types.
#pragma once

#include "MathDefinitions.h"

#include <gtest/gtest.h>

namespace foundation_test {

constexpr float kPi = 3.14159265358979f;

inline void expectNear(const Vector& a, const Vector& b, float tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

inline void expectNear(const Matrix& a, const Matrix& b, float tol) {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(a(r, c), b(r, c), tol) << "element " << r << "," << c;
}

} // namespace foundation_test
