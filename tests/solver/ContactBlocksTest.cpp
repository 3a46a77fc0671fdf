// ContactBlocksTest.cpp - the packing of manifolds into four-lane blocks (ContactBlocks.h), against what
// makes the wide sweep the sequential one: no block holds a movable body twice, and every movable body meets
// its manifolds in their order; and the lanes fill when nothing stands in the way.
#include "ContactBlocks.h"
#include "SolverRows.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <vector>

using physics::ContactBlocks;
using physics::kLanes;
using physics::Manifold;
using physics::SolverBody;

namespace {

RBDynamics g_root; // any non-null root: a body with a root and an inverse mass is movable

std::vector<SolverBody> makeBodies(int movable, int immovable) {
    std::vector<SolverBody> bodies(size_t(movable + immovable));
    for (int i = 0; i < movable; ++i) {
        bodies[size_t(i)].root = &g_root;
        bodies[size_t(i)].invMass = 1.0f;
    }
    return bodies; // the rest: no root or no inverse mass, like the static world and fixed bodies
}

Manifold manifold(int a, int b) {
    Manifold m;
    m.a = a;
    m.b = b;
    m.count = 1;
    return m;
}

// Checks the two rules for a packing, and that each manifold is where it says it is.
void expectSequentialOrder(const std::vector<Manifold>& manifolds, const std::vector<SolverBody>& bodies,
                           size_t blockCount) {
    std::map<int, int> lastBlock;                // movable body -> block of its last manifold so far
    std::map<int, std::set<int>> movableInBlock; // block -> its movable bodies
    std::set<std::pair<int, int>> usedLanes;
    for (size_t k = 0; k < manifolds.size(); ++k) {
        const Manifold& m = manifolds[k];
        ASSERT_GE(m.block, 0);
        ASSERT_LT(size_t(m.block), blockCount);
        ASSERT_GE(m.lane, 0);
        ASSERT_LT(m.lane, kLanes);
        EXPECT_TRUE(usedLanes.insert({m.block, m.lane}).second) << "two manifolds in one lane";
        for (int body : {m.a, m.b}) {
            if (!physics::movable(bodies[size_t(body)])) continue;
            EXPECT_TRUE(movableInBlock[m.block].insert(body).second)
                << "block " << m.block << " holds body " << body << " twice";
            auto it = lastBlock.find(body);
            if (it != lastBlock.end()) {
                EXPECT_LT(it->second, m.block)
                    << "body " << body << " meets manifold " << k << " out of order";
            }
            lastBlock[body] = m.block;
        }
    }
}

} // namespace

TEST(ContactBlocks, ARandomContactGraphIsPackedInEachBodysOrder) {
    std::mt19937 rng(12345);
    for (int trial = 0; trial < 50; ++trial) {
        const int movable = 2 + int(rng() % 60), immovable = 1 + int(rng() % 3);
        std::vector<SolverBody> bodies = makeBodies(movable, immovable);
        std::vector<Manifold> manifolds;
        const int count = 1 + int(rng() % 300);
        for (int k = 0; k < count; ++k) {
            const int a = int(rng() % unsigned(movable + immovable));
            int b = int(rng() % unsigned(movable + immovable));
            if (b == a) b = (a + 1) % movable; // two different bodies, at least one movable
            manifolds.push_back(manifold(a, b));
        }
        ContactBlocks blocks;
        blocks.pack(manifolds, bodies);
        expectSequentialOrder(manifolds, bodies, blocks.blockCount());
        if (HasFailure()) {
            ADD_FAILURE() << "trial " << trial;
            return;
        }
    }
}

TEST(ContactBlocks, ManifoldsSharingNoMovableBodyFillEveryLane) {
    // 40 boxes on the ground (one immovable body): 40 manifolds that share only the ground fill 10 blocks.
    std::vector<SolverBody> bodies = makeBodies(40, 1);
    std::vector<Manifold> manifolds;
    for (int i = 0; i < 40; ++i) manifolds.push_back(manifold(40, i));
    ContactBlocks blocks;
    blocks.pack(manifolds, bodies);
    EXPECT_EQ(blocks.blockCount(), 40u / kLanes);
    expectSequentialOrder(manifolds, bodies, blocks.blockCount());
}

TEST(ContactBlocks, AChainKeepsItsOrderOneLaneABlock) {
    // A tower: each manifold shares a body with the one before, so each must come after it.
    std::vector<SolverBody> bodies = makeBodies(10, 1);
    std::vector<Manifold> manifolds{manifold(10, 0)};
    for (int i = 0; i + 1 < 10; ++i) manifolds.push_back(manifold(i, i + 1));
    ContactBlocks blocks;
    blocks.pack(manifolds, bodies);
    EXPECT_EQ(blocks.blockCount(), manifolds.size());
    expectSequentialOrder(manifolds, bodies, blocks.blockCount());
}

// The normal rows are solved in their speeds (ContactBlocks::solve), through each block's coupling: how much
// a unit impulse along one point's normal changes another's normal speed. Checked against its definition:
// the impulse applied to the two bodies (v += p n / m, w += I^-1 (r x n) p, the opposite on body a) and the
// other point's relative normal speed n . (v_b + w_b x r_b - v_a - w_a x r_a) measured before and after, for
// random bodies (masses 0.1-10 kg, turned inertias, some manifolds on the static world) and points.
TEST(ContactBlocks, TheCouplingIsTheSpeedAnImpulseMakesAtEachPoint) {
    std::mt19937 rng(777);
    std::uniform_real_distribution<float> unit(-1, 1), mass(0.1f, 10.0f), moment(0.05f, 5.0f);
    const int movable = 12;
    std::vector<SolverBody> bodies = makeBodies(movable, 1); // the last: the static world
    for (int i = 0; i < movable; ++i) {
        SolverBody& b = bodies[size_t(i)];
        b.invMass = 1.0f / mass(rng);
        const physics::Quat turn =
            physics::Quat(1 + unit(rng), unit(rng), unit(rng), unit(rng)).normalized(); // any rotation
        const physics::Mat3 r = turn.toRotationMatrix();
        const physics::Vec3 inverseMoments(1 / moment(rng), 1 / moment(rng), 1 / moment(rng));
        b.invInertia = r * inverseMoments.asDiagonal() * r.transpose();
        b.com = physics::Vec3(unit(rng), unit(rng), unit(rng)) * physics::Real(3);
    }
    std::vector<Manifold> manifolds;
    for (int k = 0; k < 8; ++k) {
        // Pairs of different bodies (some lanes share a block), every fourth on the static world.
        Manifold m = manifold(k % 4 == 3 ? movable : int(rng() % movable), int(rng() % movable));
        if (m.a == m.b) m.b = (m.b + 1) % movable;
        m.count = 1 + k % 4;
        for (int i = 0; i < m.count; ++i) {
            physics::ManifoldPoint& p = m.points[i];
            p.normal = physics::Vec3(unit(rng), unit(rng), unit(rng)).normalized();
            p.point = physics::Vec3(unit(rng), unit(rng), unit(rng)) * physics::Real(3);
        }
        manifolds.push_back(m);
    }
    ContactBlocks blocks;
    blocks.pack(manifolds, bodies);
    blocks.prepare(manifolds, bodies, 1.0f / 240);
    for (const Manifold& m : manifolds) {
        const SolverBody &a = bodies[size_t(m.a)], &b = bodies[size_t(m.b)];
        auto speedChange = [&](int i, int j) { // at point i, of a unit impulse along point j's normal
            const physics::ManifoldPoint &pi = m.points[i], &pj = m.points[j];
            const physics::Vec3 ra = pj.point - a.com, rb = pj.point - b.com;
            const physics::Vec3 va = -a.invMass * pj.normal, wa = -(a.invInertia * ra.cross(pj.normal));
            const physics::Vec3 vb = b.invMass * pj.normal, wb = b.invInertia * rb.cross(pj.normal);
            const physics::Vec3 at = pi.point;
            return double(pi.normal.dot((vb + wb.cross(at - b.com)) - (va + wa.cross(at - a.com))));
        };
        for (int i = 0; i < m.count; ++i)
            for (int j = 0; j < m.count; ++j) {
                const double expected = speedChange(i, j);
                EXPECT_NEAR(blocks.coupling(m, i, j), expected, 1e-5 * (1 + std::fabs(expected)))
                    << "manifold " << m.a << "-" << m.b << ", points " << i << ", " << j;
            }
    }
}
