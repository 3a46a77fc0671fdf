// SweepAndPrune.h - the simple space's broadphase: every call sorts the entries' boxes along x and sweeps
// (nothing is kept between calls); planes meet every bounded entry, and come first, so that when the
// contact budget fills the ground is the last thing lost. Queries consider every geometry.
#pragma once

#include "Broadphase.h"

class SweepAndPrune final : public Broadphase {
public:
    void findPairs(const std::vector<SimpleCollisionSpace::Entry>& entries,
                   std::vector<EntryPair>& out) override;
    void overlapCandidates(const std::vector<CollisionGeometry*>& all, const gcol::Aabb& box,
                           std::vector<CollisionGeometry*>& out) override;
    void rayCandidates(const std::vector<CollisionGeometry*>& all, const Vector& origin, const Vector& dir,
                       float maxT, std::vector<CollisionGeometry*>& out) override;
    void forget(CollisionGeometry*) override {}

private:
    std::vector<int> m_order, m_planes;
};
