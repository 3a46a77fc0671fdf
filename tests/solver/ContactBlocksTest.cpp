// ContactBlocksTest.cpp - the packing of manifolds into four-lane blocks (ContactBlocks.h), against what
// makes the wide sweep the sequential one: no block holds a movable body twice, and every movable body meets
// its manifolds in their order; and the lanes fill when nothing stands in the way.
#include "ContactBlocks.h"
#include "SolverRows.h"

#include <gtest/gtest.h>

#include <algorithm>
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
