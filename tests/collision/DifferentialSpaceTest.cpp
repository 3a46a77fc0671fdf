// DifferentialSpaceTest.cpp - every space against brute force (SpaceDifferential.h) on random scenes, and
// the octree space against the simple space over many calls with moves, teleports, sleeping, fixing, adds
// and removes between them.
#include "SimpleCollisionSpace.h"
#include "SpaceDifferential.h"
#include "iOctreeCollisionSpace.h"
#include "iSimpleCollisionSpace.h"

namespace {
iCollisionSpace* makeSimple() { return CreateSimpleCollisionSpace(); }
iCollisionSpace* makeOctree() { return CreateOctreeCollisionSpace(); }
using spacediff::Scene;

void allScenes(iCollisionSpace* (*make)(), float moveBy = 0.0f) {
    for (Scene scene : {Scene::Sparse, Scene::Dense, Scene::Mixed, Scene::MostlyFixed})
        for (unsigned seed = 1; seed <= 5; ++seed)
            spacediff::checkAgainstBruteForce(make, scene, seed, 300, moveBy);
}
} // namespace

TEST(DifferentialSpace, SimpleSparse) {
    for (unsigned seed = 1; seed <= 5; ++seed)
        spacediff::checkAgainstBruteForce(makeSimple, spacediff::Scene::Sparse, seed, 300);
}
TEST(DifferentialSpace, SimpleDense) {
    for (unsigned seed = 1; seed <= 5; ++seed)
        spacediff::checkAgainstBruteForce(makeSimple, spacediff::Scene::Dense, seed, 300);
}
TEST(DifferentialSpace, SimpleMixed) {
    for (unsigned seed = 1; seed <= 5; ++seed)
        spacediff::checkAgainstBruteForce(makeSimple, spacediff::Scene::Mixed, seed, 300);
}
TEST(DifferentialSpace, SimpleMostlyFixed) {
    for (unsigned seed = 1; seed <= 5; ++seed)
        spacediff::checkAgainstBruteForce(makeSimple, spacediff::Scene::MostlyFixed, seed, 300);
}
TEST(DifferentialSpace, SimpleWithoutSampling) {
    auto make = [] { return CreateSimpleCollisionSpace(0); };
    spacediff::checkAgainstBruteForce(make, spacediff::Scene::Dense, 9, 300);
}
TEST(DifferentialSpace, SimpleMovingWithSampling) {
    for (unsigned seed = 1; seed <= 5; ++seed)
        spacediff::checkAgainstBruteForce(makeSimple, spacediff::Scene::Dense, seed, 300, 2.0f);
}

TEST(DifferentialSpace, OctreeEveryScene) { allScenes(makeOctree); }
TEST(DifferentialSpace, OctreeWithoutSampling) {
    auto make = [] { return CreateOctreeCollisionSpace(0); };
    spacediff::checkAgainstBruteForce(make, spacediff::Scene::Dense, 9, 300);
}
TEST(DifferentialSpace, OctreeMovingWithSampling) {
    for (unsigned seed = 1; seed <= 5; ++seed)
        spacediff::checkAgainstBruteForce(makeOctree, spacediff::Scene::Dense, seed, 300, 2.0f);
}
// The octree space beside the simple one: 60 calls per scene, something changing between most of them.
TEST(DifferentialSpace, OctreeEqualsSimpleOverManyCalls) {
    for (Scene scene : {Scene::Sparse, Scene::Dense, Scene::Mixed, Scene::MostlyFixed})
        for (unsigned seed = 1; seed <= 3; ++seed)
            spacediff::checkAgainstReference(makeOctree, makeSimple, scene, seed, 200, 60);
}
TEST(DifferentialSpace, OctreeEqualsSimpleWithoutSampling) {
    auto make = [] { return CreateOctreeCollisionSpace(0); };
    auto reference = [] { return CreateSimpleCollisionSpace(0); };
    spacediff::checkAgainstReference(make, reference, Scene::Dense, 4, 200, 40);
}
// A space whose entries mirror their geometries (a call reads a geometry only when an edit reached it or its
// body moved and its shapes are not simply at the body's origin: SpaceGather.cpp) beside one that reads every
// geometry every call, over calls with moves, teleports, sleeping, fixing, adds, removes, filters, rebinds,
// resizes and deleted bodies.
TEST(DifferentialSpace, MirroredEntriesEqualReadingEveryGeometry) {
    auto reading = [](iCollisionSpace* s) {
        dynamic_cast<SimpleCollisionSpace&>(*s).setGeometryMirrors(false);
        return s;
    };
    auto simpleReading = [&] { return reading(CreateSimpleCollisionSpace()); };
    auto octreeReading = [&] { return reading(CreateOctreeCollisionSpace()); };
    for (Scene scene : {Scene::Sparse, Scene::Dense, Scene::Mixed, Scene::MostlyFixed})
        for (unsigned seed = 1; seed <= 3; ++seed) {
            spacediff::checkAgainstReference(makeSimple, simpleReading, scene, seed, 150, 60, true, true);
            spacediff::checkAgainstReference(makeOctree, octreeReading, scene, seed, 150, 60, true, true);
        }
    auto withoutSampling = [] { return CreateSimpleCollisionSpace(0); };
    auto readingWithoutSampling = [&] { return reading(CreateSimpleCollisionSpace(0)); };
    spacediff::checkAgainstReference(withoutSampling, readingWithoutSampling, Scene::Dense, 4, 150, 60, true,
                                     true);
}

// The simple space answering every other call's queries in a batch (boxes kept from the batch's start, exact
// tests only where a query meets one) beside itself answering every query by brute force.
TEST(DifferentialSpace, SimpleBatchedQueriesEqualBruteForce) {
    for (Scene scene : {Scene::Sparse, Scene::Dense, Scene::Mixed, Scene::MostlyFixed})
        spacediff::checkAgainstReference(makeSimple, makeSimple, scene, 2, 200, 30);
}
