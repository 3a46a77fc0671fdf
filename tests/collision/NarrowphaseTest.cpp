// NarrowphaseTest.cpp - the pure pair functions against an independent truth (GjkReference.h, or the closed
// form for two spheres): 10^5 random pairs per shape pair with a fixed seed. For each pair the verdict must
// match; for each overlapping pair the normal and depth must be the minimum translation (moving the second
// shape by normal * (depth + eps) separates it, by normal * (depth * (1 - 3%) - eps) does not) and every
// contact point must lie within half the depth (plus a tolerance) of both shapes.
#include "Narrowphase.h"
#include "GjkReference.h"
#include "MathEigen.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

using namespace gcol;
using gjkref::V3;

namespace {

// 10^5 pairs per shape pair in normal builds; under ASan/UBSan (which check memory, not statistics) fewer.
#if defined(__has_feature) // clang++ says so here, g++ in __SANITIZE_ADDRESS__
#if __has_feature(address_sanitizer)
#define GUARDIAN_UNDER_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(GUARDIAN_UNDER_ASAN)
constexpr int kPairs = 5000;
#else
constexpr int kPairs = 100000;
#endif

V3 v3(const Vector& v) { return V3(v.x, v.y, v.z); }

struct Rng {
    std::mt19937 gen;
    explicit Rng(unsigned seed) : gen(seed) {}
    float uni(float a, float b) { return std::uniform_real_distribution<float>(a, b)(gen); }
    int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(gen); }
    Vector vec(float s) { return Vector(uni(-s, s), uni(-s, s), uni(-s, s)); }
    Matrix rotation() {
        Eigen::Quaternionf q(uni(-1, 1), uni(-1, 1), uni(-1, 1), uni(-1, 1));
        if (q.norm() < 1e-3f) q = Eigen::Quaternionf::Identity();
        q.normalize();
        return gmath::fromBlock3(q.toRotationMatrix());
    }
};

WorldShape makeSphere(const Vector& c, float r) {
    WorldShape s;
    s.kind = ShapeKind::Sphere;
    s.sphere.centre = c;
    s.sphere.radius = r;
    return s;
}
WorldShape makeBox(const Vector& c, const Matrix& r, const Vector& h) {
    WorldShape s;
    s.kind = ShapeKind::Box;
    s.box.centre = c;
    s.box.axis[0] = r.direction('x');
    s.box.axis[1] = r.direction('y');
    s.box.axis[2] = r.direction('z');
    s.box.halfExtents = h;
    return s;
}

// The shape moved by d and grown (or shrunk) by g on every side, as a GJK core plus a margin: a sphere is
// its centre point with its radius as margin, a box is itself with no margin. Exact for these shapes, and
// GJK on polytope cores converges in a few iterations.
struct RefShape {
    gjkref::Support core;
    double margin;
};
RefShape support(const WorldShape& s, const Vector& d = Vector(), float g = 0.0f) {
    if (s.kind == ShapeKind::Sphere)
        return {gjkref::pointSupport(v3(s.sphere.centre + d)), std::fmax(0.0, double(s.sphere.radius) + g)};
    Eigen::Matrix3d axes;
    for (int i = 0; i < 3; ++i) axes.row(i) = v3(s.box.axis[i]).transpose();
    return {
        gjkref::boxSupport(v3(s.box.centre + d), axes, (v3(s.box.halfExtents) + V3(g, g, g)).cwiseMax(0.0)),
        0.0};
}
// Distance between the two shapes (0 when they overlap).
double refDistance(const RefShape& a, const RefShape& b) {
    return std::fmax(0.0, gjkref::distance(a.core, b.core) - a.margin - b.margin);
}
RefShape point(const Vector& p) { return {gjkref::pointSupport(v3(p)), 0.0}; }

float scaleOf(const WorldShape& s) {
    return s.kind == ShapeKind::Sphere
               ? s.sphere.radius
               : std::fmax(s.box.halfExtents.x, std::fmax(s.box.halfExtents.y, s.box.halfExtents.z));
}

// A random shape of the given kind, with a share of degenerate ones (thin, axis-aligned, shared centre).
WorldShape randomShape(Rng& rng, ShapeKind kind, const Vector& centre, const Matrix* sharedRotation) {
    if (kind == ShapeKind::Sphere) return makeSphere(centre, rng.uni(0.05f, 1.0f));
    Vector h(rng.uni(0.05f, 1.0f), rng.uni(0.05f, 1.0f), rng.uni(0.05f, 1.0f));
    if (rng.pick(10) == 0) setComponent(h, rng.pick(3), 1e-3f); // very thin
    Matrix r = rng.pick(10) == 0 ? Matrix(1) : rng.rotation();
    if (sharedRotation && rng.pick(8) == 0) r = *sharedRotation; // parallel faces and edges
    return makeBox(centre, r, h);
}

struct Stats {
    int overlapping = 0, separated = 0, ambiguous = 0;
};

void checkPair(const WorldShape& a, const WorldShape& b, Stats& st) {
    ContactManifold m;
    int n = collideShapes(a, b, m);
    const float scale = std::fmax(scaleOf(a), scaleOf(b));
    const float eps = 2e-3f * (1.0f + scale);
    double d = refDistance(support(a), support(b));
    bool trulyApart = d > 1e-9;
    // Near-touching pairs are ambiguous in float: decide only when shrinking/growing by eps agrees.
    bool sure = trulyApart ? refDistance(support(a, Vector(), eps), support(b, Vector(), eps)) > 1e-9
                           : refDistance(support(a, Vector(), -0.5f * eps),
                                         support(b, Vector(), -0.5f * eps)) <= 1e-9;
    if (!sure) {
        ++st.ambiguous;
        return;
    }
    if (trulyApart) {
        ++st.separated;
        ASSERT_EQ(n, 0) << "false contact, distance " << d;
        return;
    }
    ++st.overlapping;
    ASSERT_GT(n, 0) << "missed overlap";
    float depth = 0.0f;
    Vector normal = m.points[0].normal;
    for (int i = 0; i < n; ++i) {
        const ContactPoint& p = m.points[i];
        ASSERT_TRUE(p.pos.isFinite() && p.normal.isFinite() && std::isfinite(p.depth));
        ASSERT_NEAR(p.normal.length(), 1.0f, 1e-4f);
        ASSERT_GE(p.depth, 0.0f);
        ASSERT_NEAR(dot(p.normal, normal), 1.0f, 1e-4f) << "one normal per manifold";
        depth = std::fmax(depth, p.depth);
    }
    // Minimum translation: normal * (depth + eps) separates, a few % less does not.
    double after = refDistance(support(a), support(b, normal * (depth + eps)));
    ASSERT_GT(after, 0.25 * eps) << "normal*depth does not separate: depth " << depth;
    float less = depth * 0.97f - eps;
    if (less > 0.0f) {
        double before = refDistance(support(a), support(b, normal * less));
        ASSERT_LE(before, 1e-9) << "depth " << depth << " is more than the minimum translation";
    }
    // Contact points lie between the surfaces: within depth/2 (+ tolerance) of both shapes.
    for (int i = 0; i < n; ++i) {
        const ContactPoint& p = m.points[i];
        double tol = 0.5 * depth + 1e-3 * (1.0 + scale);
        ASSERT_LE(refDistance(point(p.pos), support(a)), tol);
        ASSERT_LE(refDistance(point(p.pos), support(b)), tol);
    }
}

void runRandom(ShapeKind ka, ShapeKind kb, unsigned seed, int count) {
    Rng rng(seed);
    Stats st;
    for (int i = 0; i < count; ++i) {
        Vector ca = rng.vec(1.0f);
        Vector cb = rng.pick(20) == 0 ? ca : ca + rng.vec(1.5f); // some coincident centres
        Matrix shared = rng.rotation();
        WorldShape a = randomShape(rng, ka, ca, &shared);
        WorldShape b = randomShape(rng, kb, cb, &shared);
        checkPair(a, b, st);
        if (::testing::Test::HasFatalFailure()) {
            ADD_FAILURE() << "pair " << i;
            return;
        }
    }
    std::printf("%d pairs: %d overlapping, %d separated, %d too close to call (skipped)\n", count,
                st.overlapping, st.separated, st.ambiguous);
    // The sample really covers both verdicts.
    EXPECT_GT(st.overlapping, count / 10);
    EXPECT_GT(st.separated, count / 10);
    EXPECT_LT(st.ambiguous, count / 20);
}

} // namespace

TEST(Narrowphase, RandomSphereSphereMatchesClosedForm) {
    Rng rng(11);
    for (int i = 0; i < kPairs; ++i) {
        WorldShape a = makeSphere(rng.vec(1.0f), rng.uni(0.05f, 1.0f));
        WorldShape b = makeSphere(rng.pick(20) == 0 ? a.sphere.centre : a.sphere.centre + rng.vec(1.5f),
                                  rng.uni(0.05f, 1.0f));
        double dist = (v3(b.sphere.centre) - v3(a.sphere.centre)).norm();
        double pen = double(a.sphere.radius) + b.sphere.radius - dist;
        ContactManifold m;
        int n = collideShapes(a, b, m);
        if (std::fabs(pen) < 1e-5) continue;
        ASSERT_EQ(n, pen > 0 ? 1 : 0) << i;
        if (n == 0) continue;
        ASSERT_NEAR(m.points[0].depth, pen, 1e-4);
        ASSERT_NEAR(m.points[0].normal.length(), 1.0f, 1e-5f);
        if (dist > 1e-3) {
            V3 dir = (v3(b.sphere.centre) - v3(a.sphere.centre)) / dist;
            ASSERT_GT(dir.dot(v3(m.points[0].normal)), 0.9999);
        }
    }
}

TEST(Narrowphase, RandomSphereSphereAgainstGjk) {
    runRandom(ShapeKind::Sphere, ShapeKind::Sphere, 12, kPairs / 5);
}
TEST(Narrowphase, RandomSphereBoxAgainstGjk) { runRandom(ShapeKind::Sphere, ShapeKind::Box, 21, kPairs); }
TEST(Narrowphase, RandomBoxSphereAgainstGjk) { runRandom(ShapeKind::Box, ShapeKind::Sphere, 22, kPairs / 5); }
TEST(Narrowphase, RandomBoxBoxAgainstGjk) { runRandom(ShapeKind::Box, ShapeKind::Box, 31, kPairs); }

TEST(Narrowphase, NearlyParallelFacesGiveAFaceManifoldNotAnEdgePoint) {
    // A domino (1 x 0.1 x 0.5 m) lying 2-4 mm into another, slid along and turned a little about the
    // vertical, tilted by at most 1 mm across its face: every corner over the other's face is inside it, so
    // the manifold holds the overlap area (3 or 4 points). An edge axis barely shallower than the face axis
    // gave a single point for some of these: the domino then stood on one point for a step, tipped and came
    // back, and 30 fallen dominoes never slept.
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> tilt(-0.001f, 0.001f), yaw(-0.1f, 0.1f), sink(0.002f, 0.004f),
        slideX(-0.3f, 0.3f), slideZ(-0.1f, 0.1f);
    const Vector half(0.5f, 0.05f, 0.25f);
    WorldShape lower = makeBox(Vector(0, 0, 0), Matrix(1), half);
    int fewer = 0;
    for (int i = 0; i < 2000; ++i) {
        Matrix r = rotatey(yaw(rng)) * rotatex(tilt(rng)) * rotatez(tilt(rng));
        WorldShape probe = makeBox(Vector(0, 0, 0), r, half);
        float lowest = 0; // the upper domino's lowest corner, relative to its centre
        for (int c = 0; c < 8; ++c) lowest = std::fmin(lowest, boxCorner(probe.box, c).y);
        WorldShape upper = makeBox(Vector(slideX(rng), half.y - lowest - sink(rng), slideZ(rng)), r, half);
        ContactManifold m;
        ASSERT_GT(collideShapes(lower, upper, m), 0) << i;
        if (m.count < 3) ++fewer;
    }
    EXPECT_EQ(fewer, 0) << "of 2000 resting dominoes had fewer than 3 points";
}

TEST(Narrowphase, CoincidentCentresAreFinite) {
    ContactManifold m;
    WorldShape s = makeSphere(Vector(1, 2, 3), 0.5f);
    ASSERT_EQ(collideShapes(s, s, m), 1);
    EXPECT_TRUE(m.points[0].normal.isFinite());
    EXPECT_NEAR(m.points[0].depth, 1.0f, 1e-6f);
    WorldShape b = makeBox(Vector(1, 2, 3), rotatey(0.3f), Vector(0.5f, 0.2f, 0.4f));
    ASSERT_EQ(collideShapes(s, b, m), 1);
    EXPECT_TRUE(m.points[0].normal.isFinite());
    EXPECT_NEAR(m.points[0].depth, 0.7f, 1e-5f); // leaves through the nearest (y) face
    ASSERT_GT(collideShapes(b, b, m), 0);
    for (int i = 0; i < m.count; ++i)
        EXPECT_TRUE(m.points[i].pos.isFinite() && m.points[i].normal.isFinite());
    EXPECT_NEAR(m.points[0].depth, 0.4f, 1e-5f);
}

TEST(Narrowphase, ParallelBoxesGiveAFourPointManifoldAtTheOverlap) {
    // A 2x2 plate resting 0.1 m into a bigger plate: four points, the corners of the overlap square.
    WorldShape lower = makeBox(Vector(0, 0, 0), Matrix(1), Vector(3, 0.5f, 3));
    WorldShape upper = makeBox(Vector(0.5f, 0.9f, 0), Matrix(1), Vector(1, 0.5f, 1));
    ContactManifold m;
    ASSERT_EQ(collideShapes(lower, upper, m), 4);
    Vector centre;
    for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(m.points[i].depth, 0.1f, 1e-5f);
        EXPECT_NEAR(m.points[i].normal.y, 1.0f, 1e-6f);
        EXPECT_NEAR(m.points[i].pos.y, 0.45f, 1e-5f); // midway between the surfaces
        centre += m.points[i].pos / 4.0f;
    }
    EXPECT_NEAR(centre.x, 0.5f, 1e-5f); // centre of the overlap area
    EXPECT_NEAR(centre.z, 0.0f, 1e-5f);
    // Feature ids are distinct within the manifold and stable under a small slide.
    unsigned ids[4];
    for (int i = 0; i < 4; ++i) ids[i] = m.points[i].feature;
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) EXPECT_NE(ids[i], ids[j]);
    WorldShape moved = upper;
    moved.box.centre += Vector(0.01f, 0, 0.01f);
    ContactManifold m2;
    ASSERT_EQ(collideShapes(lower, moved, m2), 4);
    for (int i = 0; i < 4; ++i) EXPECT_EQ(m2.points[i].feature, ids[i]);
}

TEST(Narrowphase, ParallelEdgesAndThinBoxesAreFinite) {
    WorldShape a = makeBox(Vector(0, 0, 0), rotatez(0.7853982f), Vector(0.5f, 0.5f, 2));
    WorldShape b = makeBox(Vector(0.7f, 0.7f, 0.3f), rotatez(0.7853982f), Vector(0.5f, 0.5f, 2));
    WorldShape thin = makeBox(Vector(0.2f, 0.45f, 0), rotatex(1e-4f), Vector(1, 1e-4f, 1));
    ContactManifold m;
    for (const WorldShape* s : {&b, &thin}) {
        int n = collideShapes(a, *s, m);
        ASSERT_GT(n, 0);
        for (int i = 0; i < n; ++i)
            EXPECT_TRUE(m.points[i].pos.isFinite() && m.points[i].normal.isFinite() &&
                        std::isfinite(m.points[i].depth));
    }
}

TEST(Narrowphase, PlaneAgainstEachShape) {
    WorldShape p;
    p.kind = ShapeKind::Plane;
    p.plane.normal = Vector(0, 1, 0);
    p.plane.offset = 1.0f;
    ContactManifold m;
    // Sphere just above: nothing; 0.1 m in: depth 0.1, normal up (plane -> sphere), pos midway.
    EXPECT_EQ(collideShapes(p, makeSphere(Vector(0, 1.6f, 0), 0.5f), m), 0);
    ASSERT_EQ(collideShapes(p, makeSphere(Vector(3, 1.4f, 0), 0.5f), m), 1);
    EXPECT_NEAR(m.points[0].depth, 0.1f, 1e-5f);
    EXPECT_NEAR(m.points[0].normal.y, 1.0f, 1e-6f);
    EXPECT_NEAR(m.points[0].pos.y, 0.95f, 1e-5f);
    // Entirely behind the plane still collides (one-sided, solid behind).
    ASSERT_EQ(collideShapes(p, makeSphere(Vector(0, -5, 0), 0.5f), m), 1);
    EXPECT_NEAR(m.points[0].depth, 6.5f, 1e-4f);
    // Flipped order: the normal points at the plane.
    ASSERT_EQ(collideShapes(makeSphere(Vector(3, 1.4f, 0), 0.5f), p, m), 1);
    EXPECT_NEAR(m.points[0].normal.y, -1.0f, 1e-6f);
    // A box resting flat: 4 points at depth 0.05; tilted: the lowest corner.
    ASSERT_EQ(collideShapes(p, makeBox(Vector(0, 1.45f, 0), Matrix(1), Vector(0.5f, 0.5f, 0.5f)), m), 4);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(m.points[i].depth, 0.05f, 1e-5f);
    WorldShape tilted = makeBox(Vector(0, 1.6f, 0), rotatez(0.6f) * rotatex(0.5f), Vector(0.5f, 0.5f, 0.5f));
    int n = collideShapes(p, tilted, m);
    ASSERT_GT(n, 0);
    float lowest = 1e9f;
    for (int i = 0; i < 8; ++i) lowest = std::fmin(lowest, boxCorner(tilted.box, i).y);
    float deepest = 0;
    for (int i = 0; i < n; ++i) deepest = std::fmax(deepest, m.points[i].depth);
    EXPECT_NEAR(deepest, 1.0f - lowest, 1e-5f);
    // Two planes never collide.
    EXPECT_EQ(collideShapes(p, p, m), 0);
}

TEST(Narrowphase, RayCastsMatchAnalyticIntersections) {
    Rng rng(5);
    float t;
    Vector n;
    for (int i = 0; i < 2000; ++i) {
        // Sphere: |o + t d - c| = r solved in double.
        WorldShape s = makeSphere(rng.vec(2), rng.uni(0.1f, 1.5f));
        Vector o = rng.vec(5), d = rng.vec(1).normalize();
        if (d.lengthSquared() == 0) continue;
        V3 oc = v3(o) - v3(s.sphere.centre), dd = v3(d);
        double b = oc.dot(dd), c = oc.squaredNorm() - double(s.sphere.radius) * s.sphere.radius;
        double disc = b * b - c;
        bool expectHit = c <= 0 || (b < 0 && disc >= 0);
        bool hit = rayShape(s, o, d, 100.0f, t, n);
        if (std::fabs(disc) < 1e-4 || std::fabs(c) < 1e-4) continue;
        ASSERT_EQ(hit, expectHit) << i;
        if (hit && c > 0) {
            ASSERT_NEAR(t, -b - std::sqrt(disc), 1e-3);
            ASSERT_NEAR(dot(n, (o + d * t - s.sphere.centre).normalize()), 1.0f, 1e-3f);
        }
        // Box: the entry point found by a dense march in double must agree with the slab result.
        WorldShape bx =
            makeBox(rng.vec(2), rng.rotation(), Vector(rng.uni(0.1f, 1), rng.uni(0.1f, 1), rng.uni(0.1f, 1)));
        bool bhit = rayShape(bx, o, d, 100.0f, t, n);
        Vector cl;
        if (bhit) {
            Vector p = o + d * t;
            float sd = pointShapeDistance(bx, p, cl);
            if (t == 0.0f) {
                ASSERT_LE(sd, 1e-4f) << "a ray starting inside hits at its origin";
            }
            if (t > 0) {
                ASSERT_LE(std::fabs(sd), 1e-3f) << "hit point on the surface";
                ASSERT_LT(dot(n, d), 0.0f);
                ASSERT_GT(pointShapeDistance(bx, o + d * (t * 0.99f - 1e-3f), cl), 0.0f) << "first hit";
            }
        } else {
            // No hit: the ray stays outside (sampled along its length).
            for (int k = 0; k <= 2000; ++k)
                ASSERT_GT(pointShapeDistance(bx, o + d * (0.05f * k), cl), -1e-3f);
        }
    }
    // Plane: exact.
    WorldShape p;
    p.kind = ShapeKind::Plane;
    p.plane.normal = Vector(0, 1, 0);
    p.plane.offset = -1.0f;
    ASSERT_TRUE(rayShape(p, Vector(0, 3, 0), Vector(0, -1, 0), 10, t, n));
    EXPECT_NEAR(t, 4.0f, 1e-6f);
    EXPECT_FALSE(rayShape(p, Vector(0, 3, 0), Vector(0, 1, 0), 10, t, n));
    EXPECT_FALSE(rayShape(p, Vector(0, 3, 0), Vector(0, -1, 0), 3, t, n));
}

TEST(Narrowphase, SweptSphereFindsFirstTouch) {
    WorldShape box = makeBox(Vector(0, 0, 0), Matrix(1), Vector(0.5f, 0.5f, 0.5f));
    float t;
    ASSERT_TRUE(sweepSphere(box, Vector(-10, 0, 0), Vector(10, 0, 0), 0.05f, t));
    EXPECT_NEAR(-10 + 20 * t, -0.55f, 1e-4f);
    // Passing beside the box's corner region: the rounded corner decides.
    EXPECT_FALSE(sweepSphere(box, Vector(-10, 0.56f, 0.56f), Vector(10, 0.56f, 0.56f), 0.05f, t));
    ASSERT_TRUE(sweepSphere(box, Vector(-10, 0.53f, 0.53f), Vector(10, 0.53f, 0.53f), 0.05f, t));
    EXPECT_NEAR(-10 + 20 * t, -0.5f - std::sqrt(0.05f * 0.05f - 2 * 0.03f * 0.03f), 1e-3f);
}
