// WorldScaleTest.cpp - any scale of world (issue 14 item 3): a scene built in another length unit
// (iPhysicsSceneSettings::setLengthUnitsPerMetre) behaves as the same scene in metres, and bodies of very
// different sizes in one scene each rest within 1 % of their own size.
//
// Each experiment is run at s = 0.01, 1 and 100 length units per metre, every length (sizes, heights,
// speeds, gravity) multiplied by s, through scene->update(now). Its result, divided by s, is held against the
// analytic value of rigid-body mechanics and against the other scales, within 1 %.
#include "SceneFixture.h"

#include "ErrorRecorder.h"
#include "iCollisionSpaceScale.h"
#include "iOctreeCollisionSpace.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iterator>
#include <string>

using namespace resolution_test;

namespace {

const float kScales[] = {0.01f, 1.0f, 100.0f};

// A scene in units of s per metre: the unit set, gravity -9.81 s, a ground plane at y = 0.
struct ScaledScene {
    SceneFixture f{4}; // the default iterations
    float s;
    explicit ScaledScene(float scale) : s(scale) {
        EXPECT_TRUE(settingsOf(f.scene)->setLengthUnitsPerMetre(s));
        settingsOf(f.scene)->setGravity(Vector(0, -kG * s, 0));
        f.world->ground();
    }
};

// A ball of radius 0.5 (restitution 0.8, the floor's 0.5 combining by the larger) dropped with its bottom h
// above the floor: the apex of its first rebound, in metres. Energy: the impact speed is sqrt(2 g h), the
// bounce keeps e of it, so the rebound rises e^2 h.
float reboundApex(float s, float h) {
    ScaledScene w(s);
    RBDynamics* ball = w.f.world->sphere(Vector(0, (0.5f + h) * s, 0), 0.5f * s, 1.0f)->getDynamics();
    ball->restitution = 0.8f;
    bool rising = false, done = false;
    float apex = 0;
    w.f.seconds(2.5f, [&] {
        const float y = (ball->position.y / s) - 0.5f;
        if (done) return;
        if (ball->velocity.y > 0) {
            rising = true;
            apex = std::max(apex, y);
        } else if (rising) {
            done = true; // past the first apex
        }
    });
    EXPECT_TRUE(done) << "s = " << s;
    return apex;
}

// A box (half extents 0.5, friction 0.25 + the floor's 0.25: mu = 0.5) resting on the floor, sent along x at
// v: the distance it slides, in metres. Coulomb friction decelerates it at mu g: it stops after v^2/(2 mu g).
float slideDistance(float s, float v) {
    ScaledScene w(s);
    RBDynamics* box =
        w.f.world->box(Vector(0, 0.5f * s, 0), Vector(0.5f, 0.5f, 0.5f) * s, 1.0f)->getDynamics();
    box->friction = 0.25f;
    w.f.seconds(0.25f); // settles on the floor
    const float x0 = box->position.x;
    box->velocity = Vector(v * s, 0, 0);
    w.f.seconds(2.0f);
    EXPECT_LT(std::fabs(box->velocity.x), 1e-3f * v * s) << "s = " << s << ": still sliding";
    return (box->position.x - x0) / s;
}

// A solid ball (radius 0.5, mu = 0.5) set down sliding at v without spin: friction slows it and spins it up
// until it rolls, at 5/7 v (angular momentum about the contact point is conserved: m v r = m v' r +
// 2/5 m r^2 v'/r). Returns its speed along the floor then (m/s) and the slip left at the contact point (its
// speed there along the floor, m/s).
struct Roll {
    float speed, slip;
};
Roll rollingSpeed(float s, float v) {
    ScaledScene w(s);
    const float r = 0.5f * s;
    RBDynamics* ball = w.f.world->sphere(Vector(0, r, 0), r, 1.0f)->getDynamics();
    ball->friction = 0.25f;
    ball->restitution = 0.0f;
    ball->velocity = Vector(v * s, 0, 0);
    w.f.seconds(1.0f); // rolls after 2 v / (7 mu g) = 0.17 s at v = 3 m/s
    // Along the floor: the stored velocity of a rolling ball carries -0.06 m/s along the normal that its
    // height never shows (the contact's push out answers it each sub-step), at every scale alike.
    const Vector contact = ball->velocity + cross(ball->angularVelocity, Vector(0, -r, 0));
    const float horizontal = std::hypot(ball->velocity.x, ball->velocity.z);
    return Roll{horizontal / s, std::hypot(contact.x, contact.z) / s};
}

void expectWithin(float value, float truth, float fraction, const std::string& what) {
    EXPECT_NEAR(value, truth, fraction * std::fabs(truth)) << what;
}

// measure(s) at every scale: each result within 1 % of the analytic truth and of the result at s = 1.
void expectAtEveryScale(const std::string& what, float truth, const std::function<float(float)>& measure) {
    float result[3];
    for (int i = 0; i < 3; ++i) {
        result[i] = measure(kScales[i]);
        expectWithin(result[i], truth, 0.01f, what + " at s = " + std::to_string(kScales[i]));
        ::testing::Test::RecordProperty(what + "_s" + std::to_string(i), std::to_string(result[i] / truth));
    }
    for (int i = 0; i < 3; ++i)
        expectWithin(result[i], result[1], 0.01f, what + ": against s = 1, s index " + std::to_string(i));
}

} // namespace

TEST(WorldScale, ABounceReboundsToESquaredTimesItsDropAtEveryScale) {
    const float h = 1.0f;
    expectAtEveryScale("apex_over_e2h", 0.64f * h, [h](float s) { return reboundApex(s, h); });
}

TEST(WorldScale, ASlideStopsAfterVSquaredOverTwoMuGAtEveryScale) {
    const float v = 4.0f;
    expectAtEveryScale("slide_over_truth", v * v / (2.0f * 0.5f * kG),
                       [v](float s) { return slideDistance(s, v); });
}

TEST(WorldScale, ASlidingBallRollsAtFiveSeventhsOfItsSpeedAtEveryScale) {
    const float v = 3.0f, truth = 5.0f / 7.0f * v;
    expectAtEveryScale("roll_over_truth", truth, [v, truth](float s) {
        const Roll roll = rollingSpeed(s, v);
        EXPECT_LT(roll.slip, 0.01f * truth) << "still slipping at s = " << s;
        return roll.speed;
    });
}

// A 1 mm steel cube and a 1 km granite rock dropped flat onto the floor from 1 % of their size in one metre
// scene (the rock lands at 10 m/s and bounces, e = 0.5 being the floor's): each comes to rest (asleep) with
// its bottom within 1 % of its own size of the floor. Without the contact stiffness that
// follows a shape's size, the cube's contact would give |g| / (2 pi 60 Hz)^2 = 0.07 mm, 7 % of it.
TEST(WorldScale, AMillimetreCubeAndAKilometreRockEachRestWithinOnePercentOfTheirSize) {
    SceneFixture f(4);
    f.world->ground();
    struct Body {
        float half;
        RBDynamics* d;
    };
    Body bodies[] = {{0.0005f, nullptr}, {500.0f, nullptr}};
    const float density[] = {7850.0f, 2700.0f};
    const float x[] = {0.0f, 1000.0f};
    for (int i = 0; i < 2; ++i) {
        const float h = bodies[i].half, mass = density[i] * 8.0f * h * h * h;
        bodies[i].d = f.world->box(Vector(x[i], 1.01f * h, 0), Vector(h, h, h), mass)->getDynamics();
        bodies[i].d->restitution = 0.0f;
    }
    f.seconds(4.0f);
    for (const Body& b : bodies) {
        const float size = 2.0f * b.half;
        const float overlap = b.half - b.d->position.y; // the bottom's depth below the floor
        EXPECT_LT(std::fabs(overlap), 0.01f * size) << "size " << size << " m: bottom " << -overlap;
        EXPECT_TRUE(b.d->sleeping) << "size " << size << " m";
        EXPECT_LT(b.d->velocity.length(), 0.01f * size) << "size " << size << " m";
        char figure[32];
        std::snprintf(figure, sizeof figure, "%.3g", double(overlap / size));
        RecordProperty("overlap_over_size_" + std::to_string(int(size * 1000)) + "mm", figure);
    }
}

// The unit is refused out of range or when not finite (the old one kept), and reaches the collision space;
// the octree space takes one too.
TEST(WorldScale, TheUnitIsRefusedOutOfRangeAndForwardedToTheSpace) {
    SceneFixture f(4);
    iPhysicsSceneSettings* settings = settingsOf(f.scene);
    EXPECT_EQ(settings->getLengthUnitsPerMetre(), 1.0f);
    EXPECT_TRUE(settings->setLengthUnitsPerMetre(100.0f));
    iCollisionSpaceScale* space = scaleOf(f.world->space());
    ASSERT_NE(space, nullptr);
    EXPECT_EQ(space->getLengthUnitsPerMetre(), 100.0f);
    guardian_test::ErrorRecorder errors;
    const float bad[] = {0.0f, -1.0f, 1e-4f, 1e4f, std::nanf(""), INFINITY};
    for (float u : bad) {
        EXPECT_FALSE(settings->setLengthUnitsPerMetre(u)) << u;
        EXPECT_FALSE(space->setLengthUnitsPerMetre(u)) << u;
    }
    EXPECT_EQ(errors.count(), 2 * std::size(bad)); // each refusal said so
    EXPECT_EQ(settings->getLengthUnitsPerMetre(), 100.0f);
    EXPECT_EQ(space->getLengthUnitsPerMetre(), 100.0f);

    iCollisionSpace* octree = CreateOctreeCollisionSpace();
    ASSERT_NE(scaleOf(octree), nullptr);
    EXPECT_EQ(scaleOf(octree)->getLengthUnitsPerMetre(), 1.0f);
    EXPECT_TRUE(scaleOf(octree)->setLengthUnitsPerMetre(0.001f));
    EXPECT_EQ(scaleOf(octree)->getLengthUnitsPerMetre(), 0.001f);
    octree->Delete();
}

// Drag follows the body's size: spheres of radius 0.1, 1 and 10 m (Cd 0.47, mass chosen for a terminal speed
// near 10 m/s) dropped from rest fall through the air as m v' = m g - 1/2 rho Cd (pi r^2) v^2 says, reaching
// vt = sqrt(2 m g / (rho Cd pi r^2)) within 1 %; the same at 100 units per metre (every length times 100,
// gravity -981). A box's reference area is that of the sphere with its volume.
TEST(WorldScale, DragFollowsTheBodysSize) {
    const float cd = 0.47f, vt = 10.0f;
    for (float s : {1.0f, 100.0f})
        for (float r : {0.1f, 1.0f, 10.0f}) {
            SceneFixture f(4);
            ASSERT_TRUE(settingsOf(f.scene)->setLengthUnitsPerMetre(s));
            settingsOf(f.scene)->setGravity(Vector(0, -kG * s, 0));
            const float area = 3.14159265f * r * r; // m^2
            const float mass = 0.5f * 1.2f * cd * area * vt * vt / kG;
            RBDynamics* d = f.world->sphere(Vector(0, 0, 0), r * s, mass)->getDynamics();
            d->dragCoefficient = cd;
            f.seconds(6.0f); // 6 time constants vt / g
            EXPECT_NEAR(-d->velocity.y / s, vt, 0.01f * vt) << "r " << r << " m at " << s << " units/m";
        }
    SceneFixture f(4);
    const float h = 0.5f, cube = 8 * h * h * h, r = std::cbrt(cube * 3.0f / (4.0f * 3.14159265f));
    const float mass = 0.5f * 1.2f * cd * 3.14159265f * r * r * vt * vt / kG;
    RBDynamics* box = f.world->box(Vector(0, 0, 0), Vector(h, h, h), mass)->getDynamics();
    box->dragCoefficient = cd;
    f.seconds(6.0f);
    EXPECT_NEAR(-box->velocity.y, vt, 0.01f * vt);
}
