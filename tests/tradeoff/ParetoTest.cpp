// ParetoTest.cpp - bench_tradeoff's Pareto front (Pareto.h) equals the brute-force definition: a point is
// on the front when no other point dominates it (at least as cheap and as accurate, better in one).
#include "Pareto.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

using tradeoff::CostError;

namespace {

std::vector<size_t> bruteForce(const std::vector<CostError>& p) {
    std::vector<size_t> front;
    for (size_t i = 0; i < p.size(); ++i) {
        bool dominated = false;
        for (size_t j = 0; j < p.size() && !dominated; ++j) {
            dominated = p[j].cost <= p[i].cost && p[j].error <= p[i].error &&
                        (p[j].cost < p[i].cost || p[j].error < p[i].error);
        }
        if (!dominated) front.push_back(i);
    }
    return front;
}

std::vector<size_t> sorted(std::vector<size_t> v) {
    std::sort(v.begin(), v.end());
    return v;
}

} // namespace

TEST(TradeoffPareto, HandExample) {
    // (1, 5) (2, 3) (3, 4) (4, 1) (2, 6): (3, 4) is beaten by (2, 3), (2, 6) by (1, 5) and (2, 3).
    const std::vector<CostError> p = {{1, 5}, {2, 3}, {3, 4}, {4, 1}, {2, 6}};
    EXPECT_EQ(tradeoff::paretoFront(p), (std::vector<size_t>{0, 1, 3})); // by increasing cost
}

TEST(TradeoffPareto, TiesAndDuplicates) {
    // Two identical points both stay; a point as accurate but dearer goes; a point as cheap but less
    // accurate goes.
    const std::vector<CostError> p = {{1, 2}, {1, 2}, {3, 2}, {1, 3}, {0.5, 10}};
    EXPECT_EQ(sorted(tradeoff::paretoFront(p)), (std::vector<size_t>{0, 1, 4}));
    EXPECT_TRUE(tradeoff::paretoFront({}).empty());
}

TEST(TradeoffPareto, MatchesBruteForceOnRandomSets) {
    std::mt19937 rng(14);
    for (int trial = 0; trial < 500; ++trial) {
        std::uniform_int_distribution<int> size(1, 40), coarse(0, 6); // a coarse grid forces ties
        std::uniform_real_distribution<double> fine(0.0, 1.0);
        const int n = size(rng);
        const bool ties = trial % 2 == 0;
        std::vector<CostError> p;
        for (int i = 0; i < n; ++i) {
            const double c = ties ? coarse(rng) : fine(rng);
            const double e = ties ? coarse(rng) : fine(rng);
            p.push_back({c, e});
        }
        ASSERT_EQ(sorted(tradeoff::paretoFront(p)), bruteForce(p)) << "trial " << trial;
    }
}
