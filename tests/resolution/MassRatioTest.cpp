// MassRatioTest.cpp - heavy boxes resting on light ones (issue 11 item 6): the top box stays within 5 cm of
// its resting height over 5 s, and equal masses are left as they were.
#include "SceneFixture.h"

#include "Scenes.h"
#include "iPhysicsSceneStats.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace resolution_test;

namespace {

// A unit box of 1 kg on the floor and one of `ratio` kg on it; returns how far the top box's centre strayed
// from its resting height (1.5 m) over `seconds`.
float heavyOnLight(float ratio, int iterations, float seconds) {
    SceneFixture f(iterations);
    f.world->ground();
    f.world->box(Vector(0, 0.5f, 0), Vector(0.5f, 0.5f, 0.5f), 1.0f);
    RBDynamics* heavy = f.world->box(Vector(0, 1.5f, 0), Vector(0.5f, 0.5f, 0.5f), ratio)->getDynamics();
    float worst = 0;
    f.seconds(seconds, [&] { worst = std::max(worst, (heavy->position - Vector(0, 1.5f, 0)).length()); });
    return worst;
}

} // namespace

TEST(MassRatio, OneTonneOnOneKilogramHoldsAtTheDefaultIterations) {
    // 1:10^3 at the default 4 iterations: within 5 cm of resting height for 5 s. Before shock propagation
    // it sank 1.05 m, through the light box; measured after: 3.9 mm. This is the aligned stack only: set 1 um
    // off, the heavy box walks sideways up to 121 mm (README, Known limits), which no test asserts yet.
    const float strayed = heavyOnLight(1000.0f, 4, 5.0f);
    EXPECT_LT(strayed, 0.05f);
    RecordProperty("strayed_m", std::to_string(strayed));
}

TEST(MassRatio, TenTonnesOnOneKilogramHoldsAtSixteenIterations) {
    // 1:10^4 at 16 iterations (the README's setting): within 5 cm for 5 s. Measured 1.3 cm (7.8 cm at the
    // default 4, 3.7 cm at 8); before: 1.0 m at every count up to 64.
    const float strayed = heavyOnLight(10000.0f, 16, 5.0f);
    EXPECT_LT(strayed, 0.05f);
    RecordProperty("strayed_m", std::to_string(strayed));
}

TEST(MassRatio, AnEqualMassPyramidStillFallsAsleep) {
    // Shock propagation acts only under a body at least 10 times heavier: the 210 equal boxes are solved as
    // before and the pyramid sleeps within 4 s (with the pass everywhere it jittered awake for 10 s).
    SceneFixture f(10);
    buildPyramid(*f.world, 20);
    f.seconds(4.0f);
    EXPECT_EQ(statsOf(f.scene)->getAwakeBodyCount(), 0u);
}
