// ContactSolverTest.cpp - the contact solver on hand-made contacts, against closed-form impulse mechanics.
#include "SolverFixtures.h"

#include "MathDefinitions.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

using namespace solver_test;
using physics::ContactSolver;
using physics::SolverBodyAccess;

namespace {

const float kG = 9.81f, kDt = 1.0f / 60.0f;

struct Pair {
    Body a, b;
    Geometry ga{&a}, gb{&b};
};

// b: a unit box of mass m on a, a fixed floor, its centre 0.5 m up, moving at v.
void boxOnFloor(Pair& p, float m, const Vector& v) {
    p.a.d.physicsType = PHYS_FixedInSpace;
    p.b.d.mass = m;
    p.b.d.setInertiaTensor(getBoxInertiaTensor(m, Vector(0.5f, 0.5f, 0.5f)));
    p.b.d.position = Vector(0, 0.5f, 0);
    p.b.d.velocity = v;
}

} // namespace

TEST(ContactSolver, HeadOnCollisionMatchesTheRestitutionLaw) {
    // 1D collision: v1' = (m1 v1 + m2 v2 + m2 e (v2 - v1)) / (m1 + m2), and symmetrically for v2'.
    for (float e : {0.0f, 0.5f, 1.0f}) {
        Pair p;
        float m1 = 1.0f, m2 = 3.0f, v1 = 4.0f, v2 = -2.0f;
        p.a.d.mass = m1;
        p.b.d.mass = m2;
        p.a.d.setInertiaTensor(getSphereInertiaTensor(m1, 0.5f));
        p.b.d.setInertiaTensor(getSphereInertiaTensor(m2, 0.5f));
        p.a.d.restitution = p.b.d.restitution = e;
        p.a.d.position = Vector(-0.5f, 0, 0);
        p.b.d.position = Vector(0.5f, 0, 0);
        p.a.d.velocity = Vector(v1, 0, 0);
        p.b.d.velocity = Vector(v2, 0, 0);
        CollisionContact c = contact(p.ga, p.gb, Vector(0, 0, 0), Vector(1, 0, 0), 0.0f);
        ContactSolver solver;
        solver.solve(&c, 1, kDt, SolverBodyAccess());
        float expected1 = (m1 * v1 + m2 * v2 + m2 * e * (v2 - v1)) / (m1 + m2);
        float expected2 = (m1 * v1 + m2 * v2 + m1 * e * (v1 - v2)) / (m1 + m2);
        EXPECT_NEAR(p.a.d.velocity.x, expected1, 1e-4f) << "e = " << e;
        EXPECT_NEAR(p.b.d.velocity.x, expected2, 1e-4f) << "e = " << e;
        EXPECT_NEAR(m1 * p.a.d.velocity.x + m2 * p.b.d.velocity.x, m1 * v1 + m2 * v2, 1e-4f); // momentum
        EXPECT_NEAR(p.a.d.angularVelocity.length(), 0.0f, 1e-6f); // central impact: no spin
    }
}

TEST(ContactSolver, SlowApproachDoesNotBounce) {
    // Below the restitution threshold (1 m/s) a contact only stops the approach: resting stays resting.
    Pair p;
    p.a.d.physicsType = PHYS_FixedInSpace;
    p.b.d.restitution = p.a.d.restitution = 1.0f;
    p.b.d.velocity = Vector(0, -0.5f, 0);
    CollisionContact c = contact(p.ga, p.gb, Vector(0, 0, 0), Vector(0, 1, 0), 0.001f);
    ContactSolver solver;
    solver.solve(&c, 1, kDt, SolverBodyAccess());
    EXPECT_NEAR(p.b.d.velocity.y, 0.0f, 1e-4f); // stopped; the 1 mm overlap's push-out speed is relaxed away
    EXPECT_EQ(p.a.d.velocity.y, 0.0f);          // the fixed body never moves
}

TEST(ContactSolver, FrictionTakesMuTimesTheNormalImpulse) {
    // A box resting on a fixed floor, sliding at 1 m/s, after gravity acted for one step (v_y = -g dt).
    // Holding it up takes a normal impulse m g dt, so Coulomb friction removes mu g dt of sliding speed.
    Pair p;
    boxOnFloor(p, 2.0f, Vector(1, -kG * kDt, 0));
    p.a.d.friction = 0.2f;
    p.b.d.friction = 0.3f; // the seed's rule: mu = 0.2 + 0.3
    // Four corner points of the bottom face (no tipping: the torques cancel).
    CollisionContact cs[4];
    int i = 0;
    for (float x : {-0.5f, 0.5f})
        for (float z : {-0.5f, 0.5f}) cs[i++] = contact(p.ga, p.gb, Vector(x, 0, z), Vector(0, 1, 0), 0.0f);
    ContactSolver solver;
    const SolverBodyAccess gravity(physics::Vec3(0, -kG * kDt, 0)); // the sub-steps add it a share at a time
    solver.solve(cs, 4, kDt, gravity);
    EXPECT_NEAR(p.b.d.velocity.y, 0.0f, 1e-3f);
    EXPECT_NEAR(p.b.d.velocity.x, 1.0f - 0.5f * kG * kDt, 2e-3f);
    // A slow slide is stopped outright rather than reversed.
    p.b.d.position = Vector(0, 0.5f, 0);
    p.b.d.velocity = Vector(0.01f, -kG * kDt, 0);
    solver.solve(cs, 4, kDt, gravity);
    EXPECT_NEAR(p.b.d.velocity.x, 0.0f, 1e-3f); // (was 0.01 m/s; what is left is Gauss-Seidel's residue)
}

TEST(ContactSolver, OffCentreImpactSpinsTheBodyAsImpulseMechanicsSays) {
    // A body hits a fixed wall at a point r off its centre: j = -(1 + e) v_n / (1/m + n.((I^-1 (r x n)) x
    // r)), then dv = j n / m and dw = I^-1 (r x j n).
    Pair p;
    p.a.d.physicsType = PHYS_FixedInSpace;
    p.a.d.restitution = p.b.d.restitution = 0.5f;
    float m = 2.0f;
    p.b.d.mass = m;
    Matrix inertia = getBoxInertiaTensor(m, Vector(1.0f, 0.25f, 0.5f));
    p.b.d.setInertiaTensor(inertia);
    p.b.d.velocity = Vector(0, -3, 0);
    Vector r(0.8f, -0.25f, 0.1f), n(0, 1, 0); // contact point relative to the body's centre
    CollisionContact c = contact(p.ga, p.gb, r, n, 0.0f);
    p.b.d.friction = p.a.d.friction = 0.0f; // normal impulse alone
    ContactSolver solver;
    solver.solve(&c, 1, kDt, SolverBodyAccess());
    Matrix inv = inertia.inverse();
    Vector rn = cross(r, n);
    float k = 1 / m + dot(n, cross(rn * inv, r));
    float j = -(1 + 0.5f) * -3.0f / k;
    Vector dv = n * (j / m), dw = cross(r, n * j) * inv;
    EXPECT_NEAR(p.b.d.velocity.y, -3.0f + dv.y, 1e-4f);
    EXPECT_NEAR(p.b.d.angularVelocity.x, dw.x, 1e-4f);
    EXPECT_NEAR(p.b.d.angularVelocity.z, dw.z, 1e-4f);
    // The contact point itself leaves at e times its approach speed.
    EXPECT_NEAR(dot(p.b.d.getVelocityAtWorldPoint(r), n), 1.5f, 1e-4f);
}

TEST(ContactSolver, WarmStartCarriesTheRestingImpulseAcrossSteps) {
    // A resting box needs a normal impulse of m g h every sub-step h. Warm started, one sub-step a step is
    // enough to hold it: the stored impulse converges to m g dt and the box neither sinks nor tilts.
    Pair p;
    p.a.d.physicsType = PHYS_FixedInSpace;
    p.b.d.mass = 3.0f;
    p.b.d.setInertiaTensor(getBoxInertiaTensor(3.0f, Vector(0.5f, 0.5f, 0.5f)));
    p.b.d.position = Vector(0, 0.5f, 0);
    CollisionContact cs[4];
    int i = 0;
    for (float x : {-0.5f, 0.5f})
        for (float z : {-0.5f, 0.5f}) cs[i++] = contact(p.ga, p.gb, Vector(x, 0, z), Vector(0, 1, 0), 0.0f);
    ContactSolver solver;
    physics::SolverSettings s;
    s.substeps = 1;
    solver.setSettings(s);
    for (int step = 0; step < 30; ++step) {
        p.b.d.velocity += Vector(0, -kG * kDt, 0); // gravity
        solver.solve(cs, 4, kDt, SolverBodyAccess(physics::Vec3(0, -kG * kDt, 0)));
    }
    float total = 0;
    for (const physics::Manifold& m : solver.manifolds())
        for (int k = 0; k < m.count; ++k) total += m.points[k].normalImpulse;
    EXPECT_NEAR(total, 3.0f * kG * kDt, 1e-3f);
    EXPECT_NEAR(p.b.d.velocity.y, 0.0f, 1e-4f);
    EXPECT_NEAR(p.b.d.angularVelocity.length(), 0.0f, 1e-4f);
}

TEST(ContactSolver, AShallowOverlapIsPushedOutSoftlyWithoutAddingVelocity) {
    // A unit box sunk 5 mm into a fixed floor: the soft contact, a heavily damped spring, pushes it out over
    // a few steps (never faster than maxPushSpeed), and the relax passes leave it no speed: no bounce, no
    // energy.
    Pair p;
    p.a.d.physicsType = PHYS_FixedInSpace;
    p.b.d.position = Vector(0, 0.495f, 0);
    ContactSolver solver;
    float previous = 0.495f, worstSpeed = 0;
    for (int step = 1; step <= 30; ++step) {
        float depth = 0.5f - p.b.d.position.y;
        CollisionContact cs[4];
        int i = 0;
        for (float x : {-0.5f, 0.5f})
            for (float z : {-0.5f, 0.5f})
                cs[i++] = contact(p.ga, p.gb, Vector(x, -0.5f * depth, z), Vector(0, 1, 0), depth);
        solver.solve(cs, 4, kDt, SolverBodyAccess());
        worstSpeed = std::max(worstSpeed, p.b.d.velocity.length());
        EXPECT_GE(p.b.d.position.y, previous - 1e-6f) << "step " << step; // out, never back in
        EXPECT_LE(p.b.d.position.y - previous, solver.settings().maxPushSpeed * kDt + 1e-6f);
        previous = p.b.d.position.y;
        if (step == 3) {
            EXPECT_GT(p.b.d.position.y, 0.4975f); // half out within 3 steps (50 ms)
        }
    }
    EXPECT_NEAR(p.b.d.position.y, 0.5f, 1e-4f); // out, and not beyond touching
    EXPECT_LT(worstSpeed, 1e-3f);
    EXPECT_TRUE(isRotation(p.b.d.orientation));
    EXPECT_NEAR(p.b.d.orientation.m11, 1.0f, 1e-5f); // a level push does not tilt it
}

TEST(ContactSolver, ADeepOverlapIsProjectedOutAtOnce) {
    // 10 cm deep, found late after falling at 6 m/s (0.1 m in the step): out to within deepOverlap in one
    // step, without any speed (e = 0).
    Pair p;
    p.a.d.physicsType = PHYS_FixedInSpace;
    p.a.d.restitution = p.b.d.restitution = 0.0f;
    p.b.d.position = Vector(0, 0.4f, 0);
    p.b.d.velocity = Vector(0, -6, 0);
    CollisionContact cs[4];
    int i = 0;
    for (float x : {-0.5f, 0.5f})
        for (float z : {-0.5f, 0.5f})
            cs[i++] = contact(p.ga, p.gb, Vector(x, -0.05f, z), Vector(0, 1, 0), 0.1f);
    ContactSolver solver;
    solver.solve(cs, 4, kDt, SolverBodyAccess());
    EXPECT_NEAR(p.b.d.position.y, 0.5f - solver.settings().deepOverlap, 2e-3f);
    EXPECT_LE(solver.maxPenetrationAfter(), solver.settings().deepOverlap + 1e-3f);
    // Gauss-Seidel's residue of stopping 6 m/s over four corners; measured 6.7 mm/s (0.1 %).
    EXPECT_NEAR(p.b.d.velocity.length(), 0.0f, 0.01f);
}

TEST(ContactSolver, ADeepOverlapNotFlownIntoIsPushedOutAtTheCappedSpeed) {
    // 10 cm deep at rest (spawned inside): projection may undo only what the pair closed in the step, so the
    // soft push moves it out, no faster than maxPushSpeed, and leaves it no speed.
    Pair p;
    p.a.d.physicsType = PHYS_FixedInSpace;
    p.b.d.position = Vector(0, 0.4f, 0);
    CollisionContact cs[4];
    int i = 0;
    for (float x : {-0.5f, 0.5f})
        for (float z : {-0.5f, 0.5f})
            cs[i++] = contact(p.ga, p.gb, Vector(x, -0.05f, z), Vector(0, 1, 0), 0.1f);
    ContactSolver solver;
    solver.solve(cs, 4, kDt, SolverBodyAccess());
    EXPECT_GT(p.b.d.position.y, 0.4f + 1e-3f);
    EXPECT_LE(p.b.d.position.y, 0.4f + solver.settings().maxPushSpeed * kDt + 1e-5f);
    EXPECT_NEAR(p.b.d.velocity.length(), 0.0f, 2e-3f);
}

TEST(ContactSolver, ALandingBoxLosesMuTimesItsImpactSpeedOfSlidingSpeed) {
    // Coulomb's law for an impact: the normal impulse m v_n stops the fall (e = 0), and friction takes at
    // most mu m v_n of the slide: 3 m/s - 0.5 * 4 m/s = 1 m/s. (Friction bounded by a warm-started impact
    // impulse in every sub-step would stop the slide outright.)
    Pair p;
    p.a.d.physicsType = PHYS_FixedInSpace;
    p.a.d.restitution = p.b.d.restitution = 0.0f;
    p.b.d.position = Vector(0, 0.5f, 0);
    p.b.d.velocity = Vector(3, -4, 0);
    CollisionContact cs[4];
    int i = 0;
    for (float x : {-0.5f, 0.5f})
        for (float z : {-0.5f, 0.5f}) cs[i++] = contact(p.ga, p.gb, Vector(x, 0, z), Vector(0, 1, 0), 0.0f);
    ContactSolver solver;
    solver.solve(cs, 4, kDt, SolverBodyAccess());
    // Measured: 1.003 m/s of slide kept and a 0.015 m/s hop (Gauss-Seidel's residue over four corners).
    EXPECT_NEAR(p.b.d.velocity.y, 0.0f, 0.05f);
    EXPECT_NEAR(p.b.d.velocity.x, 3.0f - 0.5f * 4.0f, 0.02f);
}

TEST(ContactSolver, CombineRules) {
    using physics::combine;
    EXPECT_FLOAT_EQ(combine(COMBINE_Sum, 0.2f, 0.3f), 0.5f);
    EXPECT_FLOAT_EQ(combine(COMBINE_Average, 0.2f, 0.3f), 0.25f);
    EXPECT_FLOAT_EQ(combine(COMBINE_Max, 0.2f, 0.3f), 0.3f);
    EXPECT_FLOAT_EQ(combine(COMBINE_Min, 0.2f, 0.3f), 0.2f);
    EXPECT_FLOAT_EQ(combine(COMBINE_Product, 0.2f, 0.3f), 0.06f);
    EXPECT_NEAR(combine(COMBINE_GeometricMean, 0.2f, 0.8f), 0.4f, 1e-6f);
}

TEST(ContactSolver, ABodilessGeometryIsTheStaticWorld) {
    // A world-space plane has no body: it acts as an immovable anchor, and its material is the default.
    Body ball;
    Geometry plane(nullptr), sphere(&ball);
    ball.d.restitution = 0.0f; // max(0, default 0.5) = 0.5 with the default rule
    ball.d.velocity = Vector(0, -4, 0);
    CollisionContact c = contact(plane, sphere, Vector(0, 0, 0), Vector(0, 1, 0), 0.01f);
    ContactSolver solver;
    solver.solve(&c, 1, kDt, SolverBodyAccess());
    EXPECT_NEAR(ball.d.velocity.y, 2.0f, 1e-4f); // bounces at e = 0.5
    EXPECT_GE(ball.d.position.y, 0.0f);          // not pushed into the plane
}

TEST(ContactSolver, ACornerThatLiftedByAHairIsKeptAndHoldsOnlyOnceItsGapCloses) {
    // A box rests on a fixed floor on four corners; next step it is 1 mm higher and the detector reports
    // only the two corners at z = +0.5. The other two are kept (apart by 1 mm, under keepDistance): falling
    // g dt^2 = 2.7 mm this step would close their gap, so they catch the box level instead of letting it
    // tip over the reported edge.
    auto run = [](float keepDistance, size_t& points) {
        Pair p;
        boxOnFloor(p, 1.0f, Vector(0, -kG * kDt, 0));
        ContactSolver solver;
        physics::SolverSettings s;
        s.keepDistance = keepDistance;
        solver.setSettings(s);
        const SolverBodyAccess gravity(physics::Vec3(0, -kG * kDt, 0));
        CollisionContact cs[4];
        int i = 0;
        for (float x : {-0.5f, 0.5f})
            for (float z : {-0.5f, 0.5f})
                cs[i++] = contact(p.ga, p.gb, Vector(x, 0, z), Vector(0, 1, 0), 0.0f);
        solver.solve(cs, 4, kDt, gravity);
        p.b.d.position = Vector(0, 0.501f, 0);
        p.b.d.orientation = Matrix(1);
        p.b.d.velocity = Vector(0, -kG * kDt, 0);
        p.b.d.angularVelocity = Vector();
        CollisionContact edge[2] = {contact(p.ga, p.gb, Vector(-0.5f, 0.001f, 0.5f), Vector(0, 1, 0), 0.0f),
                                    contact(p.ga, p.gb, Vector(0.5f, 0.001f, 0.5f), Vector(0, 1, 0), 0.0f)};
        solver.solve(edge, 2, kDt, gravity);
        points = size_t(solver.manifolds()[0].count);
        return p.b.d.angularVelocity.length();
    };
    size_t kept = 0, reported = 0;
    float tipKept = run(0.01f, kept), tipReported = run(0.0f, reported);
    EXPECT_EQ(kept, 4u);
    EXPECT_EQ(reported, 2u);
    EXPECT_LT(tipKept, 0.5f * tipReported);
    EXPECT_GT(tipReported, 0.1f); // rad/s: on the reported edge alone the box starts to tip
    RecordProperty("tip_rad_per_s_kept", std::to_string(tipKept));
    RecordProperty("tip_rad_per_s_reported_only", std::to_string(tipReported));
}

TEST(ContactSolver, ContactsWithoutBothGeometriesAreSkipped) {
    // A space of the game's own may list a contact with a null geometry: it is no contact, and the solve of
    // a list holding such entries among real ones equals, bit for bit, the solve of the real ones alone.
    // (Long enough for collecting the manifolds to look ahead past the null entries.)
    auto run = [](bool withNulls) {
        Pair p;
        boxOnFloor(p, 2.0f, Vector(1, -kG * kDt, 0.2f));
        std::vector<CollisionContact> list;
        const CollisionContact none{Vector(), Vector(0, 1, 0), 0.0f, nullptr, nullptr};
        for (int k = 0; k < 40; ++k) {
            if (withNulls) {
                CollisionContact half = none;
                half.g1 = (k % 2) ? &p.ga : nullptr;
                half.g2 = (k % 2) ? nullptr : &p.gb;
                list.push_back(k % 3 ? half : none);
            }
            if (k % 10 == 0) // the four corners of the bottom face, spread along the list
                list.push_back(contact(p.ga, p.gb,
                                       Vector(k < 20 ? -0.5f : 0.5f, 0, (k / 10) % 2 ? 0.5f : -0.5f),
                                       Vector(0, 1, 0), 0.001f));
        }
        ContactSolver solver;
        solver.solve(list.data(), list.size(), kDt, SolverBodyAccess(physics::Vec3(0, -kG * kDt, 0)));
        return std::make_pair(p.b.d.velocity, p.b.d.angularVelocity);
    };
    const auto clean = run(false), mixed = run(true);
    EXPECT_NEAR(clean.first.y, 0.0f, 1e-3f); // the corners held the box up
    EXPECT_LT(clean.first.x, 1.0f);          // and their friction slowed it
    for (float Vector::*axis : {&Vector::x, &Vector::y, &Vector::z}) {
        EXPECT_EQ(clean.first.*axis, mixed.first.*axis);
        EXPECT_EQ(clean.second.*axis, mixed.second.*axis);
    }
}
