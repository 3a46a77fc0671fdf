// SweepAndPrune.h - the simple space's broadphase: the entries' boxes sorted along x and swept; planes meet
// every bounded entry, and come first, so that when the contact budget fills the ground is the last thing
// lost. Queries consider every geometry: outside a batch each is tested exactly (the brute-force reference
// the octree space's queries are checked against); in a batch (iCollisionQueries.h) the batch's start keeps
// every geometry's box at its pose, and a query tests exactly only the geometry whose box it meets.
//
// The order is kept between calls: when only some boxes changed, an insertion sort on the previous order
// brings it up to date (O(n + how far they moved in it)), and the sweep runs over a packed copy of the
// sorted boxes, a column per coordinate, four later boxes compared at once (SSE2); when nothing changed, the
// previous pairs stand as they are. The pairs, and their order (by
// the low x of the first box, ties by entry index, then along the sweep), are those of sorting afresh.
#pragma once

#include "Broadphase.h"

class SweepAndPrune final : public Broadphase {
public:
    PairList findPairs(const std::vector<SimpleCollisionSpace::Entry>& entries,
                       const std::vector<int>* changed) override;
    void syncQueries(const std::vector<CollisionGeometry*>& all,
                     const std::vector<SimpleCollisionSpace::Entry>& entries, bool batch) override;
    void overlapCandidates(const std::vector<CollisionGeometry*>& all, const gcol::Aabb& box,
                           std::vector<CollisionGeometry*>& out) override;
    void rayCandidates(const std::vector<CollisionGeometry*>& all, const Vector& origin, const Vector& dir,
                       float maxT, std::vector<CollisionGeometry*>& out) override;
    void forget(CollisionGeometry*) override {}

private:
    void sortAfresh(const std::vector<SimpleCollisionSpace::Entry>& entries);
    void sweep();                       // m_sorted's overlapping pairs into m_out
    std::vector<int> m_order, m_planes; // active bounded entries by (box.min.x, index); active planes
    std::vector<gcol::Aabb> m_sorted;   // m_order's boxes, in that order
    std::vector<int> m_place;           // each entry's place in m_order (-1: none, -2: a plane)
    std::vector<EntryPair> m_out;
    std::vector<float> m_minX, m_minY, m_maxY, m_minZ, m_maxZ; // m_sorted's, a column each (sweep)
    // In a batch: each geometry's box at its pose, in the order of the space's members (a query's all).
    struct QueryBox {
        gcol::Aabb box;
        enum Kind : unsigned char { Never, Bounded, Always } kind; // not posed; its box; a plane
    };
    std::vector<QueryBox> m_queryBoxes;
    bool m_filtered = false; // m_queryBoxes hold the last sync's (a batch's)
    // all, or (in a batch) the planes and the geometry whose box meets(box) accepts, into out.
    template <class Meets>
    void candidates(const std::vector<CollisionGeometry*>& all, std::vector<CollisionGeometry*>& out,
                    Meets meets) const;
    std::vector<gcol::WorldShape> m_shapes; // scratch
};
