// MassRatioTest.cpp - heavy boxes resting on light ones (issue 11 item 6): the top box stays near its resting
// place over 5 s from starts 1 um apart, equal masses are left as they were, and a heavy body hitting light
// ones from the side is not stopped as if by a floor.
#include "SceneFixture.h"

#include "Scenes.h"
#include "iPhysicsSceneStats.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace resolution_test;

namespace {

// A unit box of 1 kg on the floor and one of `ratio` kg on it; returns how far the top box's centre strayed
// from its resting height (1.5 m) over `seconds`. Start 0 is the stack as built; each later start moves both
// boxes up to 1 um in x and z (jitterStart): the stray is chaotic, and an aligned stack hides it. awake: the
// bodies still awake at the end (sleeping is on: the default).
float heavyOnLight(float ratio, int iterations, float seconds, unsigned start, size_t* awake = nullptr) {
    SceneFixture f(iterations);
    f.world->ground();
    f.world->box(Vector(0, 0.5f, 0), Vector(0.5f, 0.5f, 0.5f), 1.0f);
    RBDynamics* heavy = f.world->box(Vector(0, 1.5f, 0), Vector(0.5f, 0.5f, 0.5f), ratio)->getDynamics();
    if (start > 0) jitterStart(*f.world, start);
    float worst = 0;
    f.seconds(seconds, [&] { worst = std::max(worst, (heavy->position - Vector(0, 1.5f, 0)).length()); });
    if (awake) *awake = statsOf(f.scene)->getAwakeBodyCount();
    return worst;
}

// The strays of `starts` starts, smallest first.
std::vector<float> strays(float ratio, int iterations, unsigned starts) {
    std::vector<float> v;
    for (unsigned start = 0; start < starts; ++start)
        v.push_back(heavyOnLight(ratio, iterations, 5.0f, start));
    std::sort(v.begin(), v.end());
    return v;
}

} // namespace

// 1:10^3 and 1:10^4 at the default 4 iterations: the heavy box stays within 2 cm of its resting place for
// 5 s from every one of eight starts, and within 1 cm in the median. Before shock propagation it sank 1.05 m,
// through the light box. Before the contact's stiffness followed its load (ContactSolver::contactSoftness)
// the light box gave under the heavy one as a spring of its own mass (69 mm at 1:10^3) and the pair walked
// sideways: 1:10^3 strayed 4-121 mm over such starts (median 57), 1:10^4 5-203 mm. Measured after: at most
// 8.1 mm and 5.3 mm; since the push out has no friction rows (96667a9), 5.6 mm and 6.9 mm.
TEST(MassRatio, HeavyOnLightHoldsFromEveryStartAtTheDefaultIterations) {
    for (float ratio : {1000.0f, 10000.0f}) {
        const std::vector<float> v = strays(ratio, 4, 8);
        EXPECT_LT(v.back(), 0.02f) << "1:" << ratio << ", the worst start";
        EXPECT_LT(v[v.size() / 2], 0.01f) << "1:" << ratio << ", the median start";
        RecordProperty("strayed_m_worst_1_to_" + std::to_string(int(ratio)), std::to_string(v.back()));
    }
}

// The 5 s above are not the whole story: kept awake (sleeping off, or an island something keeps moving) the
// pair walks, the heavy box sideways on the light one (README Known limits: 1:10^3 about 0.1 m in 40 s and
// off the light box within 160 s, 1:10^4 off within 20 s, from the centred start). At the defaults the pair
// falls asleep first and stays: from eight starts, 1:10^3 and 1:10^4 at the default 4 iterations with
// sleeping on, the heavy box within 2 cm of its resting place for a minute (measured 2.7-10.6 mm) and both
// boxes asleep at its end.
TEST(MassRatio, HeavyOnLightAtTheDefaultsFallsAsleepAndStaysForAMinute) {
    for (float ratio : {1000.0f, 10000.0f})
        for (unsigned start = 0; start < 8; ++start) {
            size_t awake = 0;
            const float worst = heavyOnLight(ratio, 4, 60.0f, start, &awake);
            EXPECT_LT(worst, 0.02f) << "1:" << ratio << ", start " << start;
            EXPECT_EQ(awake, 0u) << "1:" << ratio << ", start " << start;
            std::printf("[ measured ] 1:%g start %u: strayed %.2f mm in 60 s, awake %zu\n", ratio, start,
                        1000 * worst, awake);
        }
}

TEST(MassRatio, TenTonnesOnOneKilogramHoldsAtSixteenIterations) {
    // 1:10^4 at 16 iterations: the median of five starts within 5 cm for 5 s (before: 1.0 m at every count up
    // to 64 without shock propagation; 8-196 mm over eight starts before the load-following stiffness; 6-20
    // mm after: more sub-steps hold this pair less well than the default, README Known limits).
    const std::vector<float> v = strays(10000.0f, 16, 5);
    EXPECT_LT(v[v.size() / 2], 0.05f);
    RecordProperty("strayed_m_median", std::to_string(v[v.size() / 2]));
}

TEST(MassRatio, AnEqualMassPyramidStillFallsAsleep) {
    // Shock propagation acts only under a body at least 10 times heavier: the 210 equal boxes are solved as
    // before and the pyramid sleeps within 4 s (with the pass everywhere it jittered awake for 10 s).
    SceneFixture f(10);
    buildPyramid(*f.world, 20);
    f.seconds(4.0f);
    EXPECT_EQ(statsOf(f.scene)->getAwakeBodyCount(), 0u);
}

// Shock propagation takes a lower body for a floor only under what rests on it. A 500 kg ball (0.2 m) thrown
// level at 6 m/s into the middle of a wall of nine 10 kg boxes (0.5 m; three columns of three) on the floor
// is not resting on them: it hits the middle box as one body hits another, which by momentum and energy
// leaves it at least v (M - m) / (M + m) = 5.76 m/s (any restitution up to 1). Asserted: still 5.4 m/s along
// x 0.3 s after the hit (friction with the boxes around take a little more; measured 5.69). When the pass
// took every lower body for a floor, the wall held the ball like one: 5.01 m/s here, and in the game's
// wrecking-ball scene the ball stopped in the wall (JointScenes.WreckingBallSwingsThroughTheWallOnItsChain).
TEST(MassRatio, AHeavyBodyHittingALightStackFromTheSideKeepsGoing) {
    SceneFixture f(4);
    f.world->ground();
    for (int layer = 0; layer < 3; ++layer)
        for (int column = -1; column <= 1; ++column)
            f.world->box(Vector(0, 0.25f + 0.5f * float(layer), 0.5f * float(column)),
                         Vector(0.25f, 0.25f, 0.25f), 10.0f);
    RBDynamics* ball = f.world->sphere(Vector(-1.0f, 0.75f, 0), 0.2f, 500.0f)->getDynamics();
    ball->velocity = Vector(6.0f, 0, 0);
    f.seconds(0.4f); // the hit at about 0.09 s
    EXPECT_GT(ball->velocity.x, 5.4f);
    RecordProperty("speed_after", std::to_string(ball->velocity.x));
    std::printf("[ measured ] 500 kg ball into a stack of 10 kg boxes: %.3f m/s along x after (6 before)\n",
                ball->velocity.x);
}
