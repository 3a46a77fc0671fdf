// DynamicTreeTest.cpp - the dynamic AABB tree against brute force: random inserts, moves, removes and bulk
// rebuilds with a fixed seed, where every box and ray query must find exactly the leaves a loop over all
// boxes finds, the tree stays valid, and its height stays within 2.5 log2 n + 4 after 10,000 random moves.
#include "DynamicTree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using gcol::Aabb;
using gcol::DynamicTree;

namespace {

struct Model {
    std::mt19937 gen{7};
    float uni(float a, float b) { return std::uniform_real_distribution<float>(a, b)(gen); }
    Aabb randomBox(float extent) {
        Vector c(uni(-extent, extent), uni(-extent, extent), uni(-extent, extent));
        Vector h(uni(0.05f, 2.0f), uni(0.05f, 2.0f), uni(0.05f, 2.0f));
        return Aabb{c - h, c + h};
    }
};

std::vector<int> sorted(std::vector<int> v) {
    std::sort(v.begin(), v.end());
    return v;
}

} // namespace

TEST(DynamicTree, QueriesEqualBruteForceUnderRandomEdits) {
    Model m;
    DynamicTree tree;
    std::vector<int> leafOf; // value -> leaf (-1: removed)
    std::vector<Aabb> boxOf; // value -> box
    for (int round = 0; round < 4000; ++round) {
        const int op = std::uniform_int_distribution<int>(0, 9)(m.gen);
        if (op < 4 || leafOf.empty()) {
            boxOf.push_back(m.randomBox(40.0f));
            leafOf.push_back(tree.insert(boxOf.back(), int(boxOf.size()) - 1));
        } else {
            const int v = std::uniform_int_distribution<int>(0, int(leafOf.size()) - 1)(m.gen);
            if (leafOf[size_t(v)] < 0) continue;
            if (op < 8) {
                boxOf[size_t(v)] = m.randomBox(40.0f);
                tree.move(leafOf[size_t(v)], boxOf[size_t(v)]);
                EXPECT_EQ(tree.value(leafOf[size_t(v)]), v);
            } else {
                tree.remove(leafOf[size_t(v)]);
                leafOf[size_t(v)] = -1;
            }
        }
        if (round % 500 == 250) { // the bulk path: some boxes changed in place, then one rebuild
            std::vector<int> order;
            for (size_t v = 0; v < leafOf.size(); ++v) {
                if (leafOf[v] < 0) continue;
                if (v % 3 == 0) {
                    boxOf[v] = m.randomBox(40.0f);
                    tree.setLeafBox(leafOf[v], boxOf[v]);
                }
                order.push_back(leafOf[v]);
            }
            tree.rebuild(order);
            EXPECT_LE(float(tree.height()), std::ceil(std::log2(float(order.size()))));
        }
        if (round % 50 != 0) continue;
        ASSERT_TRUE(tree.valid()) << "round " << round;
        const Aabb q = m.randomBox(40.0f);
        const Vector origin(m.uni(-40, 40), m.uni(-40, 40), m.uni(-40, 40));
        const Vector dir(m.uni(-1, 1), m.uni(-1, 1), round % 100 == 0 ? 0.0f : m.uni(-1, 1));
        const float maxT = m.uni(1.0f, 60.0f);
        std::vector<int> found, rayFound, expected, rayExpected;
        tree.query(q, [&](int v) { found.push_back(v); });
        tree.rayCast(origin, dir, maxT, [&](int v) { rayFound.push_back(v); });
        for (size_t v = 0; v < leafOf.size(); ++v) {
            if (leafOf[v] < 0) continue;
            if (gcol::overlaps(boxOf[v], q)) expected.push_back(int(v));
            if (gcol::rayHitsBox(boxOf[v], origin, dir, maxT)) rayExpected.push_back(int(v));
        }
        EXPECT_EQ(sorted(found), expected) << "round " << round;
        EXPECT_EQ(sorted(rayFound), rayExpected) << "round " << round;
    }
}

TEST(DynamicTree, RayHitsBoxAgreesWithSampling) {
    Model m;
    for (int i = 0; i < 2000; ++i) {
        const Aabb b = m.randomBox(5.0f);
        const Vector o(m.uni(-8, 8), m.uni(-8, 8), m.uni(-8, 8)), d(m.uni(-1, 1), m.uni(-1, 1), m.uni(-1, 1));
        bool sampled = false;
        for (int k = 0; k <= 4000 && !sampled; ++k) {
            Vector p = o + d * (10.0f * float(k) / 4000.0f);
            sampled = gcol::contains(b, Aabb{p, p});
        }
        if (sampled) { // sampling can only miss a graze
            EXPECT_TRUE(gcol::rayHitsBox(b, o, d, 10.0f)) << i;
        }
    }
}

TEST(DynamicTree, HeightStaysLogarithmicAfter10000RandomMoves) {
    for (int n : {1000, 10000}) {
        Model m;
        DynamicTree tree;
        std::vector<int> leaves;
        // Inserted in sorted order along x: the worst order for a tree that does not rebalance.
        for (int i = 0; i < n; ++i) {
            Vector c(float(i) * 0.5f, 0.0f, 0.0f), h(0.5f, 0.5f, 0.5f);
            leaves.push_back(tree.insert(Aabb{c - h, c + h}, i));
        }
        const float bound = 2.5f * std::log2(float(n)) + 4.0f;
        EXPECT_LE(float(tree.height()), bound) << n << " sorted inserts";
        for (int k = 0; k < 10000; ++k)
            tree.move(leaves[size_t(std::uniform_int_distribution<int>(0, n - 1)(m.gen))],
                      m.randomBox(100.0f));
        ASSERT_TRUE(tree.valid());
        EXPECT_EQ(tree.leafCount(), n);
        EXPECT_LE(float(tree.height()), bound) << n << " after moves";
        RecordProperty("height_" + std::to_string(n), tree.height());
    }
}
