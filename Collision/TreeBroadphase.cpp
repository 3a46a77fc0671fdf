// TreeBroadphase.cpp - proxies, the move buffer and the persistent pair set of the octree space
// (TreeBroadphase.h).
#include "TreeBroadphase.h"
#include "iRigidBody.h"

#include <algorithm>
#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace {

// gcol::overlaps of two proxies' exact boxes: x, y and z at once on SSE2 (the fourth lane, the entry index
// against the fourth hi, is masked off).
template <class Exact> bool boxesOverlap(const Exact& a, const Exact& b) {
#if defined(__SSE2__)
    const __m128 lower = _mm_cmple_ps(_mm_load_ps(a.lo), _mm_load_ps(b.hi));
    const __m128 upper = _mm_cmple_ps(_mm_load_ps(b.lo), _mm_load_ps(a.hi));
    return (_mm_movemask_ps(_mm_and_ps(lower, upper)) & 7) == 7;
#else
    return (a.lo[0] <= b.hi[0]) & (a.hi[0] >= b.lo[0]) & (a.lo[1] <= b.hi[1]) & (a.hi[1] >= b.lo[1]) &
           (a.lo[2] <= b.hi[2]) & (a.hi[2] >= b.lo[2]);
#endif
}

// Stretches [lo, hi] by d (its side toward d), at most by limit.
void stretch(float& lo, float& hi, float d, float limit) {
    d = std::fmax(-limit, std::fmin(limit, d));
    (d > 0.0f ? hi : lo) += d;
}

} // namespace

int TreeBroadphase::proxyOf(CollisionGeometry* g) {
    CollisionGeometry::SpaceState& st = g->spaceState();
    if (st.proxy >= 0) return st.proxy;
    int p;
    if (m_freeProxies.empty()) {
        p = int(m_proxies.size());
        m_proxies.emplace_back();
        m_exact.emplace_back();
        m_checked.emplace_back();
    } else {
        p = m_freeProxies.back();
        m_freeProxies.pop_back();
    }
    Proxy& x = m_proxies[size_t(p)];
    x = Proxy();
    m_checked[size_t(p)].valid = false;
    x.g = g;
    x.order = st.order;
    x.used = true;
    st.proxy = p;
    return p;
}

void TreeBroadphase::refit(int p, const gcol::Aabb& tight) {
    Proxy& x = m_proxies[size_t(p)];
    const Vector m(m_margin, m_margin, m_margin);
    gcol::Aabb fat{tight.min - m, tight.max + m};
    if (x.leaf != gcol::DynamicTree::kNull) {
        // Motion prediction: where it went since its last fat box, it probably goes on (at most a box size).
        const Vector d = (tight.min + tight.max - x.fat.min - x.fat.max) * 0.5f;
        const Vector size = tight.max - tight.min + m;
        stretch(fat.min.x, fat.max.x, d.x, size.x);
        stretch(fat.min.y, fat.max.y, d.y, size.y);
        stretch(fat.min.z, fat.max.z, d.z, size.z);
    }
    x.fat = fat;
    x.stale = true;
    x.holdsEntry = false;
    m_checked[size_t(p)].valid = false;
    if (!x.moved) {
        x.moved = true;
        m_moveBuffer.push_back(p);
    }
}

namespace {

// 10 bits of v spread to every third bit.
unsigned spread(unsigned v) {
    v &= 0x3FFu;
    v = (v | (v << 16)) & 0x030000FFu;
    v = (v | (v << 8)) & 0x0300F00Fu;
    v = (v | (v << 4)) & 0x030C30C3u;
    v = (v | (v << 2)) & 0x09249249u;
    return v;
}

} // namespace

unsigned TreeBroadphase::mortonKey(int p, const gcol::Aabb& bounds, float scale) const {
    const gcol::Aabb& f = m_proxies[size_t(p)].fat;
    const Vector c = ((f.min + f.max) * 0.5f - bounds.min) * scale;
    return spread(unsigned(c.x)) | spread(unsigned(c.y)) << 1 | spread(unsigned(c.z)) << 2;
}

void TreeBroadphase::applyMoves() {
    if (m_moveBuffer.empty()) return;
    const size_t alive = m_proxies.size() - m_freeProxies.size() - m_dead.size();
    // Most moved: new boxes in place and one rebuild over every leaf, instead of a re-insertion each.
    const bool bulk = m_moveBuffer.size() >= kBulkMoves && 4 * m_moveBuffer.size() >= alive;
    gcol::Aabb bounds = m_proxies[size_t(m_moveBuffer[0])].fat;
    m_keys.clear();
    for (size_t p = 0; p < m_proxies.size(); ++p) {
        const Proxy& x = m_proxies[p];
        if (x.used && !x.dead && (bulk || x.moved)) bounds = gcol::unite(bounds, x.fat);
    }
    const Vector size = bounds.max - bounds.min;
    const float extent = std::fmax(size.x, std::fmax(size.y, size.z));
    const float scale = extent > 0.0f ? 1023.0f / extent : 0.0f;
    if (bulk) {
        for (size_t p = 0; p < m_proxies.size(); ++p) {
            Proxy& x = m_proxies[p];
            if (!x.used || x.dead) continue;
            if (x.leaf == gcol::DynamicTree::kNull)
                x.leaf = m_tree.insert(x.fat, int(p), false);
            else if (x.stale)
                m_tree.setLeafBox(x.leaf, x.fat);
            x.stale = false;
            m_keys.emplace_back(mortonKey(int(p), bounds, scale), int(p));
        }
        std::sort(m_keys.begin(), m_keys.end());
        m_leafOrder.clear();
        m_moveBuffer.clear();
        for (const std::pair<unsigned, int>& k : m_keys) {
            m_leafOrder.push_back(m_proxies[size_t(k.second)].leaf);
            if (m_proxies[size_t(k.second)].moved) m_moveBuffer.push_back(k.second);
        }
        m_tree.rebuild(m_leafOrder);
        return;
    }
    for (int p : m_moveBuffer) m_keys.emplace_back(mortonKey(p, bounds, scale), p);
    std::sort(m_keys.begin(), m_keys.end());
    for (size_t i = 0; i < m_keys.size(); ++i) m_moveBuffer[i] = m_keys[i].second;
    for (int p : m_moveBuffer) {
        Proxy& x = m_proxies[size_t(p)];
        if (!x.stale || x.dead) continue;
        x.stale = false;
        if (x.leaf == gcol::DynamicTree::kNull)
            x.leaf = m_tree.insert(x.fat, p);
        else
            m_tree.move(x.leaf, x.fat);
    }
}

void TreeBroadphase::kill(int p) {
    Proxy& x = m_proxies[size_t(p)];
    if (x.dead || !x.used) return;
    if (x.leaf != gcol::DynamicTree::kNull) m_tree.remove(x.leaf);
    x.leaf = gcol::DynamicTree::kNull;
    x.dead = true;
    x.g->spaceState().proxy = -1;
    x.g = nullptr; // it may be deleted: its pairs go at the next update, the slot after that
    m_dead.push_back(p);
}

void TreeBroadphase::forget(CollisionGeometry* g) {
    if (g->spaceState().proxy >= 0) kill(g->spaceState().proxy);
}

int TreeBroadphase::knownProxy(const SimpleCollisionSpace::Entry& e, int i) const {
    if (size_t(i) < m_entryProxy.size()) {
        const int p = m_entryProxy[size_t(i)];
        if (p >= 0 && m_proxies[size_t(p)].g == e.g) return p; // (a proxy names its geometry until it dies)
    }
    return e.g->spaceState().proxy;
}

void TreeBroadphase::track(const SimpleCollisionSpace::Entry& e, int i) {
    int p = knownProxy(e, i);
    if (p < 0) p = proxyOf(e.g);
    if (m_entryProxy.size() <= size_t(i)) m_entryProxy.resize(size_t(i) + 1, -1);
    m_entryProxy[size_t(i)] = p;
    Proxy& x = m_proxies[size_t(p)];
    x.entry = i;
    x.stamp = m_stamp;
    if ((x.leaf == gcol::DynamicTree::kNull && !x.stale) || !gcol::contains(x.fat, e.box)) refit(p, e.box);
    x.holdsEntry = true;
    Exact& ex = m_exact[size_t(p)];
    ex.lo[0] = e.box.min.x;
    ex.lo[1] = e.box.min.y;
    ex.lo[2] = e.box.min.z;
    ex.hi[0] = e.box.max.x;
    ex.hi[1] = e.box.max.y;
    ex.hi[2] = e.box.max.z;
    ex.entry = i;
}

void TreeBroadphase::listEntries(const std::vector<SimpleCollisionSpace::Entry>& entries) {
    m_planes.clear();
    m_bounded.clear();
    for (int i = 0; i < int(entries.size()); ++i)
        if (entries[size_t(i)].active) (entries[size_t(i)].plane ? m_planes : m_bounded).push_back(i);
}

Broadphase::PairList TreeBroadphase::findPairs(const std::vector<SimpleCollisionSpace::Entry>& entries,
                                               const std::vector<int>* changed) {
    ++m_stamp;
    // Every entry is looked at when they may be new ones, or when queries moved proxies since the last call
    // (a proxy they made or refitted may belong to no entry, or its fat box may have left its entry's box).
    const bool all = !changed || !m_moveBuffer.empty() || !m_outValid;
    bool lists = all, boxes = all;
    if (all) {
        listEntries(entries);
        for (int i : m_bounded) track(entries[size_t(i)], i);
        // Geometry not gathered this call (no body now, a pose that is not finite, an empty compound) leaves.
        for (size_t p = 0; p < m_proxies.size(); ++p)
            if (m_proxies[p].used && !m_proxies[p].dead && m_proxies[p].stamp != m_stamp) kill(int(p));
    } else {
        for (int i : *changed) {
            const SimpleCollisionSpace::Entry& e = entries[size_t(i)];
            if (e.plane) { // a plane joined or left
                lists = true;
                continue;
            }
            const int p = knownProxy(e, i);
            if (!e.active) { // it leaves
                if (p >= 0) kill(p);
                lists = true;
                continue;
            }
            lists = lists || p < 0; // it joins
            track(e, i);
            boxes = true;
        }
        if (lists) listEntries(entries);
    }
    const bool pairs = !m_moveBuffer.empty() || !m_dead.empty();
    updatePairs();
    if (!lists && !boxes && !pairs) return {m_out.data(), m_outCount}; // nothing changed: the same pairs
    const size_t most = m_planes.size() * m_bounded.size() + m_pairs.size();
    if (m_out.size() < most) m_out.resize(most);
    EntryPair* out = m_out.data();
    size_t n = 0;
    for (int p : m_planes)
        for (int i : m_bounded) out[n++] = EntryPair(std::min(p, i), std::max(p, i));
    // Every kept pair is tested again and written, kept when it touches, without a branch that goes either
    // way. (Remembering each pair's answer and testing only pairs whose boxes changed cost more than it
    // saved: the test is a few instructions, the bookkeeping as many and a store.)
    const Exact* exact = m_exact.data();
    for (const Pair& pr : m_pairs) {
        const Exact& a = exact[pr.a];
        const Exact& b = exact[pr.b];
        out[n] = EntryPair(a.entry, b.entry); // a joined first: its entry comes first (the members' order)
        n += size_t(boxesOverlap(a, b));
    }
    m_outCount = n;
    m_outValid = true;
    return {m_out.data(), m_outCount};
}

void TreeBroadphase::updatePairs() {
    if (m_moveBuffer.empty() && m_dead.empty()) return; // nothing moved: the pairs stand
    applyMoves();
    m_newPairs.clear();
    for (int p : m_moveBuffer) {
        const Proxy& x = m_proxies[size_t(p)];
        if (x.dead) continue;
        ++m_treeQueries;
        m_tree.query(x.fat, [&](int q) {
            const Proxy& y = m_proxies[size_t(q)];
            if (q == p || (y.moved && q < p)) return; // itself, or found by q's own query
            m_newPairs.push_back(pairOf(x, p, y, q));
        });
    }
    std::sort(m_newPairs.begin(), m_newPairs.end());
    // Merge: an old pair stays while both proxies live and, if either moved, their fat boxes still overlap.
    auto keep = [this](const Pair& pr) {
        const Proxy& a = m_proxies[size_t(pr.a)];
        const Proxy& b = m_proxies[size_t(pr.b)];
        return !a.dead && !b.dead && (!(a.moved || b.moved) || gcol::overlaps(a.fat, b.fat));
    };
    m_merged.clear();
    size_t i = 0, j = 0;
    while (i < m_pairs.size() || j < m_newPairs.size()) {
        if (j == m_newPairs.size() || (i < m_pairs.size() && m_pairs[i] < m_newPairs[j])) {
            if (keep(m_pairs[i])) m_merged.push_back(m_pairs[i]);
            ++i;
        } else {
            if (i < m_pairs.size() && !(m_newPairs[j] < m_pairs[i])) ++i; // the same pair, found again
            m_merged.push_back(m_newPairs[j]);
            ++j;
        }
    }
    m_pairs.swap(m_merged);
    for (int p : m_moveBuffer) m_proxies[size_t(p)].moved = false;
    m_moveBuffer.clear();
    for (int p : m_dead) {
        m_proxies[size_t(p)] = Proxy();
        m_freeProxies.push_back(p);
    }
    m_dead.clear();
}

bool TreeBroadphase::stillInside(const CollisionGeometry* g,
                                 const std::vector<SimpleCollisionSpace::Entry>& entries, const Vector& o,
                                 const Matrix& r) const {
    const CollisionGeometry::SpaceState& st = g->spaceState();
    if (st.proxy < 0) return false;
    const Proxy& x = m_proxies[size_t(st.proxy)];
    if (x.leaf == gcol::DynamicTree::kNull) return false;
    const unsigned version = g->shapeVersion();
    if (x.holdsEntry && st.entry >= 0 && size_t(st.entry) < entries.size()) {
        // The entry the proxy was last tracked from: its box was made from its pose and shape version.
        const SimpleCollisionSpace::Entry& e = entries[size_t(st.entry)];
        if (e.g == g && e.active && e.cache.valid && e.cache.shapeVersion == version && e.origin == o &&
            e.rotation == r)
            return true;
    }
    const Checked& c = m_checked[size_t(st.proxy)];
    return c.valid && c.shapeVersion == version && c.origin == o && c.rotation == r;
}

void TreeBroadphase::syncQueries(const std::vector<CollisionGeometry*>& all,
                                 const std::vector<SimpleCollisionSpace::Entry>& entries, bool) {
    m_queryPlanes.clear();
    for (CollisionGeometry* g : all) {
        if (g->isPlane()) {
            m_queryPlanes.push_back(g);
            continue;
        }
        const CollisionGeometry::SpaceState& st = g->spaceState();
        if (!g->body() || st.pendingDelete || st.pendingRemove) continue; // never a query result
        // At the pose a query last checked its fat box at (first: once bodies moved since the space's
        // call, that is the later pose), or the one it was made for, known without posing it.
        const RBDynamics& d = g->body()->getDynamics();
        const bool raw = !d.attachedTo();
        if (st.proxy >= 0 && raw && m_proxies[size_t(st.proxy)].leaf != gcol::DynamicTree::kNull) {
            const Checked& c = m_checked[size_t(st.proxy)];
            if (c.valid && c.raw && c.shapeVersion == g->shapeVersion() && c.inputs.same(d)) continue;
            if (m_proxies[size_t(st.proxy)].holdsEntry && st.entry >= 0 &&
                size_t(st.entry) < entries.size() &&
                SimpleCollisionSpace::atEntryPose(entries[size_t(st.entry)], *g))
                continue;
        }
        Vector o;
        Matrix r(1);
        if (!g->currentPose(o, r)) continue;
        if (stillInside(g, entries, o, r)) continue; // where its fat box was made (or checked)
        m_shapes.clear();
        g->worldShapes(o, r, m_shapes);
        if (m_shapes.empty()) continue;
        const gcol::Aabb box = gcol::boundsOf(m_shapes);
        const int p = proxyOf(g);
        Proxy& x = m_proxies[size_t(p)];
        if ((x.leaf == gcol::DynamicTree::kNull && !x.stale) || !gcol::contains(x.fat, box)) refit(p, box);
        Checked& checked = m_checked[size_t(p)];
        checked.origin = o;
        checked.rotation = r;
        checked.shapeVersion = g->shapeVersion();
        checked.valid = true;
        checked.raw = raw;
        if (raw) checked.inputs.store(d);
    }
    applyMoves();
}

void TreeBroadphase::gatherCandidates(std::vector<CollisionGeometry*>& out) {
    out.clear();
    for (int p : m_hits) out.push_back(m_proxies[size_t(p)].g);
    out.insert(out.end(), m_queryPlanes.begin(), m_queryPlanes.end());
    std::sort(out.begin(), out.end(), [](CollisionGeometry* a, CollisionGeometry* b) {
        return a->spaceState().order < b->spaceState().order;
    });
}

void TreeBroadphase::overlapCandidates(const std::vector<CollisionGeometry*>&, const gcol::Aabb& box,
                                       std::vector<CollisionGeometry*>& out) {
    m_hits.clear();
    ++m_treeQueries;
    m_tree.query(box, [this](int p) { m_hits.push_back(p); });
    gatherCandidates(out);
}

void TreeBroadphase::rayCandidates(const std::vector<CollisionGeometry*>&, const Vector& origin,
                                   const Vector& dir, float maxT, std::vector<CollisionGeometry*>& out) {
    m_hits.clear();
    ++m_treeQueries;
    m_tree.rayCast(origin, dir, maxT, [this](int p) { m_hits.push_back(p); });
    gatherCandidates(out);
}
