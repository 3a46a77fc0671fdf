// CandidatePairsTest.cpp - the candidate-pair stage alone (SimpleCollisionSpace::findCandidatePairs, what
// bench_compare times beside Bullet's and ODE's broadphases) finds exactly the pairs whose world boxes
// overlap, counted by brute force from the bodies' poses, in both spaces: on the first call, again with
// nothing moved (the tree's kept pairs), and after half the bodies moved.
#include "MathEigen.h"
#include "SimpleCollisionSpace.h"
#include "UserBody.h"
#include "iCOBB.h"
#include "iCSphere.h"
#include "iOctreeCollisionSpace.h"
#include "iSimpleCollisionSpace.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <vector>

namespace {

struct Body {
    std::unique_ptr<UserBody> body;
    Eigen::Vector3d half; // a sphere's radius in every entry, or a box's half extents
    bool sphere;
};

// The world box of each body, from its pose: centre +- |R| h (a box), centre +- r (a sphere).
Eigen::AlignedBox3d worldBox(const Body& b) {
    const RBDynamics& d = b.body->getDynamics();
    const Vector o = d.position;
    const Eigen::Vector3d c(o.x, o.y, o.z);
    Eigen::Vector3d e = b.half;
    if (!b.sphere) {
        Eigen::Matrix3d r; // Guardian's rows are the box's axes in world coordinates
        for (int i = 0; i < 3; ++i) {
            const Vector axis = d.orientation.direction(char('x' + i));
            r.col(i) = Eigen::Vector3d(axis.x, axis.y, axis.z);
        }
        e = r.cwiseAbs() * b.half;
    }
    return Eigen::AlignedBox3d(c - e, c + e);
}

// Pairs whose boxes overlap by more than 1e-4 m on every axis (certain) and those within 1e-4 m of
// touching on some axis (float rounding may go either way).
void bruteForce(const std::vector<Body>& bodies, size_t& certain, size_t& borderline) {
    certain = borderline = 0;
    for (size_t i = 0; i < bodies.size(); ++i)
        for (size_t j = i + 1; j < bodies.size(); ++j) {
            const Eigen::AlignedBox3d a = worldBox(bodies[i]), b = worldBox(bodies[j]);
            const Eigen::Vector3d gap = (a.min() - b.max()).cwiseMax(b.min() - a.max());
            if (gap.maxCoeff() < -1e-4)
                ++certain;
            else if (gap.maxCoeff() <= 1e-4)
                ++borderline;
        }
}

void expectBruteForcePairs(iCollisionSpace* (*make)()) {
    std::mt19937 rng(29);
    auto uni = [&](float a, float b) { return std::uniform_real_distribution<float>(a, b)(rng); };
    iCollisionSpace* space = make();
    auto* candidates = dynamic_cast<SimpleCollisionSpace*>(space);
    ASSERT_NE(candidates, nullptr);
    std::vector<Body> bodies;
    std::vector<iCollisionGeometry*> geoms;
    for (int i = 0; i < 400; ++i) {
        Body b;
        b.body = std::make_unique<UserBody>(Vector(uni(-8, 8), uni(-8, 8), uni(-8, 8)), PHYS_Falling);
        Eigen::Quaternionf q(uni(-1, 1), uni(-1, 1), uni(-1, 1), uni(-1, 1));
        q.normalize();
        b.body->getDynamics().orientation = gmath::fromBlock3(q.toRotationMatrix());
        b.sphere = i % 3 == 0;
        if (b.sphere) {
            const float r = uni(0.2f, 1.2f);
            b.half = Eigen::Vector3d::Constant(r);
            geoms.push_back(CreateCSphere(b.body.get(), r));
        } else {
            const Vector h(uni(0.2f, 1.2f), uni(0.2f, 1.2f), uni(0.2f, 1.2f));
            b.half = Eigen::Vector3d(h.x, h.y, h.z);
            geoms.push_back(CreateCOBB(b.body.get(), h));
        }
        ASSERT_NE(geoms.back(), nullptr);
        if (geoms.back()->getSpace() != space) space->add(geoms.back());
        bodies.push_back(std::move(b));
    }
    size_t certain = 0, borderline = 0;
    bruteForce(bodies, certain, borderline);
    ASSERT_GT(certain, 100u); // a scene with something to find
    size_t found = candidates->findCandidatePairs();
    EXPECT_GE(found, certain);
    EXPECT_LE(found, certain + borderline);
    EXPECT_EQ(candidates->findCandidatePairs(), found) << "nothing moved";
    for (size_t i = 0; i < bodies.size(); i += 2) // half the bodies move, some far
        bodies[i].body->getDynamics().position += Vector(uni(-0.3f, 0.3f), uni(-0.3f, 0.3f), uni(-3, 3));
    bruteForce(bodies, certain, borderline);
    found = candidates->findCandidatePairs();
    EXPECT_GE(found, certain);
    EXPECT_LE(found, certain + borderline);
    for (iCollisionGeometry* g : geoms) g->Delete();
    space->Delete();
}

} // namespace

TEST(CandidatePairs, SortAndSweepFindsTheBruteForceBoxOverlaps) {
    expectBruteForcePairs([] { return CreateSimpleCollisionSpace(); });
}
TEST(CandidatePairs, TreeFindsTheBruteForceBoxOverlapsAndKeepsThem) {
    expectBruteForcePairs([] { return CreateOctreeCollisionSpace(); });
}
