// Pareto.h - which settings are worth having: the Pareto front of (cost, error) points, both minimised.
// A point is on the front when no other point is at least as cheap and at least as accurate and strictly
// better in one of the two. Header-only and engine-free, so a unit test checks it against brute force.
#pragma once

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace tradeoff {

struct CostError {
    double cost;
    double error;
};

// True when a dominates b.
inline bool dominates(const CostError& a, const CostError& b) {
    return a.cost <= b.cost && a.error <= b.error && (a.cost < b.cost || a.error < b.error);
}

// The indices of the points on the front, by increasing cost. Sort by cost (then error), sweep keeping
// each point strictly more accurate than every cheaper one; equal points are all kept. O(n log n).
inline std::vector<size_t> paretoFront(const std::vector<CostError>& p) {
    std::vector<size_t> order(p.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        return p[a].cost < p[b].cost || (p[a].cost == p[b].cost && p[a].error < p[b].error);
    });
    std::vector<size_t> front;
    for (size_t i : order) {
        if (front.empty()) {
            front.push_back(i);
            continue;
        }
        const CostError& last = p[front.back()];
        if (p[i].error < last.error) {
            front.push_back(i);
        } else if (p[i].error == last.error && p[i].cost == last.cost) {
            front.push_back(i); // a tie with a front point: it is not dominated either
        }
    }
    return front;
}

} // namespace tradeoff
