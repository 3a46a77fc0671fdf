// DeterminismTest.cpp - the same scene gives the same bits: twice in one process, and against a hash
// committed here, so that a change to the solver's arithmetic shows in review (Box2D's test_determinism.c
// does the same). The reference scenes use the whole path a game takes: contacts, friction, restitution,
// sleeping, spheres shot with ApplyImpulse (the continuous stage) and ReferenceGame's scene code.
//
// When a commit changes the arithmetic on purpose, update kShootingHash / kBoxPileHash with the values
// this test prints, and say in the commit message why the results changed.
#include "SceneFixture.h"

#include "Scenes.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace resolution_test;

namespace {

// ReferenceGame's shooting gallery (40 boxes, a sphere shot every so often) for 600 steps.
unsigned long long shootingGallery() {
    SceneFixture f(4); // the default iterations
    const SceneSpec* spec = findScene("shooting");
    spec->build(*f.world);
    for (int frame = 0; frame < 600; ++frame) f.steps(1, [&] { spec->act(*f.world, frame); });
    return f.stateHash();
}

// 60 randomly turned boxes dropped into a pile, 480 steps.
unsigned long long boxPile() {
    SceneFixture f(4);
    buildBoxPile(*f.world, 60, 5);
    f.steps(480);
    return f.stateHash();
}

// The committed results: g++ and clang++ (x86-64, Debian 12) agree, in every build type: SSE2 arithmetic,
// no FMA contraction (-ffp-contract=off), and scene code that draws its random numbers in a stated order.
// The double build (GUARDIAN_DOUBLE, tests/double) has its own.
#if defined(GUARDIAN_DOUBLE) && GUARDIAN_DOUBLE
constexpr unsigned long long kShootingHash = 0x45f99e6e3bbc07ccull;
constexpr unsigned long long kBoxPileHash = 0xc44f423a28312aafull;
#else
constexpr unsigned long long kShootingHash = 0x3d9877a438034331ull;
constexpr unsigned long long kBoxPileHash = 0xe73d1409b81ec59full;
#endif

} // namespace

TEST(Determinism, TwoRunsOfTheSameSceneAreBitIdentical) {
    auto run = [] {
        SceneFixture f;
        buildBallPit(*f.world, 60, 11);
        f.steps(600);
        return f.stateHash();
    };
    unsigned long long first = run(), second = run();
    EXPECT_EQ(first, second);
}

TEST(Determinism, ReferenceScenesMatchTheCommittedHashes) {
    const unsigned long long shooting = shootingGallery(), pile = boxPile();
    std::printf("shooting gallery 0x%016llx, box pile 0x%016llx\n", shooting, pile);
    EXPECT_EQ(shooting, kShootingHash)
        << "the shooting gallery's final state changed (see the file's comment)";
    EXPECT_EQ(pile, kBoxPileHash) << "the box pile's final state changed (see the file's comment)";
}
