// DeepChainTest.cpp - a 1,000-deep attachment chain is one rigid body: it falls and spins as one (its
// composite centre of mass follows the projectile law of the integrator, every link keeps its pose relative
// to the others), and an update of it costs linear time (chain_bench measures that; WorldPoseCache.cpp).
#include "PhysicsTestSupport.h"
#include "iPhysicsSceneStats.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using physics_test::SceneHolder;

namespace {

constexpr int kDepth = 1000;

// Distance and relative rotation angle of link i+1 seen from link i, from world poses alone.
struct Relative {
    float distance;
    Matrix rotation; // R_(i+1) R_i^T (row vectors): constant while the chain is rigid
};

std::vector<Relative> relativePoses(const std::vector<iRigidBody*>& links) {
    std::vector<Relative> out;
    for (size_t i = 0; i + 1 < links.size(); ++i) {
        const RBDynamics& a = links[i]->getDynamics();
        const RBDynamics& b = links[i + 1]->getDynamics();
        out.push_back({(b.getWorldPosition() - a.getWorldPosition()).length(),
                       b.getWorldOrientation() * a.getWorldOrientation().transpose()});
    }
    return out;
}

} // namespace

TEST(DeepChain, AThousandLinksFallAndSpinAsOneBody) {
    SceneHolder h(60);
    std::vector<iRigidBody*> links;
    RBDynamics* parent = nullptr;
    for (int i = 0; i < kDepth; ++i) {
        iRigidBody* b = CreateRigidBody(nullptr);
        RBDynamics& d = b->getDynamics();
        d.mass = 1.0f + float(i % 3); // uneven: the centre of mass is not the middle link
        d.position = Vector(0.05f * float(i), 0.02f * float(i % 7), 0.0f);
        d.orientation.rotatez(0.001f * float(i));
        d.attachTo(parent);
        parent = &d;
        links.push_back(b);
    }
    RBDynamics& root = links[0]->getDynamics();
    root.velocity = Vector(2.0f, 5.0f, 0.0f);
    root.angularVelocity = Vector(0.0f, 0.0f, 0.5f);

    // Truth from the API's own mass properties, computed before any step: the centre C0 and its velocity.
    const RBDynamics::MassProperties mp0 = root.getCompositeMassProperties();
    const Vector c0 = mp0.centre;
    const Vector vc0 = root.getVelocityAtWorldPoint(c0);
    const std::vector<Relative> rel0 = relativePoses(links);

    settingsOf(h.scene)->setMaxStepsPerUpdate(60);
    h.run(1000, 1000); // one update: 60 steps of 1/60 s
    const int n = int(statsOf(h.scene)->getStepCount());
    ASSERT_EQ(n, 60);

    // Semi-implicit Euler on the composite's centre: v_k = v0 + g k dt, x_n = x0 + v0 n dt + g dt^2 n(n+1)/2.
    const double dt = 1.0 / 60.0, g = -9.81;
    const Vector c = root.getCompositeMassProperties().centre;
    EXPECT_NEAR(c.x, c0.x + vc0.x * n * dt, 2e-3);
    EXPECT_NEAR(c.y, c0.y + vc0.y * n * dt + g * dt * dt * n * (n + 1) / 2, 2e-3);
    EXPECT_NEAR(c.z, c0.z, 1e-4);

    // Rigid: every link where it was relative to its neighbour (distances and relative rotations).
    const std::vector<Relative> rel = relativePoses(links);
    for (size_t i = 0; i < rel.size(); ++i) {
        ASSERT_NEAR(rel[i].distance, rel0[i].distance, 1e-3f) << "link " << i;
        for (int k = 0; k < 16; ++k)
            ASSERT_NEAR(rel[i].rotation.data()[k], rel0[i].rotation.data()[k], 1e-3f);
    }
    // And it turned as one: the root (which started unrotated) turned by w t about z (torque-free spin about
    // the principal z axis of a planar chain keeps w).
    const Matrix r = root.getWorldOrientation();
    EXPECT_NEAR(std::acos(r.m11), 0.5 * n * dt, 1e-3);
    EXPECT_NEAR(r.m33, 1.0f, 1e-5f);
}
