// ContactOrderTest.cpp - the contact solver's result does not depend on the order a space lists its contacts
// in: a pair's contacts apart in the list still make one manifold, and each manifold finds last step's
// impulses whatever order the pairs come in (ContactManifolds.cpp looks where the last one found ends first,
// then in a table). Two boxes on a fixed floor touch nothing else, so their manifolds commute exactly: every
// order gives the reference order's bits.
#include "SolverFixtures.h"

#include "MathDefinitions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace solver_test;
using physics::ContactSolver;
using physics::SolverBodyAccess;

namespace order_test { // named: the test programs are unity builds

const float kG = 9.81f, kDt = 1.0f / 60.0f;

// Two unit boxes on a fixed floor, sliding and spinning apart from each other.
struct Scene {
    Body floor, left, right;
    Geometry gFloor{&floor}, gLeft{&left}, gRight{&right};
    Scene() {
        floor.d.physicsType = PHYS_FixedInSpace;
        for (Body* b : {&left, &right}) {
            b->d.mass = 2.0f;
            b->d.setInertiaTensor(getBoxInertiaTensor(2.0f, Vector(0.5f, 0.5f, 0.5f)));
        }
        left.d.position = Vector(-2, 0.5f, 0);
        right.d.position = Vector(2, 0.5f, 0);
        left.d.velocity = Vector(1.5f, 0, 0.5f);
        right.d.velocity = Vector(-1, 0, 0.8f);
        left.d.angularVelocity = Vector(0, 2, 0);
        right.d.angularVelocity = Vector(0, -1, 0);
    }
    // The four corners under a box, 1 mm deep, at its current position.
    std::vector<CollisionContact> corners(Geometry& g, Body& b) {
        std::vector<CollisionContact> out;
        for (float x : {-0.5f, 0.5f})
            for (float z : {-0.5f, 0.5f})
                out.push_back(
                    contact(gFloor, g, b.d.position + Vector(x, -0.5005f, z), Vector(0, 1, 0), 0.001f));
        return out;
    }
};

using Contacts = std::vector<CollisionContact>;

struct Outcome {
    std::vector<float> state; // both boxes' position, velocity and angular velocity
    size_t manifolds = 0;     // after the last step
};

// Twenty steps under gravity, listing each step's contacts as order(step, left's, right's) gives them.
template <class Order> Outcome run(Order order, bool warmStart = true) {
    Scene s;
    ContactSolver solver;
    physics::SolverSettings settings;
    settings.warmStart = warmStart;
    solver.setSettings(settings);
    for (int step = 0; step < 20; ++step) {
        for (Body* b : {&s.left, &s.right}) b->d.velocity += Vector(0, -kG * kDt, 0);
        const Contacts list = order(step, s.corners(s.gLeft, s.left), s.corners(s.gRight, s.right));
        solver.solve(list.data(), list.size(), kDt, SolverBodyAccess(physics::Vec3(0, -kG * kDt, 0)));
    }
    Outcome out;
    for (Body* b : {&s.left, &s.right})
        for (const Vector& v : {b->d.position, b->d.velocity, b->d.angularVelocity})
            out.state.insert(out.state.end(), {v.x, v.y, v.z});
    out.manifolds = solver.manifolds().size();
    return out;
}

Contacts inTurn(const Contacts& first, const Contacts& second) {
    Contacts out = first;
    out.insert(out.end(), second.begin(), second.end());
    return out;
}

Contacts interleaved(const Contacts& first, const Contacts& second) {
    Contacts out;
    for (size_t i = 0; i < first.size(); ++i) out.insert(out.end(), {first[i], second[i]});
    return out;
}

} // namespace order_test

using namespace order_test;

TEST(ContactOrder, APairsContactsAndLastStepsImpulsesAreFoundInAnyListingOrder) {
    const Outcome reference = run([](int, const Contacts& l, const Contacts& r) { return inTurn(l, r); });
    ASSERT_EQ(reference.manifolds, 2u);
    // The pairs change places every other step (last step's manifold is not where the last one found ends).
    const Outcome swapping = run([](int step, const Contacts& l, const Contacts& r) {
        return step % 2 ? inTurn(r, l) : inTurn(l, r);
    });
    // Each pair's contacts apart in the list (one manifold each all the same).
    const Outcome apart = run([](int, const Contacts& l, const Contacts& r) { return interleaved(l, r); });
    // Both.
    const Outcome both = run([](int step, const Contacts& l, const Contacts& r) {
        return step % 2 ? interleaved(r, l) : interleaved(l, r);
    });
    for (const Outcome* o : {&swapping, &apart, &both}) {
        EXPECT_EQ(o->manifolds, 2u);
        EXPECT_EQ(o->state, reference.state);
    }
    // The warm start counts here (friction and the load carried from step to step): without it the boxes end
    // elsewhere, so an order that lost last step's impulses could not pass as the reference.
    const Outcome cold = run([](int, const Contacts& l, const Contacts& r) { return inTurn(l, r); }, false);
    EXPECT_NE(cold.state, reference.state);
    // And the boxes slid: friction acted on both (each started at over 1 m/s).
    EXPECT_LT(std::abs(reference.state[3]), 1.5f);
    EXPECT_LT(std::abs(reference.state[12]), 1.0f);
}
