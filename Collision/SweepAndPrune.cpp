// SweepAndPrune.cpp - sort-and-sweep over the entries' boxes along x, planes first (SweepAndPrune.h).
#include "SweepAndPrune.h"
#include "DynamicTree.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#define GUARDIAN_SSE_SWEEP 1
#else
#define GUARDIAN_SSE_SWEEP 0
#endif

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
    sweep();
    return {m_out.data(), m_out.size()};
}

// Each box against those after it in the x order whose low x is not past its high x. The boxes' coordinates
// are laid out one array each, so that four later boxes are compared at once; four boxes whose low x is
// +infinity close the arrays, so a group of four never reads past them and, for a box with a finite high x,
// the last group always ends the sweep. The pairs come out in the order of the one-at-a-time sweep (the
// fallback without SSE2, and for a box reaching to infinity).
void SweepAndPrune::sweep() {
    const size_t n = m_sorted.size();
    for (std::vector<float>* column : {&m_minX, &m_minY, &m_maxY, &m_minZ, &m_maxZ}) column->resize(n + 4);
    for (size_t k = 0; k < n; ++k) {
        const gcol::Aabb& b = m_sorted[k];
        m_minX[k] = b.min.x;
        m_minY[k] = b.min.y;
        m_maxY[k] = b.max.y;
        m_minZ[k] = b.min.z;
        m_maxZ[k] = b.max.z;
    }
    for (size_t k = n; k < n + 4; ++k)
        m_minX[k] = m_minY[k] = m_maxY[k] = m_minZ[k] = m_maxZ[k] = std::numeric_limits<float>::infinity();
    auto emit = [this](size_t oi, size_t oj) {
        m_out.emplace_back(std::min(m_order[oi], m_order[oj]), std::max(m_order[oi], m_order[oj]));
    };
    for (size_t oi = 0; oi < n; ++oi) {
        const gcol::Aabb& a = m_sorted[oi];
#if GUARDIAN_SSE_SWEEP
        // (Only a box with a finite high x: the closing boxes are then past it, and end the loop.)
        if (a.max.x < std::numeric_limits<float>::infinity()) {
            const __m128 highX = _mm_set1_ps(a.max.x), lowY = _mm_set1_ps(a.min.y),
                         highY = _mm_set1_ps(a.max.y), lowZ = _mm_set1_ps(a.min.z),
                         highZ = _mm_set1_ps(a.max.z);
            for (size_t oj = oi + 1;; oj += 4) {
                // The lanes whose low x is past a's high x: from the first such on, every later one is too.
                const int past = _mm_movemask_ps(_mm_cmpgt_ps(_mm_loadu_ps(&m_minX[oj]), highX));
                const __m128 y = _mm_and_ps(_mm_cmple_ps(_mm_loadu_ps(&m_minY[oj]), highY),
                                            _mm_cmple_ps(lowY, _mm_loadu_ps(&m_maxY[oj])));
                const __m128 z = _mm_and_ps(_mm_cmple_ps(_mm_loadu_ps(&m_minZ[oj]), highZ),
                                            _mm_cmple_ps(lowZ, _mm_loadu_ps(&m_maxZ[oj])));
                int hits = _mm_movemask_ps(_mm_and_ps(y, z)) & (past ? (past & -past) - 1 : 0xF);
                for (int lane = 0; hits; ++lane, hits >>= 1)
                    if (hits & 1) emit(oi, oj + size_t(lane));
                if (past) break;
            }
            continue;
        }
#endif
        for (size_t oj = oi + 1; oj < n; ++oj) {
            if (m_minX[oj] > a.max.x) break;
            const gcol::Aabb& b = m_sorted[oj];
            // One branch, rarely taken, in place of four that go either way.
            const bool overlap =
                (b.min.y <= a.max.y) & (a.min.y <= b.max.y) & (b.min.z <= a.max.z) & (a.min.z <= b.max.z);
            if (overlap) emit(oi, oj);
        }
    }
}

void SweepAndPrune::syncQueries(const std::vector<CollisionGeometry*>& all,
                                const std::vector<SimpleCollisionSpace::Entry>& entries, bool batch) {
    m_filtered = batch;
    if (!batch) return; // each query tests every geometry exactly
    m_queryBoxes.resize(all.size());
    for (size_t k = 0; k < all.size(); ++k) {
        const CollisionGeometry* g = all[k];
        QueryBox& q = m_queryBoxes[k];
        q.kind = QueryBox::Never;
        if (g->isPlane()) {
            q.kind = QueryBox::Always;
            continue;
        }
        const CollisionGeometry::SpaceState& st = g->spaceState();
        if (!g->body() || st.pendingDelete || st.pendingRemove) continue; // never a query result
        if (st.entry >= 0 && size_t(st.entry) < entries.size() &&
            SimpleCollisionSpace::atEntryPose(entries[size_t(st.entry)], *g)) {
            q.box = entries[size_t(st.entry)].cache.tight; // its shapes' box at this very pose
        } else {
            Vector o;
            Matrix r(1);
            if (!g->currentPose(o, r)) continue;
            m_shapes.clear();
            g->worldShapes(o, r, m_shapes);
            if (m_shapes.empty()) continue;
            q.box = gcol::boundsOf(m_shapes);
        }
        // Grown by far more than rounding (1e-5 of its distance from the origin, at least 1e-5): a grazing
        // query that the exact test accepts is never filtered out.
        const Vector& lo = q.box.min;
        const Vector& hi = q.box.max;
        const float reach =
            std::fmax(std::fmax(std::fmax(std::fabs(lo.x), std::fabs(lo.y)), std::fabs(lo.z)),
                      std::fmax(std::fmax(std::fabs(hi.x), std::fabs(hi.y)), std::fabs(hi.z)));
        const float grow = 1e-5f * (1.0f + reach);
        q.box.min -= Vector(grow, grow, grow);
        q.box.max += Vector(grow, grow, grow);
        q.kind = QueryBox::Bounded;
    }
}

template <class Meets>
void SweepAndPrune::candidates(const std::vector<CollisionGeometry*>& all,
                               std::vector<CollisionGeometry*>& out, Meets meets) const {
    if (!m_filtered) {
        out.assign(all.begin(), all.end());
        return;
    }
    out.clear();
    for (size_t k = 0; k < all.size(); ++k) {
        const QueryBox& q = m_queryBoxes[k];
        if (q.kind == QueryBox::Always || (q.kind == QueryBox::Bounded && meets(q.box)))
            out.push_back(all[k]);
    }
}

void SweepAndPrune::overlapCandidates(const std::vector<CollisionGeometry*>& all, const gcol::Aabb& box,
                                      std::vector<CollisionGeometry*>& out) {
    candidates(all, out, [&box](const gcol::Aabb& b) { return gcol::overlaps(b, box); });
}

void SweepAndPrune::rayCandidates(const std::vector<CollisionGeometry*>& all, const Vector& origin,
                                  const Vector& dir, float maxT, std::vector<CollisionGeometry*>& out) {
    const gcol::RaySegment segment(origin, dir, maxT);
    candidates(all, out, [&segment](const gcol::Aabb& b) { return segment.hits(b); });
}
