// SweepAndPrune.cpp - sort-and-sweep over the entries' boxes along x, planes first (SweepAndPrune.h).
#include "SweepAndPrune.h"

#include <algorithm>

namespace {

bool before(const gcol::Aabb& a, int ia, const gcol::Aabb& b, int ib) {
    return a.min.x < b.min.x || (a.min.x == b.min.x && ia < ib);
}

} // namespace

void SweepAndPrune::sortAfresh(const std::vector<SimpleCollisionSpace::Entry>& entries) {
    m_order.clear();
    m_planes.clear();
    m_place.assign(entries.size(), -1);
    for (int i = 0; i < int(entries.size()); ++i) {
        const SimpleCollisionSpace::Entry& e = entries[size_t(i)];
        if (!e.active) continue;
        if (e.plane) {
            m_planes.push_back(i);
            m_place[size_t(i)] = -2;
        } else {
            m_order.push_back(i);
        }
    }
    std::sort(m_order.begin(), m_order.end(), [&entries](int a, int b) {
        return before(entries[size_t(a)].box, a, entries[size_t(b)].box, b);
    });
    m_sorted.clear();
    for (size_t k = 0; k < m_order.size(); ++k) {
        m_sorted.push_back(entries[size_t(m_order[k])].box);
        m_place[size_t(m_order[k])] = int(k);
    }
}

Broadphase::PairList SweepAndPrune::findPairs(const std::vector<SimpleCollisionSpace::Entry>& entries,
                                              const std::vector<int>* changed) {
    bool afresh = !changed || m_place.size() != entries.size();
    if (!afresh) {
        if (changed->empty()) return {m_out.data(), m_out.size()}; // nothing changed: the same pairs
        for (int i : *changed) {
            const SimpleCollisionSpace::Entry& e = entries[size_t(i)];
            const int place = m_place[size_t(i)];
            if (e.active != (place != -1)) { // joined or left: the lists change
                afresh = true;
                break;
            }
            if (place >= 0) m_sorted[size_t(place)] = e.box;
        }
    }
    if (afresh) {
        sortAfresh(entries);
    } else {
        // Insertion sort on the previous order: each box moves down past those it now sorts before.
        for (size_t k = 1; k < m_order.size(); ++k) {
            if (!before(m_sorted[k], m_order[k], m_sorted[k - 1], m_order[k - 1])) continue;
            const gcol::Aabb box = m_sorted[k];
            const int index = m_order[k];
            size_t j = k;
            do {
                m_sorted[j] = m_sorted[j - 1];
                m_order[j] = m_order[j - 1];
                m_place[size_t(m_order[j])] = int(j);
                --j;
            } while (j > 0 && before(box, index, m_sorted[j - 1], m_order[j - 1]));
            m_sorted[j] = box;
            m_order[j] = index;
            m_place[size_t(index)] = int(j);
        }
    }
    m_out.clear();
    for (int p : m_planes)
        for (int i : m_order) m_out.emplace_back(std::min(p, i), std::max(p, i));
    const size_t n = m_sorted.size();
    for (size_t oi = 0; oi < n; ++oi) {
        const gcol::Aabb& a = m_sorted[oi];
        for (size_t oj = oi + 1; oj < n; ++oj) {
            const gcol::Aabb& b = m_sorted[oj];
            if (b.min.x > a.max.x) break;
            // One branch, rarely taken, in place of four that go either way.
            const bool overlap =
                (b.min.y <= a.max.y) & (a.min.y <= b.max.y) & (b.min.z <= a.max.z) & (a.min.z <= b.max.z);
            if (overlap)
                m_out.emplace_back(std::min(m_order[oi], m_order[oj]), std::max(m_order[oi], m_order[oj]));
        }
    }
    return {m_out.data(), m_out.size()};
}

void SweepAndPrune::overlapCandidates(const std::vector<CollisionGeometry*>& all, const gcol::Aabb&,
                                      std::vector<CollisionGeometry*>& out) {
    out.assign(all.begin(), all.end());
}

void SweepAndPrune::rayCandidates(const std::vector<CollisionGeometry*>& all, const Vector&, const Vector&,
                                  float, std::vector<CollisionGeometry*>& out) {
    overlapCandidates(all, gcol::Aabb(), out);
}
