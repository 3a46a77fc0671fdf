// Broadphase.h - the candidate-pair stage of a collision space, behind one small internal interface, so
// the same space (SimpleCollisionSpace: gathering, the fixed/sleeping skip, exact and continuous tests,
// events, the budget) runs with sort-and-sweep (SweepAndPrune.h, the simple space) or with a persistent
// dynamic tree (TreeBroadphase.h, the octree space).
//
// Contract: findPairs lists exactly the pairs of this call's active entries (Entry::active) whose boxes
// (Entry::box, swept over the motion) overlap, plus every active plane with every active bounded entry, each
// once as (i, j) with i < j (entry indices), in the order they are to be tested. Two broadphases may differ
// in that order, never in the set: the space's contacts are the same set whichever runs. The list is the
// broadphase's own storage, valid until its next call. changed names the entries whose box or activity may
// differ from the previous call's (an entry not named is as it was: its box, activity and index); nullptr
// means any may, and the entries may be new ones (a broadphase then looks at every entry). A call where
// nothing changed may return the previous list as it is. The query candidates are a superset of the
// geometries whose shapes at their current pose meet the query: the space tests each exactly.
#pragma once

#include "SimpleCollisionSpace.h"

#include <utility>
#include <vector>

class Broadphase {
public:
    using EntryPair = std::pair<int, int>;
    struct PairList {
        const EntryPair* first = nullptr;
        size_t count = 0;
        const EntryPair* begin() const { return first; }
        const EntryPair* end() const { return first + count; }
        size_t size() const { return count; }
    };
    virtual ~Broadphase() = default;

    virtual PairList findPairs(const std::vector<SimpleCollisionSpace::Entry>& entries,
                               const std::vector<int>* changed) = 0;
    // Brings what queries search up to date with the geometries of all (the space's members) at their current
    // poses. entries are the space's from its last call (a geometry's SpaceState::entry names its own, if
    // that entry's g is the geometry). batch: for the queries of a batch (iCollisionQueries.h), for which it
    // may keep what is worth keeping over many queries.
    virtual void syncQueries(const std::vector<CollisionGeometry*>& all,
                             const std::vector<SimpleCollisionSpace::Entry>& entries, bool batch) = 0;
    // Geometries of all that may meet box, or the segment origin + t * dir (0 <= t <= maxT), at the poses of
    // the last syncQueries (all unchanged since), in the order of all.
    virtual void overlapCandidates(const std::vector<CollisionGeometry*>& all, const gcol::Aabb& box,
                                   std::vector<CollisionGeometry*>& out) = 0;
    virtual void rayCandidates(const std::vector<CollisionGeometry*>& all, const Vector& origin,
                               const Vector& dir, float maxT, std::vector<CollisionGeometry*>& out) = 0;
    // g is leaving the space (its space state still names its proxy).
    virtual void forget(CollisionGeometry* g) = 0;
    // The space's length units per metre (iCollisionSpaceScale.h), for a broadphase with a margin.
    virtual void setLengthUnit(float) {}
};
