// TimeStepExtremesTest.cpp - zero and huge time steps, and bad input: update() with the same time twice
// takes no step and changes nothing; update(now + 10^6 ms) takes at most the catch-up cap, says so with
// error() and leaves every state finite; NaN and infinite input is refused with error(), not propagated.
#include "ExtremesSupport.h"

#include "Scenes.h"
#include "iPhysicsSceneStats.h"

#include <cstdio>
#include <limits>
#include <string>

using namespace extremes;
using guardian_test::ErrorRecorder;

TEST(ExtremeTimeStep, TheSameTimeTwiceTakesNoStep) {
    Bench b(4);
    buildBoxPile(*b.world, 10, 3);
    b.steps(30);
    const long long steps = statsOf(b.scene)->getStepCount();
    const Vector p = b.world->bodies()[0]->getDynamics()->position;
    b.scene->update(int(b.now));
    b.scene->update(int(b.now));
    EXPECT_EQ(statsOf(b.scene)->getStepCount(), steps);
    EXPECT_EQ(b.world->bodies()[0]->getDynamics()->position, p);
}

// 10^6 ms at once: the default cap of 8 steps is taken, the rest (59,992 steps) dropped and counted, and
// error() says so once; then the scene goes on normally.
TEST(ExtremeTimeStep, AHugeStepIsCappedAndReported) {
    ErrorRecorder errors;
    Bench b(4);
    buildBoxPile(*b.world, 10, 3);
    b.steps(30);
    const long long before = statsOf(b.scene)->getStepCount();
    b.scene->update(int(b.now) + 1000000);
    EXPECT_EQ(statsOf(b.scene)->getStepCount() - before, 8);
    EXPECT_EQ(statsOf(b.scene)->getDroppedStepCount(), 60000 - 8);
    EXPECT_EQ(errors.count(), 1u);
    EXPECT_NE(std::wstring(ErrorRecorder::last()).find(L"catch-up"), std::wstring::npos);
    EXPECT_TRUE(allFinite(*b.world));
    for (int i = 1; i <= 60; ++i) b.scene->update(int(b.now) + 1000000 + i * 17);
    EXPECT_TRUE(allFinite(*b.world));
}

// Bad input at the extremes: a NaN position, an infinite velocity, a 10^38 m/s velocity that overflows in
// the step: each is refused or undone with an error() message, and the pile stays finite.
TEST(ExtremeTimeStep, NonFiniteInputIsReportedNotPropagated) {
    const float inf = std::numeric_limits<float>::infinity();
    struct Case {
        const char* name;
        Vector position, velocity;
    };
    for (Case c : {Case{"NaN position", Vector(std::nanf(""), 1, 0), Vector()},
                   Case{"infinite velocity", Vector(0, 1, 0), Vector(inf, 0, 0)},
                   Case{"1e38 m/s", Vector(0, 1, 0), Vector(1e38f, 1e38f, 0)}}) {
        ErrorRecorder errors;
        Bench b(4);
        buildBoxPile(*b.world, 10, 3);
        b.steps(30);
        RBDynamics* d = b.world->bodies()[0]->getDynamics();
        d->position = c.position;
        d->velocity = c.velocity;
        b.steps(30);
        EXPECT_GE(errors.count(), 1u) << c.name;
        std::printf("extremes: %s: error() said: %ls\n", c.name, ErrorRecorder::last().c_str());
        EXPECT_TRUE(allFinite(*b.world)) << c.name;
    }
}
