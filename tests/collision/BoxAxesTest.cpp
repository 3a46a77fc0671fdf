// BoxAxesTest.cpp - gcol::unitAxes against its definition, Vector::normalize of each row, bit for bit: on
// 10^5 random matrices (rotations with drift, arbitrary scales, rows of zeros, denormals, huge values, NaN
// and infinity), fixed seed. gcol::boxBounds against the general gcol::shapeAabb, bit for bit, and against
// the box's eight corners computed in double, on 10^5 random boxes.
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

TEST(BoxAxes, BoxBoundsAreTheGeneralBoundsAndHoldEveryCorner) {
    std::mt19937 gen(20261127);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::uniform_int_distribution<int> exponent(-20, 20);
    for (int n = 0; n < 100000; ++n) {
        gcol::WorldShape s;
        s.kind = gcol::ShapeKind::Box;
        gcol::BoxShape& b = s.box;
        const float scale = std::ldexp(1.0f, exponent(gen));
        b.centre = Vector(unit(gen), unit(gen), unit(gen)) * scale;
        b.halfExtents = Vector(std::fabs(unit(gen)), std::fabs(unit(gen)), std::fabs(unit(gen))) * scale;
        const Matrix r = rotate(Vector(unit(gen), unit(gen), unit(gen)), 10.0f * unit(gen));
        gcol::unitAxes(r, b.axis);
        if (n % 7 == 0) b.axis[n % 3] = -b.axis[n % 3]; // signed zeros and negative components too
        gcol::Aabb fast, general;
        gcol::boxBounds(b, fast);
        ASSERT_TRUE(gcol::shapeAabb(s, general));
        ASSERT_TRUE(sameBits(fast.min, general.min) && sameBits(fast.max, general.max)) << "box " << n;
        // Every corner inside, to float rounding of the sums (a few ulps of the largest term).
        const double slack = 1e-6 * (std::fabs(b.centre.x) + std::fabs(b.centre.y) + std::fabs(b.centre.z) +
                                     b.halfExtents.x + b.halfExtents.y + b.halfExtents.z);
        double reach[3] = {0, 0, 0}; // how far the farthest corner is from the centre along x, y, z
        for (int corner = 0; corner < 8; ++corner) {
            const double sx = corner & 1 ? 1 : -1, sy = corner & 2 ? 1 : -1, sz = corner & 4 ? 1 : -1;
            const double p[3] = {b.centre.x + sx * b.halfExtents.x * b.axis[0].x +
                                     sy * b.halfExtents.y * b.axis[1].x + sz * b.halfExtents.z * b.axis[2].x,
                                 b.centre.y + sx * b.halfExtents.x * b.axis[0].y +
                                     sy * b.halfExtents.y * b.axis[1].y + sz * b.halfExtents.z * b.axis[2].y,
                                 b.centre.z + sx * b.halfExtents.x * b.axis[0].z +
                                     sy * b.halfExtents.y * b.axis[1].z + sz * b.halfExtents.z * b.axis[2].z};
            const double lo[3] = {fast.min.x, fast.min.y, fast.min.z},
                         hi[3] = {fast.max.x, fast.max.y, fast.max.z};
            const double c[3] = {b.centre.x, b.centre.y, b.centre.z};
            for (int k = 0; k < 3; ++k) {
                ASSERT_GE(p[k], lo[k] - slack) << "box " << n << " corner " << corner;
                ASSERT_LE(p[k], hi[k] + slack) << "box " << n << " corner " << corner;
                reach[k] = std::fmax(reach[k], std::fabs(p[k] - c[k]));
            }
        }
        // And tight: the farthest corner reaches each face of the bounds.
        ASSERT_NEAR(reach[0], 0.5 * (double(fast.max.x) - fast.min.x), slack) << "box " << n;
        ASSERT_NEAR(reach[1], 0.5 * (double(fast.max.y) - fast.min.y), slack) << "box " << n;
        ASSERT_NEAR(reach[2], 0.5 * (double(fast.max.z) - fast.min.z), slack) << "box " << n;
    }
}

} // namespace
