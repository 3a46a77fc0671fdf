// DifferentialSpaceTest.cpp - the simple space against brute force (SpaceDifferential.h) on random scenes.
// A future space adds one line per scene here with its own factory.
#include "SpaceDifferential.h"
#include "iSimpleCollisionSpace.h"

namespace {
iCollisionSpace* makeSimple() { return CreateSimpleCollisionSpace(); }
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
