// CourseMathApiTest.cpp - course-framework code that uses the whole of the framework's math header API
// (fwk4gps 2012 MathDeclarations.h / MathDefinitions.h) compiles against ours, and each piece means what
// the framework's does. A package's MathDeclarations.h overwrites a course project's: dropping any of this
// would break the game's own drawing code. Values are checked against hand-computed results.
#include "MathDeclarations.h"
#include "MathDefinitions.h"
#include "MathExpect.h"

#include <gtest/gtest.h>

#include <cmath>

using foundation_test::expectNear;
using foundation_test::kPi;

namespace {

// Code shaped like a course design's drawing setup: colours, materials, a plane, a camera.
struct DrawSetup {
    Colour red = Colour(1, 0, 0);
    Reflectivity redish = Reflectivity(red);
    Reflectivity shiny = Reflectivity(Colour(0, 0, 1, 0.5f), 40);
    Plane floor = Plane(Vector(0, 1, 0), -2); // y = 2 in the framework's n . p + d = 0 form
    Matrix camera = view(Vector(0, 0, -10), Vector(0, 0, 0), Vector(0, 1, 0));
    Matrix lens = projection(kPi / 3, 4.0f / 3.0f, 1.0f, 1000.0f);
};

TEST(CourseMathApi, ColourAndReflectivityMeanWhatTheFrameworkSays) {
    DrawSetup d;
    EXPECT_EQ(d.red.a, 1.0f);  // alpha 1 by default
    const float* rgba = d.red; // operator const float*
    EXPECT_EQ(rgba[0], 1.0f);
    EXPECT_EQ(rgba[3], 1.0f);
    EXPECT_EQ(COLOUR_TO_ARGB(d.red), 0xFFFF0000u);
    EXPECT_FLOAT_EQ(d.redish.ambient.r, 0.7f); // ambient is 70 % of the colour
    EXPECT_EQ(d.redish.diffuse.r, 1.0f);
    EXPECT_EQ(d.redish.specular.g, 1.0f); // white specular
    EXPECT_EQ(d.redish.power, float(DEFAULT_SHININESS));
    EXPECT_FALSE(d.redish.translucent());
    EXPECT_EQ(d.shiny.power, 40.0f);
    EXPECT_TRUE(d.shiny.translucent());
}

TEST(CourseMathApi, PlaneKeepsTheFrameworksMembersAndTest) {
    DrawSetup d;
    EXPECT_EQ(d.floor.normal(), Vector(0, 1, 0));
    EXPECT_EQ(d.floor.constant(), -2.0f);
    EXPECT_EQ(d.floor.n, Vector(0, 1, 0));
    EXPECT_EQ(d.floor.d, -2.0f);
    // The framework's test: n . v + d < 0.
    EXPECT_TRUE(d.floor.onPositiveSide(Vector(0, 1, 0)));
    EXPECT_FALSE(d.floor.onPositiveSide(Vector(0, 3, 0)));
}

TEST(CourseMathApi, MacrosComputeWhatTheirNamesSay) {
    EXPECT_EQ(SQR(3), 9);
    EXPECT_NEAR(DEGTORAD(180.0f), kPi, 1e-6);
    EXPECT_NEAR(RADTODEG(kPi / 2), 90.0f, 1e-4);
    float v = 5.0f;
    LIMIT_RANGE(0.0f, v, 1.0f);
    EXPECT_EQ(v, 1.0f);
    v = -3.0f;
    LIMIT_RANGE(0.0f, v, 1.0f);
    EXPECT_EQ(v, 0.0f);
}

TEST(CourseMathApi, VectorAndMatrixMembersOfTheFramework) {
    Vector a(1, 2, 3);
    Vector b = +a;
    b += Vector(1, 1, 1);
    b -= Vector(0, 1, 0);
    EXPECT_EQ(b, Vector(2, 2, 4));
    EXPECT_EQ(-a, Vector(-1, -2, -3));
    EXPECT_FLOAT_EQ(Vector(3, 4, 0).length(), 5.0f);
    EXPECT_EQ(a / 0.0f, a); // dividing by zero leaves the vector unchanged
    EXPECT_EQ(cross(Vector(1, 0, 0), Vector(0, 1, 0)), Vector(0, 0, 1));
    EXPECT_EQ(dot(a, a), 14.0f);
    EXPECT_FLOAT_EQ(normal(Vector(0, 0, 2)).z, 1.0f);
    // Ported Team Guardian code negates a normal with `n *= -1`: it must still mean negation.
    Vector n(0, 1, 0);
    n *= -1;
    EXPECT_EQ(n, Vector(0, -1, 0));

    Matrix m(2.0f);             // implicit diag(2, 2, 2, 1)
    Matrix s = Vector(1, 2, 3); // implicit diag(v, 1), as in the framework
    EXPECT_EQ(s.m22, 2.0f);
    EXPECT_EQ(m.m44, 1.0f);
    Matrix i;
    i.isIdentity();
    EXPECT_EQ(i, Matrix(1));
    Matrix t = translation(1, 2, 3);
    EXPECT_EQ(t.transpose().m14, 1.0f);
    Matrix sum = m;
    sum += Matrix(1);
    sum -= Matrix(1);
    EXPECT_EQ(sum, m);
    sum *= Matrix(1);
    EXPECT_EQ(sum, m);

    // Row vectors: p * M, translation in m41..m43; rotations about parent axes through the own origin.
    Matrix frame(1);
    frame.translate(5, 0, 0);
    frame.rotatez(kPi / 2);
    Vector p = Vector(1, 0, 0) * frame;
    EXPECT_NEAR(p.x, 5.0f, 1e-6);
    EXPECT_NEAR(p.y, 1.0f, 1e-6);
    EXPECT_EQ(frame.position(), Vector(5, 0, 0));
    EXPECT_EQ(position(frame), Vector(5, 0, 0));
    EXPECT_NEAR(frame.direction('x').y, 1.0f, 1e-6);
    EXPECT_NEAR(frame.direction(Vector(0, 1, 0)).x, -1.0f, 1e-6);
    EXPECT_EQ(rotation(frame).m41, 0.0f);
    frame.rotatex(0.3f);
    frame.rotatey(0.2f);
    frame.rotate(Vector(1, 1, 0), 0.1f);
    frame.rotate(rotatex(0.1f));
    frame.orient(Matrix(1));
    EXPECT_EQ(frame.rotation(), Matrix(1));
    frame.scale(2, 2, 2);
    EXPECT_EQ(frame.m11, 2.0f);
    Vector q = Vector(1, 0, 0);
    q *= translation(0, 1, 0);
    EXPECT_EQ(q, Vector(1, 1, 0));
    // rotate(axis, rad) about z by 90 degrees takes x to y.
    Vector r = Vector(1, 0, 0) * rotate(Vector(0, 0, 1), kPi / 2);
    EXPECT_NEAR(r.y, 1.0f, 1e-6);
    // Matrix * Vector is the framework's column form with the fourth column as translation.
    Matrix c(1);
    c.m14 = 7;
    EXPECT_EQ(c * Vector(1, 0, 0), Vector(8, 0, 0));
}

TEST(CourseMathApi, CameraHelpersOfTheFramework) {
    DrawSetup d;
    // The view matrix takes the eye to the origin and the target onto +z (left-handed, looking along +z).
    Vector eye = Vector(0, 0, -10) * d.camera;
    Vector target = Vector(0, 0, 0) * d.camera;
    EXPECT_NEAR(eye.z, 0.0f, 1e-5);
    EXPECT_NEAR(target.z, 10.0f, 1e-5);
    // Perspective: a point on the near plane maps to depth 0, on the far plane to depth w (= z).
    EXPECT_NEAR(d.lens.m33 * 1.0f + d.lens.m43, 0.0f, 1e-5);
    EXPECT_NEAR((d.lens.m33 * 1000.0f + d.lens.m43) / 1000.0f, 1.0f, 1e-5);
    EXPECT_NEAR(d.lens.m22, 1.0f / std::tan(kPi / 6), 1e-5);
    Matrix offCentre = projection(-1, 1, -1, 1, 1, 100);
    EXPECT_NEAR(offCentre.m11, 1.0f, 1e-6);
    Matrix rhs = projToRhs(d.lens);
    EXPECT_EQ(rhs.m33, d.lens.m33);
    Matrix ortho = orthographic(800, 600);
    EXPECT_NEAR((Vector(800, 600, 0) * ortho).x, 1.0f, 1e-6);
    Matrix sc;
    scale(sc, 1, 2, 3);
    EXPECT_EQ(sc.m33, 3.0f);
    scale(sc, Vector(4, 5, 6));
    EXPECT_EQ(sc.m11, 4.0f);
}

} // namespace
