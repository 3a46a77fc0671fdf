// SweepAndPrune.cpp - sort-and-sweep over the entries' boxes along x, planes first (SweepAndPrune.h).
#include "SweepAndPrune.h"

#include <algorithm>

void SweepAndPrune::findPairs(const std::vector<SimpleCollisionSpace::Entry>& entries,
                              std::vector<EntryPair>& out) {
    out.clear();
    m_order.clear();
    m_planes.clear();
    for (int i = 0; i < int(entries.size()); ++i)
        (entries[size_t(i)].plane ? m_planes : m_order).push_back(i);
    std::sort(m_order.begin(), m_order.end(), [&entries](int a, int b) {
        float ma = entries[size_t(a)].box.min.x, mb = entries[size_t(b)].box.min.x;
        return ma < mb || (ma == mb && a < b);
    });
    for (int p : m_planes)
        for (int i : m_order) out.emplace_back(std::min(p, i), std::max(p, i));
    for (size_t oi = 0; oi < m_order.size(); ++oi) {
        const gcol::Aabb& a = entries[size_t(m_order[oi])].box;
        for (size_t oj = oi + 1; oj < m_order.size(); ++oj) {
            const gcol::Aabb& b = entries[size_t(m_order[oj])].box;
            if (b.min.x > a.max.x) break;
            if (b.min.y > a.max.y || a.min.y > b.max.y || b.min.z > a.max.z || a.min.z > b.max.z) continue;
            out.emplace_back(std::min(m_order[oi], m_order[oj]), std::max(m_order[oi], m_order[oj]));
        }
    }
}

void SweepAndPrune::overlapCandidates(const std::vector<CollisionGeometry*>& all, const gcol::Aabb&,
                                      std::vector<CollisionGeometry*>& out) {
    out.assign(all.begin(), all.end());
}

void SweepAndPrune::rayCandidates(const std::vector<CollisionGeometry*>& all, const Vector&, const Vector&,
                                  float, std::vector<CollisionGeometry*>& out) {
    overlapCandidates(all, gcol::Aabb(), out);
}
