// ShapeCastTest.cpp - the simple space's shape cast (iShapeCast.h) against independent answers: the analytic
// time of impact of a sphere, a brute-force scan of a tumbling box's path with the overlap query, and the
// cases it must leave alone (slow bodies, pairs touching at the start).
#include "DefaultSpace.h"
#include "UserBody.h"
#include "iCOBB.h"
#include "iCPlane.h"
#include "iCSphere.h"
#include "iCollisionQueries.h"
#include "iShapeCast.h"
#include "iSimpleCollisionSpace.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

// A rotation of angle a about a unit axis, as a row-vector Matrix (local -> world).
Matrix rotation(const Vector& axis, float a) {
    Vector u = axis.normalize();
    float c = std::cos(a), s = std::sin(a), k = 1 - c;
    Matrix m(1);
    // Column-vector R, stored transposed (row-vector convention).
    float r[3][3] = {{c + u.x * u.x * k, u.x * u.y * k - u.z * s, u.x * u.z * k + u.y * s},
                     {u.y * u.x * k + u.z * s, c + u.y * u.y * k, u.y * u.z * k - u.x * s},
                     {u.z * u.x * k - u.y * s, u.z * u.y * k + u.x * s, c + u.z * u.z * k}};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m.data()[j * 4 + i] = r[i][j];
    return m;
}

struct Fixture {
    iCollisionSpace* space = CreateSimpleCollisionSpace();
    DefaultSpace joins{space};
    std::vector<iCollisionGeometry*> shapes;
    ~Fixture() {
        for (iCollisionGeometry* g : shapes) g->Delete();
        space->Delete();
    }
    BodySweep sweep(UserBody& b, const Vector& from, const Matrix& fromRotation = Matrix(1)) {
        BodySweep s;
        s.body = &b;
        s.startPosition = from;
        s.startOrientation = fromRotation;
        castOf(space)->sweepBodies(&s, 1);
        return s;
    }
};

} // namespace

TEST(ShapeCast, SphereStopsAtItsAnalyticTimeOfImpactPlusTheSkin) {
    // A 0.05 m sphere along x at y = 0.1 through a fixed 1 m box: it touches when its centre is at
    // x = -0.55, a fraction (10 - 0.55) / 20 of the way; it is left 0.2 mm further in.
    Fixture f;
    UserBody wall(Vector(), PHYS_FixedInSpace), ball(Vector(10, 0.1f, -0.2f));
    f.shapes.push_back(CreateCOBB(&wall, Vector(0.5f, 0.5f, 0.5f)));
    f.shapes.push_back(CreateCSphere(&ball, 0.05f));
    BodySweep s = f.sweep(ball, Vector(-10, 0.1f, -0.2f));
    ASSERT_EQ(s.hit, f.shapes[0]);
    const float x = -10.0f + 20.0f * s.fraction; // the centre where it is left
    EXPECT_GT(x, -0.55f);
    EXPECT_LT(x, -0.55f + 0.0005f);
}

TEST(ShapeCast, NothingIsSteppedOverAtAnySpeedOrThickness) {
    for (float thickness : {0.001f, 0.1f})
        for (float speed : {10.0f, 1000.0f, 10000.0f}) {
            Fixture f;
            UserBody wall(Vector(0.5f * thickness, 0, 0), PHYS_FixedInSpace);
            f.shapes.push_back(CreateCOBB(&wall, Vector(0.5f * thickness, 1, 1)));
            // One 60 Hz step of travel from 5 cm short of the wall (the cube's front face).
            const float path = speed / 60.0f;
            UserBody cube(Vector(-0.15f + path, 0, 0));
            f.shapes.push_back(CreateCOBB(&cube, Vector(0.1f, 0.1f, 0.1f)));
            BodySweep s = f.sweep(cube, Vector(-0.15f, 0, 0));
            ASSERT_EQ(s.hit, f.shapes[0]) << thickness << " m at " << speed << " m/s";
            const float front = -0.05f + path * s.fraction;
            EXPECT_GT(front, 0.0f);
            EXPECT_LT(front, 0.0005f + 1e-6f * speed); // float rounding of a 167 m path
        }
}

TEST(ShapeCast, TumblingBoxStopsWhereABruteForceScanFirstFindsOverlap) {
    // A 0.4 x 0.2 x 0.1 box moving 3 m and turning up to 3 rad towards a fixed box; the reference scans
    // the same interpolated path (COM linear, orientation slerp: about a fixed axis here) at 20,000 points
    // with the overlap query. The cast must stop within one scan step of the first overlap, never after.
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (int trial = 0; trial < 20; ++trial) {
        Fixture f;
        UserBody wall(Vector(0, 0, 0), PHYS_FixedInSpace);
        f.shapes.push_back(CreateCOBB(&wall, Vector(0.05f, 0.5f, 0.5f)));
        const Vector half(0.2f, 0.1f, 0.05f), axis(u(rng), u(rng), u(rng));
        const float angle = 1.5f * (u(rng) + 1.0f);
        const Vector from(-1.5f, 0.3f * u(rng), 0.3f * u(rng)), to = from + Vector(3.0f, 0.2f * u(rng), 0);
        UserBody box(to);
        box.place(to, rotation(axis, angle));
        f.shapes.push_back(CreateCOBB(&box, half));
        BodySweep s = f.sweep(box, from);
        ASSERT_EQ(s.hit, f.shapes[0]) << trial;
        const int n = 20000;
        int first = n;
        std::vector<iCollisionGeometry*> out;
        for (int k = 0; k <= n && first == n; ++k) {
            float t = float(k) / n;
            queriesOf(f.space)->overlapBox(from + (to - from) * t, rotation(axis, angle * t), half, out);
            for (iCollisionGeometry* g : out)
                if (g == f.shapes[0]) first = k;
        }
        const float reference = float(first) / n;
        EXPECT_LE(s.fraction, reference + 1.0f / n + 0.0005f / 3.0f) << trial; // + the skin along the path
        EXPECT_GE(s.fraction, reference - 1.0f / n) << trial;
    }
}

TEST(ShapeCast, SlowBodiesAndPairsTouchingAtTheStartAreLeftToContacts) {
    Fixture f;
    f.shapes.push_back(CreateCPlane(nullptr, Vector(0, 1, 0), 0.0f));
    UserBody wall(Vector(1, 0, 0), PHYS_FixedInSpace);
    f.shapes.push_back(CreateCOBB(&wall, Vector(0.5f, 0.5f, 0.5f)));
    // Moved 2 cm (under a quarter of its 0.1 m diameter) into the box: not swept.
    UserBody slow(Vector(0.47f, 0.2f, 0));
    f.shapes.push_back(CreateCSphere(&slow, 0.05f));
    EXPECT_EQ(f.sweep(slow, Vector(0.45f, 0.2f, 0)).fraction, 1.0f);
    // Sliding fast along the floor it already touches, away from the box: the floor is not a hit.
    UserBody slider(Vector(-20, 0.049f, 0));
    f.shapes.push_back(CreateCSphere(&slider, 0.05f));
    BodySweep s = f.sweep(slider, Vector(-3, 0.049f, 0));
    EXPECT_EQ(s.fraction, 1.0f);
    EXPECT_EQ(s.hit, nullptr);
}

TEST(ShapeCast, ABoxSkimmingAFloorLandsWhenItsDescentClosesTheGap) {
    // A 0.2 m cube 2 mm above a floor box moves 5 m along it while sinking 4 mm: its bottom face meets the
    // floor half-way (t = 2 mm / 4 mm), however long the slide; it is left at most 0.1 of its size further.
    Fixture f;
    UserBody floor(Vector(0, -0.5f, 0), PHYS_FixedInSpace);
    f.shapes.push_back(CreateCOBB(&floor, Vector(50, 0.5f, 50)));
    UserBody cube(Vector(5, 0.098f, 0));
    f.shapes.push_back(CreateCOBB(&cube, Vector(0.1f, 0.1f, 0.1f)));
    BodySweep s = f.sweep(cube, Vector(0, 0.102f, 0));
    ASSERT_EQ(s.hit, f.shapes[0]);
    EXPECT_GE(s.fraction, 0.5f - 1e-4f);
    EXPECT_LE(s.fraction, 0.5f + 0.1f * 0.2f / 5.0f + 1e-4f);
}

TEST(ShapeCast, AGeometryFarFromItsCentreOfMassIsSweptWhenOnlyTheTurnCarriesIt) {
    // The centre of mass stays at the origin; the 0.05 m sphere sits 2 m from it (com = (-2, 0, 0)) and the
    // body turns 0.2 rad about z, which carries the sphere 0.4 m along an arc through a 1 mm plate at
    // y = 0.2. At both ends the sphere is clear of the plate. It first touches when 2 sin(theta) + 0.05 =
    // 0.1995; the turn is uniform in angle, so at theta / 0.2 of the motion. It is left overlapping the plate
    // (the skin, 0.2 mm, so that the next step's contacts see it) but under a quarter of the plate's 1 mm.
    Fixture f;
    UserBody plate(Vector(2, 0.2f, 0), PHYS_FixedInSpace);
    f.shapes.push_back(CreateCOBB(&plate, Vector(0.5f, 0.0005f, 0.5f)));
    UserBody arm(Vector(0, 0, 0));
    arm.getDynamics().com = Vector(-2, 0, 0);
    arm.place(Vector(0, 0, 0), rotation(Vector(0, 0, 1), 0.2f));
    f.shapes.push_back(CreateCSphere(&arm, 0.05f));
    BodySweep s = f.sweep(arm, Vector(0, 0, 0), Matrix(1));
    ASSERT_EQ(s.hit, f.shapes[0]);
    const float reference = std::asin((0.1995f - 0.05f) / 2.0f) / 0.2f;
    EXPECT_GE(s.fraction, reference - 0.0005f); // the touch tolerance (0.1 mm) is 0.00025 of the motion here
    EXPECT_LE(s.fraction, reference + 0.001f);
    const float top = 2.0f * std::sin(0.2f * s.fraction) + 0.05f;
    EXPECT_GT(top, 0.1995f);
    EXPECT_LT(top, 0.1995f + 0.00025f);
}
