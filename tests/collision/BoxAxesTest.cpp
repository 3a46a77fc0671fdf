// BoxAxesTest.cpp - gcol::unitAxes against its definition, Vector::normalize of each row, bit for bit: on
// 10^5 random matrices (rotations with drift, arbitrary scales, rows of zeros, denormals, huge values, NaN
// and infinity), fixed seed.
#include "BoxAxes.h"
#include "MathDefinitions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

namespace {

bool sameBits(const Vector& a, const Vector& b) { return std::memcmp(&a, &b, sizeof(Vector)) == 0; }

TEST(BoxAxes, EveryRowIsNormalisedExactlyAsVectorNormalizeDoes) {
    std::mt19937 gen(20261127);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::uniform_int_distribution<int> kind(0, 9), exponent(-140, 120);
    const float specials[] = {0.0f,
                              -0.0f,
                              std::numeric_limits<float>::denorm_min(),
                              1e-30f,
                              3e38f,
                              std::numeric_limits<float>::infinity(),
                              -std::numeric_limits<float>::infinity(),
                              std::numeric_limits<float>::quiet_NaN()};
    for (int n = 0; n < 100000; ++n) {
        Matrix m(1);
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) {
                const int k = kind(gen);
                float x = unit(gen);
                if (k == 0)
                    x = specials[size_t(gen() % 8)];
                else if (k == 1)
                    x = std::ldexp(x, exponent(gen));
                else if (k == 2)
                    x = 0.0f;
                m(r, c) = x;
            }
        if (n % 3 == 0) { // a rotation with a little drift, as bodies' orientations have
            const Matrix r = rotate(Vector(unit(gen), unit(gen), unit(gen)), 10.0f * unit(gen));
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) m(i, j) = r(i, j) * (1.0f + 1e-3f * unit(gen));
        }
        Vector axes[3];
        gcol::unitAxes(m, axes);
        const Vector expected[3] = {m.direction('x').normalize(), m.direction('y').normalize(),
                                    m.direction('z').normalize()};
        for (int i = 0; i < 3; ++i) {
            ASSERT_TRUE(sameBits(axes[i], expected[i]))
                << "matrix " << n << " row " << i << ": " << axes[i].x << " " << axes[i].y << " " << axes[i].z
                << " against " << expected[i].x << " " << expected[i].y << " " << expected[i].z;
            // What a box needs of them: a drifted rotation's rows come out unit (in double, to float
            // rounding).
            if (n % 3 == 0) {
                const double x = axes[i].x, y = axes[i].y, z = axes[i].z;
                ASSERT_NEAR(std::sqrt(x * x + y * y + z * z), 1.0, 1e-6) << "matrix " << n << " row " << i;
            }
        }
    }
}

} // namespace
