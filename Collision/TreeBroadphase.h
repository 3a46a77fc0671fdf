// TreeBroadphase.h - the octree space's broadphase (iOctreeCollisionSpace.h): a dynamic AABB tree of fat
// boxes whose pairs persist between calls, in the manner of Box2D's broadphase (move buffer, pair set).
//
// Each bounded geometry has a proxy: a leaf of the tree with a fat box, its tight box grown by kMargin on
// every side and stretched along its last displacement (motion prediction). A call compares each entry's
// box with its fat box; only a geometry that left it gets a new fat box and goes into the move buffer, and
// only moved proxies query the tree. The moved leaves are re-inserted and query in Morton order of their
// centres (neighbours one after the other: the nodes they pass stay in cache, and the tree they make is
// tighter), which does not change any result. When most proxies moved (kBulkMoves), the tree is rebuilt
// in that order over all leaves instead of re-inserting each. The pair set (a vector sorted by the
// geometries' join order, so it never depends on heap addresses) keeps every pair whose fat boxes overlap: a
// new pair joins when a moved proxy finds it, a pair leaves when one of its proxies moved and the fat boxes
// no longer overlap, or when a geometry leaves the space. A call where nothing moved makes no tree query and
// no merge: it lists the pairs whose exact boxes overlap, O(pairs). Pairs are listed planes first, then by
// join order. Queries first bring the proxies up to date with the bodies' current poses (syncQueries: a pose
// compare per geometry, shapes rebuilt only for one that moved; once for a batch of queries), then ask the
// tree.
//
// A call's work follows what changed: the space names the entries whose boxes changed, and only their
// proxies are looked at (every entry's only when the space laid its entries out anew, or queries moved
// proxies since). When a box changed, every kept pair's exact boxes are compared again (a few instructions a
// pair); when none did, the previous list stands as it is.
#pragma once

#include "Broadphase.h"
#include "DynamicTree.h"
#include "PoseInputs.h"

#include <cstdint>

class TreeBroadphase final : public Broadphase {
public:
    // m (times the length unit), fat box margin on every side. Bullet's dbvt margin: against 0.1 m, the kept
    // pairs a call tests again fall from 97,900 to 69,100, the candidate stage of 10,000 boxes moved 1 cm 5 %
    // faster; a 1,000-sphere rain and box pile cost the same (their moves are the stretch's or inside both).
    static constexpr float kMargin = 0.05f;
    static constexpr size_t kBulkMoves = 64; // this many moved, and a quarter of all: one rebuild

    PairList findPairs(const std::vector<SimpleCollisionSpace::Entry>& entries,
                       const std::vector<int>* changed) override;
    // Every proxy brought to its geometry's current pose: a pose compare a geometry, shapes made anew only
    // for one that moved.
    void syncQueries(const std::vector<CollisionGeometry*>& all,
                     const std::vector<SimpleCollisionSpace::Entry>& entries, bool batch) override;
    void overlapCandidates(const std::vector<CollisionGeometry*>& all, const gcol::Aabb& box,
                           std::vector<CollisionGeometry*>& out) override;
    void rayCandidates(const std::vector<CollisionGeometry*>& all, const Vector& origin, const Vector& dir,
                       float maxT, std::vector<CollisionGeometry*>& out) override;
    void forget(CollisionGeometry* g) override;
    // Fat boxes made from now on get the new margin (the ones made already are still conservative).
    void setLengthUnit(float unitsPerMetre) override { m_margin = kMargin * unitsPerMetre; }

    // For tests and benchmarks: tree queries made so far, the tree, the pairs kept.
    size_t treeQueries() const { return m_treeQueries; }
    const gcol::DynamicTree& tree() const { return m_tree; }
    size_t pairCount() const { return m_pairs.size(); }

private:
    float m_margin = kMargin;
    // One cache line: what a call reads of every proxy whose box changed.
    struct alignas(64) Proxy {
        gcol::Aabb fat;
        unsigned long long order = 0; // the geometry's join order (SpaceState::order)
        CollisionGeometry* g = nullptr;
        int leaf = gcol::DynamicTree::kNull;
        int entry = -1;     // its entry in the current call
        unsigned stamp = 0; // the call that last saw it
        bool moved = false, dead = false, used = false;
        bool stale = false;      // fat changed; the tree's leaf not yet
        bool holdsEntry = false; // fat holds the box of its entry (its pose and shapes as the space has them)
    };
    struct Pair {
        // The join orders, lower in the high half: sorted by key, pairs follow the space's order. (Join
        // orders are counted modulo 2^32 here: the order only goes wrong after 4 billion geometries joined.)
        uint64_t key;
        int a, b; // their proxies, a the earlier joined
        bool operator<(const Pair& o) const { return key < o.key; }
    };
    static Pair pairOf(const Proxy& x, int p, const Proxy& y, int q) {
        const uint64_t ox = uint32_t(x.order), oy = uint32_t(y.order);
        return ox < oy ? Pair{ox << 32 | oy, p, q} : Pair{oy << 32 | ox, q, p};
    }
    // What the pair list reads of each proxy, packed in two 16-byte rows (one SSE load each): its entry's
    // exact box (lo, hi) and index.
    struct alignas(16) Exact {
        float lo[3] = {0, 0, 0};
        int entry = -1;
        float hi[3] = {0, 0, 0};
        float unused = 0;
    };
    // Entry i (active, bounded) of this call: its proxy made or found, its fat box checked, its box noted.
    void track(const SimpleCollisionSpace::Entry& e, int i);
    void listEntries(const std::vector<SimpleCollisionSpace::Entry>& entries); // m_planes, m_bounded
    int proxyOf(CollisionGeometry* g);
    // The proxy of entry i's geometry (-1: none), remembered by entry index: the geometry's space state is a
    // cache line the call has no other need of.
    int knownProxy(const SimpleCollisionSpace::Entry& e, int i) const;
    // Gives proxy p the box tight (not inside its fat box): a new fat box, into the move buffer.
    void refit(int p, const gcol::Aabb& tight);
    // Puts the move buffer in Morton order and brings the tree's leaves up to date with the fat boxes.
    void applyMoves();
    unsigned mortonKey(int p, const gcol::Aabb& bounds, float scale) const;
    void kill(int p);
    void updatePairs();
    // A pose at which a query found the fat box holding a proxy's shapes (kept out of Proxy: only queries
    // read or write it; a new fat box voids it).
    struct Checked {
        Vector origin;
        Matrix rotation = Matrix(1);
        gcol::PoseInputs inputs; // what the pose was made of, when its body had no parent (raw)
        unsigned shapeVersion = 0;
        bool valid = false, raw = false;
    };
    // g's proxy's fat box holds g's shapes at (o, r): it held its entry's box, and the entry is at that pose.
    bool stillInside(const CollisionGeometry* g, const std::vector<SimpleCollisionSpace::Entry>& entries,
                     const Vector& o, const Matrix& r) const;
    void gatherCandidates(std::vector<CollisionGeometry*>& out);

    gcol::DynamicTree m_tree;
    std::vector<Proxy> m_proxies;
    std::vector<Exact> m_exact;     // per proxy
    std::vector<Checked> m_checked; // per proxy
    std::vector<int> m_entryProxy;  // per entry index, its geometry's proxy when last tracked
    std::vector<EntryPair> m_out;   // its first m_outCount are this call's pairs (it never shrinks)
    size_t m_outCount = 0;
    bool m_outValid = false;
    std::vector<int> m_freeProxies, m_dead;
    std::vector<int> m_moveBuffer;
    std::vector<std::pair<unsigned, int>> m_keys; // Morton key, proxy
    std::vector<int> m_leafOrder;
    std::vector<Pair> m_pairs, m_newPairs, m_merged;
    std::vector<int> m_planes, m_bounded, m_hits;
    std::vector<gcol::WorldShape> m_shapes;
    std::vector<CollisionGeometry*> m_queryPlanes;
    unsigned m_stamp = 0;
    size_t m_treeQueries = 0;
};
