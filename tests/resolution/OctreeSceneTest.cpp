// OctreeSceneTest.cpp - whole simulations with the octree space as the scene's collision space behave like
// with the simple space: a pyramid and a tower rest at the same heights, body for body, within 1 mm. (The
// two spaces list the same contacts in different orders, so the solver's results differ in rounding only.)
#include "SceneFixture.h"
#include "Scenes.h"
#include "iOctreeCollisionSpace.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

using namespace resolution_test;

namespace {

std::vector<Vector> restingPositions(iCollisionSpace* space, const std::function<void(World&)>& build) {
    SceneFixture f(10, space);
    build(*f.world);
    f.seconds(5.0f);
    std::vector<Vector> out;
    for (const iPhysicsFrame* b : f.world->bodies()) out.push_back(b->getDynamics()->position);
    EXPECT_LT(f.world->kineticEnergy(), 0.01f);
    return out;
}

void sameRest(const std::function<void(World&)>& build, const char* what) {
    const std::vector<Vector> simple = restingPositions(nullptr, build);
    const std::vector<Vector> octree = restingPositions(CreateOctreeCollisionSpace(), build);
    ASSERT_EQ(simple.size(), octree.size());
    float worst = 0.0f;
    for (size_t i = 0; i < simple.size(); ++i) {
        EXPECT_NEAR(octree[i].y, simple[i].y, 0.001f) << what << " body " << i;
        worst = std::fmax(worst, (octree[i] - simple[i]).length());
    }
    ::testing::Test::RecordProperty(std::string(what) + "_worst_difference_m", std::to_string(worst));
}

} // namespace

TEST(OctreeScene, PyramidOf55RestsAtTheSameHeightsAsWithTheSimpleSpace) {
    sameRest([](World& w) { buildPyramid(w, 10); }, "pyramid");
}

TEST(OctreeScene, TowerOf10RestsAtTheSameHeightsAsWithTheSimpleSpace) {
    sameRest([](World& w) { buildTower(w, 10); }, "tower");
}
