// MathTest.cpp - the Vector/Matrix shim against independent formulas (triple loops, trig, identities).
#include "MathDefinitions.h"
#include "MathExpect.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using foundation_test::expectNear;
using foundation_test::kPi;

namespace {

std::mt19937 rng(12345);
float uniform(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }
Vector randomVector(float r = 10.0f) { return Vector(uniform(-r, r), uniform(-r, r), uniform(-r, r)); }
Matrix randomMatrix() {
    Matrix m;
    for (int i = 0; i < 16; ++i) m.data()[i] = uniform(-3, 3);
    return m;
}

} // namespace

TEST(Vector, ArithmeticDotCrossLength) {
    Vector a(1, 2, 3), b(-4, 5, 0.5f);
    expectNear(a + b, Vector(-3, 7, 3.5f), 0);
    expectNear(a - b, Vector(5, -3, 2.5f), 0);
    EXPECT_FLOAT_EQ(dot(a, b), -4 + 10 + 1.5f);
    expectNear(cross(Vector(1, 0, 0), Vector(0, 1, 0)), Vector(0, 0, 1), 0); // x cross y = z
    expectNear(cross(a, b), Vector(2 * 0.5f - 3 * 5, 3 * -4 - 1 * 0.5f, 1 * 5 - 2 * -4), 1e-6f);
    EXPECT_FLOAT_EQ(length(Vector(3, 4, 12)), 13.0f);
    expectNear(normal(Vector(0, 0, -7)), Vector(0, 0, -1), 0);
    expectNear(Vector().normalize(), Vector(), 0); // zero stays zero, no NaN
    expectNear(a / 0.0f, a, 0);                    // framework rule: dividing by zero leaves v unchanged
    expectNear(projectOnTo(Vector(3, 4, 0), Vector(2, 0, 0)), Vector(3, 0, 0), 1e-6f);
}

TEST(Vector, TimesEqualsMinusOneNegates) {
    // Ported Team Guardian code writes `contact->normal *= -1`; it must keep meaning negation.
    Vector n(0.25f, -2, 7);
    n *= -1;
    expectNear(n, Vector(-0.25f, 2, -7), 0);
}

TEST(Matrix, ProductMatchesTripleLoopOnRandomInputs) {
    for (int trial = 0; trial < 200; ++trial) {
        Matrix a = randomMatrix(), b = randomMatrix(), loop;
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) {
                double s = 0;
                for (int k = 0; k < 4; ++k) s += double(a(r, k)) * b(k, c);
                loop(r, c) = float(s);
            }
        expectNear(a * b, loop, 1e-4f);
    }
}

TEST(Matrix, InverseTimesMatrixIsIdentity) {
    for (int trial = 0; trial < 200; ++trial) {
        Matrix m = rotate(randomVector(), uniform(-kPi, kPi)) * translation(uniform(-5, 5), 1, 2);
        m.m11 *= 2.0f; // not orthonormal: a general inverse is needed
        expectNear(m * m.inverse(), Matrix(1), 1e-4f);
    }
    Matrix singular; // all zeros: refused, returned unchanged
    expectNear(singular.inverse(), singular, 0);
}

TEST(Matrix, TransposeSwapsRowsAndColumns) {
    Matrix m = randomMatrix(), t = m.transpose();
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_EQ(t(r, c), m(c, r));
}

TEST(Matrix, RotatexHasTheDirect3DLayout) {
    float a = 0.7f, c = std::cos(a), s = std::sin(a);
    expectNear(rotatex(a), Matrix(1, 0, 0, 0, 0, c, s, 0, 0, -s, c, 0, 0, 0, 0, 1), 1e-6f);
    expectNear(rotatey(a), Matrix(c, 0, -s, 0, 0, 1, 0, 0, s, 0, c, 0, 0, 0, 0, 1), 1e-6f);
    expectNear(rotatez(a), Matrix(c, s, 0, 0, -s, c, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1), 1e-6f);
}

TEST(Matrix, AxisRotationIsRodriguesForRowVectors) {
    for (int trial = 0; trial < 500; ++trial) {
        Vector k = randomVector().normalize(), p = randomVector();
        float a = uniform(-kPi, kPi);
        Vector rodrigues = p * std::cos(a) + cross(k, p) * std::sin(a) + k * (dot(k, p) * (1 - std::cos(a)));
        expectNear(p * rotate(k, a), rodrigues, 1e-4f);
    }
}

TEST(Matrix, RotationsAreOrthonormalAndCompose) {
    for (int trial = 0; trial < 200; ++trial) {
        Vector k = randomVector();
        float a = uniform(-kPi, kPi), b = uniform(-kPi, kPi);
        Matrix r = rotate(k, a);
        expectNear(r * r.transpose(), Matrix(1), 1e-5f);
        EXPECT_TRUE(isRotation(r));
        expectNear(rotate(k, a) * rotate(k, b), rotate(k, a + b), 1e-4f); // same axis: angles add
        // Row vectors compose left to right: p * (A * B) == (p * A) * B.
        Matrix other = rotate(randomVector(), b);
        Vector p = randomVector();
        expectNear(p * (r * other), (p * r) * other, 1e-3f);
    }
}

TEST(Matrix, PointTransformAppliesTranslationDirectionDoesNot) {
    Matrix m = rotatey(kPi / 2) * translation(10, 0, 0);
    expectNear(Vector(1, 0, 0) * m, Vector(10, 0, -1), 1e-6f); // x turns to -z about y, then moves
    expectNear(m.direction(Vector(1, 0, 0)), Vector(0, 0, -1), 1e-6f);
    expectNear(m.position(), Vector(10, 0, 0), 0);
}

TEST(Matrix, FrameworkRotateKeepsTranslation) {
    Matrix t = translation(1, 2, 3);
    t.rotatez(0.5f);
    expectNear(t.position(), Vector(1, 2, 3), 0);
    expectNear(t.rotation(), rotatez(0.5f), 1e-6f);
    t.translate(1, 0, 0); // parent-space axes
    expectNear(t.position(), Vector(2, 2, 3), 1e-6f);
}

TEST(Matrix, OrthoNormalizeRemovesScaleAndShear) {
    for (int trial = 0; trial < 100; ++trial) {
        Matrix r = rotate(randomVector(), uniform(-kPi, kPi));
        Matrix scaled = Matrix(Vector(1.5f, 0.5f, 2.0f)) * r;
        scaled.m41 = 4;
        EXPECT_FALSE(isRotation(scaled));
        Matrix clean = orthoNormalize(scaled);
        EXPECT_TRUE(isRotation(clean));
        EXPECT_EQ(clean.m41, 4.0f);
        // A slightly perturbed rotation comes back to (almost) itself.
        Matrix noisy = r;
        noisy.m12 += 1e-3f;
        expectNear(orthoNormalize(noisy).rotation(), r, 2e-3f);
    }
    Matrix mirror(Vector(1, 1, -1));
    EXPECT_TRUE(isRotation(orthoNormalize(mirror))); // a reflection becomes a proper rotation
}

TEST(Matrix, ImplicitScalarConstructorIsDiagonal) {
    Matrix m = 2.0f;
    expectNear(m, Matrix(2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1), 0);
    Matrix zero;
    EXPECT_EQ(zero.m44, 0.0f);
}
