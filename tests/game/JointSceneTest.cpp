// JointSceneTest.cpp - the joint scenes (ReferenceGame/JointScenes.h) run as the game runs them, watched
// every physics step, against what physics says: the cradle on strings sends out as many balls as were
// released at the speed of the fall, a hinge chain does not stretch, a motorised door stays within its
// hinge's limits against motor and impact, a ragdoll comes to rest on the floor with its joints together,
// and a wrecking ball swings through a wall of boxes on its light chain.
#include "SceneProbe.h"

#include "JointScenes.h"
#include "iHingeJoint.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

using namespace game_test;

namespace {

float speedOf(const iPhysicsFrame* f) { return length(f->getDynamics()->velocity); }
float stepOf(const World& w) { return 1.0f / float(settingsOf(w.scene())->getStepRate()); }

// The y of the lowest corner of every box of w (the boxes' own faces, not their centres).
float lowestBoxCorner(const World& w) {
    float lowest = 1e9f;
    for (const World::Shape& s : w.shapes()) {
        if (s.kind != World::Shape::Box) continue;
        const RBDynamics& d = *w.bodies()[size_t(s.body)]->getDynamics();
        for (int c = 0; c < 8; ++c) {
            const Vector corner(c & 1 ? s.size.x : -s.size.x, c & 2 ? s.size.y : -s.size.y,
                                c & 4 ? s.size.z : -s.size.z);
            lowest = std::min(lowest, (d.getWorldOrigin() + corner * d.getWorldOrientation()).y);
        }
    }
    return lowest;
}

// The cradle on strings with `released` balls let go from the raise h: each reaches the row at sqrt(2 g h)
// (energy; within 2 %), and in the swing after the impacts exactly the last `released` balls rise beyond
// the row by more than h / 2 (by energy, a ball leaving at v rises v^2 / 2g: h if the row passes the
// speed on, at most a quarter of h if it leaves at half of it), while the others stay nearly still.
void checkCradle(const char* scene, int released) {
    SCOPED_TRACE(scene);
    size_t n = 0;
    float g = 0, h = 0, dt = 0, restY = 0, spacing = 0;
    std::vector<float> restX, impactSpeed, farRise, stray, straySpeed;
    long exchange = -1, last = 0;
    const RunStatus status = runProbed(scene, 120, [&](const World& w, long step) {
        const auto& b = w.bodies();
        if (step == 0) {
            n = b.size();
            g = gravityOf(w);
            dt = stepOf(w);
            // The balls left hanging mark the row: the last two give its rest height and spacing.
            restY = b[n - 1]->getDynamics()->position.y;
            spacing = b[n - 1]->getDynamics()->position.x - b[n - 2]->getDynamics()->position.x;
            h = b[0]->getDynamics()->position.y - restY;
            for (size_t i = 0; i < n; ++i)
                restX.push_back(b[n - 1]->getDynamics()->position.x - spacing * float(n - 1 - i));
            impactSpeed.assign(n, 0);
            farRise.assign(n, 0);
            stray.assign(n, 0);
            straySpeed.assign(n, 0);
        }
        last = step;
        const float v = std::sqrt(2 * g * h);
        if (exchange < 0) {
            // The impacts start when a ball of the row moves: until then, the released balls' speeds.
            for (size_t i = size_t(released); i < n; ++i)
                if (speedOf(b[i]) > 0.05f * v) exchange = step;
            if (exchange < 0)
                for (size_t i = 0; i < size_t(released); ++i) impactSpeed[i] = speedOf(b[i]);
            return;
        }
        // The swing out and back takes half a period (over 1 s for a 1 m string): 0.8 s sees the leaving
        // balls' peaks before they return. The others are judged from 0.1 s on, once the impacts are done.
        const float since = float(step - exchange) * dt;
        if (since > 0.8f) return;
        for (size_t i = 0; i < n; ++i) {
            const Vector p = b[i]->getDynamics()->position;
            if (p.x > restX[i]) farRise[i] = std::max(farRise[i], p.y - restY);
            if (since > 0.1f) {
                stray[i] = std::max(stray[i], length(p - Vector(restX[i], restY, p.z)));
                straySpeed[i] = std::max(straySpeed[i], speedOf(b[i]));
            }
        }
    });
    ASSERT_EQ(status, RUN_OK);
    ASSERT_EQ(n, 5u);
    EXPECT_NEAR(h, kCradleRaise, 1e-4f);
    ASSERT_GT(exchange, 0);
    ASSERT_GT(float(last - exchange) * dt, 0.8f); // the run saw the whole window
    const float v = std::sqrt(2 * g * h);
    for (int i = 0; i < released; ++i) {
        EXPECT_NEAR(impactSpeed[size_t(i)] / v, 1.0f, 0.02f)
            << "ball " << i << ": " << impactSpeed[size_t(i)];
        ::testing::Test::RecordProperty("impact_speed_" + std::to_string(i),
                                        std::to_string(impactSpeed[size_t(i)]));
        std::printf("%s ball %d: %.4f m/s at the row (sqrt(2 g h) = %.4f)\n", scene, i,
                    impactSpeed[size_t(i)], v);
    }
    int out = 0;
    for (size_t i = 0; i < n; ++i) {
        const bool leaves = i >= n - size_t(released);
        out += farRise[i] > 0.5f * h;
        if (leaves)
            EXPECT_GT(farRise[i], 0.5f * h) << "ball " << i << " should swing out";
        else // nearly still: it took under 1 % of a released ball's energy (a tenth of its speed) at any time
            EXPECT_LT(straySpeed[i], 0.1f * v) << "ball " << i << " should stay";
        std::printf("%s ball %zu: rise beyond the row %.4f m, off its rest place %.4f m at up to %.4f m/s "
                    "(impact speed %.4f)\n",
                    scene, i, farRise[i], stray[i], straySpeed[i], v);
    }
    EXPECT_EQ(out, released);
}

} // namespace

TEST(JointScenes, CradleOnStringsSendsOutOneBallForOne) { checkCradle("cradle-strings", 1); }
TEST(JointScenes, CradleOnStringsSendsOutTwoBallsForTwo) { checkCradle("cradle-strings-2", 2); }
TEST(JointScenes, CradleOnStringsSendsOutThreeBallsForThree) { checkCradle("cradle-strings-3", 3); }

// 20 links on hinges, kicked: no hinge's two anchors part by 1 % of a link's length at any step, and the
// chain from its pin to the last link's end is never 1 % longer than its links end to end.
TEST(JointScenes, HingeChainHoldsTogetherWhileItSwings) {
    float pitch = 0, length0 = 0, worstGap = 0, worstStretch = 0, swing = 0;
    size_t links = 0, joints = 0;
    Vector top, bottomAnchor; // the pin (world) and the last link's hinge (in its frame)
    const RunStatus status = runProbed("hinge-chain", 180, [&](const World& w, long step) {
        const RBDynamics& last = *w.named("bottom")->getDynamics();
        if (step == 0) {
            links = w.bodies().size();
            joints = w.joints().size();
            for (const iJoint* j : w.joints()) {
                if (!j->getBodyB()) top = j->getLocalAnchorB(); // the world's: world coordinates
                if (j->getBodyA() == w.named("bottom")->getRB()) bottomAnchor = j->getLocalAnchorA();
            }
        }
        // The end of the last link: its hinge mirrored through its centre.
        const Vector end = 2 * last.position - worldPoint(w.named("bottom")->getRB(), bottomAnchor);
        if (step == 0) { // as built, hanging straight: the chain's length, and a link's hinge to hinge
            length0 = length(end - top);
            pitch = length0 / float(links);
        }
        for (const iJoint* j : w.joints()) worstGap = std::max(worstGap, anchorGap(j));
        worstStretch = std::max(worstStretch, length(end - top) / length0 - 1);
        swing = std::max(swing, std::fabs(end.x - top.x));
    });
    ASSERT_EQ(status, RUN_OK);
    ASSERT_EQ(links, 20u);
    ASSERT_EQ(joints, 20u);
    EXPECT_LT(worstGap, 0.01f * pitch);
    EXPECT_LT(worstStretch, 0.01f);
    EXPECT_GT(swing, pitch); // it did swing
    std::printf("hinge-chain: worst anchor gap %.5f m (link %.3f m), worst stretch %.4f %%, swing %.3f m\n",
                worstGap, pitch, 100 * worstStretch, swing);
}

// The door's motor drives it open at kDoorMotorSpeed into its stop at kDoorOpen and keeps pushing; a ball
// thrown at it pushes the same way. The hinge angle stays within [closed, open] +- 0.01 rad at every step,
// and the door ends at rest at the open stop.
TEST(JointScenes, DoorStaysWithinItsHingeLimitsAgainstMotorAndBall) {
    float lowest = 1e9f, highest = -1e9f, endAngle = 0, endSpeed = 0, thrown = 0, slowest = 1e9f;
    Vector aim;
    const iHingeJoint* hinge = nullptr;
    long throwStep = -1;
    const RunStatus status = runProbed("door", 300, [&](const World& w, long step) {
        ASSERT_EQ(w.joints().size(), 1u);
        hinge = dynamic_cast<const iHingeJoint*>(w.joints().front());
        ASSERT_NE(hinge, nullptr);
        lowest = std::min(lowest, hinge->getAngle());
        highest = std::max(highest, hinge->getAngle());
        endAngle = hinge->getAngle();
        endSpeed = hinge->getSpeed();
        // The ball: did it hit the door (lose more than half its speed along its throw within 0.5 s)?
        if (const iPhysicsFrame* ball = w.named("ball")) {
            const Vector v = ball->getDynamics()->velocity;
            if (throwStep < 0) {
                throwStep = step;
                thrown = length(v);
                aim = normal(v);
            } else if (float(step - throwStep) * stepOf(w) < 0.5f) {
                slowest = std::min(slowest, dot(v, aim));
            }
        }
    });
    ASSERT_EQ(status, RUN_OK);
    EXPECT_GT(lowest, kDoorClosed - 0.01f);
    EXPECT_LT(highest, kDoorOpen + 0.01f);
    EXPECT_NEAR(endAngle, kDoorOpen, 0.01f);
    EXPECT_NEAR(endSpeed, 0.0f, 0.01f);
    ASSERT_GE(throwStep, 0);
    EXPECT_LT(slowest, 0.5f * thrown);
    std::printf("door: angle in [%.5f, %.5f] rad (limits [%.2f, %.2f]), ends at %.5f rad, %.5f rad/s; ball "
                "thrown at %.2f m/s, slowest along its throw %.3f m/s\n",
                lowest, highest, kDoorClosed, kDoorOpen, endAngle, endSpeed, thrown, slowest);
}

// The ragdoll run as the game runs it for 480 frames (7.7 s), watched every step.
struct RagdollRun {
    RunStatus status = RUN_BAD_ARGUMENTS;
    size_t joints = 0;
    bool finite = true;
    float restedAt = -1;                     // s: from then on every body asleep or under 0.05 m/s
    float worstGap = 0, lowest = 1e9f;       // at any step
    float restingGap = 0, restingLow = 1e9f; // once at rest
    long worstGapStep = -1, lowestStep = -1;
};

const RagdollRun& ragdollRun() {
    static RagdollRun r = [] {
        RagdollRun run;
        run.status = runProbed("ragdoll", 480, [&run](const World& w, long step) {
            run.joints = w.joints().size();
            float gap = 0;
            for (const iJoint* j : w.joints()) gap = std::max(gap, anchorGap(j));
            const float low = lowestBoxCorner(w);
            if (gap > run.worstGap) run.worstGap = gap, run.worstGapStep = step;
            if (low < run.lowest) run.lowest = low, run.lowestStep = step;
            run.finite = run.finite && w.allFinite();
            bool still = true; // the sleep speed (iPhysicsSceneSettings.h)
            for (const iPhysicsFrame* f : w.bodies())
                still = still && (f->getDynamics()->sleeping || speedOf(f) < 0.05f);
            if (!still) {
                run.restedAt = -1;
                run.restingGap = 0;
                run.restingLow = 1e9f;
            } else {
                if (run.restedAt < 0) run.restedAt = float(step) * stepOf(w);
                run.restingGap = std::max(run.restingGap, gap);
                run.restingLow = std::min(run.restingLow, low);
            }
        });
        std::printf(
            "ragdoll: worst anchor gap %.5f m (step %ld), lowest corner %.5f m (step %ld); at rest from "
            "%.2f s with gaps up to %.5f m, lowest corner %.5f m\n",
            run.worstGap, run.worstGapStep, run.lowest, run.lowestStep, run.restedAt, run.restingGap,
            run.restingLow);
        return run;
    }();
    return r;
}

// Dropped on the floor, the ragdoll comes to rest (every body asleep or under the sleep speed, 0.05 m/s)
// within 5 s and stays so, every state finite; at rest its joints' anchors are within 1 cm of each other and
// no box corner is more than 1 cm below the floor.
TEST(JointScenes, RagdollComesToRestOnTheFloorWithItsJointsTogether) {
    const RagdollRun& r = ragdollRun();
    ASSERT_EQ(r.status, RUN_OK);
    EXPECT_EQ(r.joints, 9u); // neck, shoulders, hips; elbows, knees
    EXPECT_TRUE(r.finite);
    EXPECT_GE(r.restedAt, 0.0f);
    EXPECT_LT(r.restedAt, 5.0f);
    EXPECT_LT(r.restingGap, 0.01f);
    EXPECT_GT(r.restingLow, -0.01f);
}

// A known limit (README, "Known limits"): the truth is the same at every step of the fall; measured at 60 Hz,
// anchors 0.4 cm apart and a corner 3.4 cm below the floor for a few steps as the limbs land (the impact's
// impulses through the joints converge slowly). Before the step closed the joints of what its projection and
// continuous stage move alone (JointClosing.h), 5.2 cm and 2.6 cm (this one run is chaotic: the twelve
// thrown ragdolls below tell the trend). Asserted: the measured bound, so a regression shows.
TEST(JointScenes, RagdollJointsStayWithinTheKnownBoundAtEveryStep) {
    const RagdollRun& r = ragdollRun();
    ASSERT_EQ(r.status, RUN_OK);
    EXPECT_LT(r.worstGap, 0.015f);
    EXPECT_GT(r.lowest, -0.04f);
    RecordProperty("worst_gap", std::to_string(r.worstGap));
    RecordProperty("lowest_corner", std::to_string(r.lowest));
}

// The ragdoll thrown from twelve starts (every body given the same velocity: along x and z up to 2 m/s, down
// up to 3 m/s; seeds 1 to 12), so that it lands a different way each time (one run is chaotic: a change
// anywhere in the solver moves its worst step): per start, the widest any joint's anchors are apart at any
// step over 4 s, and the lowest box corner. Measured: anchors 1.1 cm apart at the median start, 1.6 cm at the
// worst; corners 2.9 and 6.4 cm below the floor (g++; clang's AVX build: 1.3 and 2.9 cm, 3.1 and 6.4). Before
// the step closed the joints of what its projection and continuous stage move alone (JointClosing.h): 8.6
// and 13.7 cm apart, 3.2 and 8.6 cm below. Asserted: those measured bounds, with room for the spread
// (compilers differ here: a different rounding anywhere lands a ragdoll another way). The lowest corner of
// the worst start is a tail: over starts 1 to 60 the worst was 8.7 cm (g++) and 6.4 cm (clang AVX) before
// 4ba9f54, 9.4 and 8.5 cm after it (the medians 3.1-3.4 cm throughout). With the normal rows solved in
// their speeds (ContactBlocks::solve; same sweep, other rounding) start 5 sinks a corner 13.2 cm on g++ (8.5
// on clang AVX), and over the 60 starts the two solves are alike: medians 3.4 cm with it and 3.3 before, the
// speed form deeper in 21 of 60 paired starts (rank test z = -0.5), the next worst 8.7 / 7.4 cm with it and
// 7.4 / 6.5 before. The worst of twelve is a draw from that tail: held to 15 cm. Anchors over the 60:
// median 1.2 cm, worst 3.7 (g++) and 5.4 cm (clang AVX); the twelve's worst 2.9 and 3.3.
namespace {
int gThrowSeed = 0;
void buildThrownRagdoll(World& w) {
    buildRagdoll(w);
    std::mt19937 rng{unsigned(gThrowSeed)};
    std::uniform_real_distribution<float> across(-2.0f, 2.0f), down(-3.0f, 0.0f);
    const Vector v(across(rng), down(rng), across(rng));
    for (iPhysicsFrame* f : w.bodies()) f->getDynamics()->velocity = v;
}
} // namespace

TEST(JointScenes, RagdollThrownFromTwelveStartsKeepsItsJointsWithinTheKnownBound) {
    static const bool registered =
        registerScene({"ragdoll-thrown", "the ragdoll thrown (tests)", buildThrownRagdoll, nullptr});
    ASSERT_TRUE(registered);
    std::vector<float> gaps, lows;
    for (gThrowSeed = 1; gThrowSeed <= 12; ++gThrowSeed) {
        float gap = 0, low = 1e9f;
        ASSERT_EQ(runProbed("ragdoll-thrown", 240,
                            [&](const World& w, long) {
                                for (const iJoint* j : w.joints()) gap = std::max(gap, anchorGap(j));
                                low = std::min(low, lowestBoxCorner(w));
                            }),
                  RUN_OK);
        gaps.push_back(gap);
        lows.push_back(low);
    }
    std::vector<float> g = gaps, l = lows;
    std::sort(g.begin(), g.end());
    std::sort(l.begin(), l.end());
    std::printf(
        "ragdoll thrown, 12 starts: worst anchor gap median %.4f m, worst %.4f m; lowest corner median "
        "%.4f m, lowest %.4f m\n",
        0.5f * (g[5] + g[6]), g.back(), 0.5f * (l[5] + l[6]), l.front());
    for (size_t i = 0; i < gaps.size(); ++i)
        std::printf("  start %zu: gap %.4f m, lowest %.4f m\n", i + 1, gaps[i], lows[i]);
    EXPECT_LT(0.5f * (g[5] + g[6]), 0.02f);
    EXPECT_LT(g.back(), 0.04f);
    EXPECT_GT(0.5f * (l[5] + l[6]), -0.045f);
    EXPECT_GT(l.front(), -0.15f);
}

// The wrecking ball (500 kg on ten 0.5 kg links, let go 60 degrees out) swings through the wall of boxes at
// the bottom of its swing: at no step is it further from the pivot than the chain and its radius, 4.4 m, by
// 1 % (tethers: without, the links stretched 36 % hanging still); it comes out beyond the wall (x > 2 m: the
// boxes did not stop it, as they did when shock propagation took them for a floor under it) and knocks at
// least ten of the 25 boxes 0.5 m or more from where they stood. The links struck by 10 kg boxes while the
// ball pulls on them part at their joints during the hit (a known limit, README: measured 3.9 cm of a 0.4 m
// link, asserted under a fifth of a link), and are together again after it: from 1 s after the hit (step
// 100) within 2 % of a link (measured 4.5 mm).
TEST(JointScenes, WreckingBallSwingsThroughTheWallOnItsChain) {
    const float reach = kWreckPitch * float(kWreckLinks) + kWreckRadius;
    float worstStretch = 0, worstGap = 0, gapAfter = 0, furthest = -1e9f;
    std::vector<Vector> start;
    size_t knocked = 0, boxes = 0;
    const RunStatus status = runProbed("wrecking-ball", 180, [&](const World& w, long step) {
        const RBDynamics& ball = *w.named("ball")->getDynamics();
        worstStretch = std::max(worstStretch, length(ball.position - kWreckPivot) / reach - 1);
        for (const iJoint* j : w.joints()) {
            worstGap = std::max(worstGap, anchorGap(j));
            if (step >= 100) gapAfter = std::max(gapAfter, anchorGap(j));
        }
        furthest = std::max(furthest, ball.position.x);
        // The wall's boxes: the bodies after the links and the ball.
        const size_t first = size_t(kWreckLinks) + 1;
        boxes = w.bodies().size() - first;
        if (step == 0)
            for (size_t i = first; i < w.bodies().size(); ++i)
                start.push_back(w.bodies()[i]->getDynamics()->position);
        knocked = 0;
        for (size_t i = first; i < w.bodies().size(); ++i)
            if (length(w.bodies()[i]->getDynamics()->position - start[i - first]) > 0.5f) ++knocked;
    });
    ASSERT_EQ(status, RUN_OK);
    ASSERT_EQ(boxes, size_t(kWreckWallBoxes));
    EXPECT_LT(worstStretch, 0.01f);
    EXPECT_LT(worstGap, 0.2f * kWreckPitch);
    EXPECT_LT(gapAfter, 0.02f * kWreckPitch);
    EXPECT_GT(furthest, 2.0f);
    EXPECT_GE(knocked, 10u);
    std::printf(
        "wrecking-ball: worst stretch %.4f %%, worst anchor gap %.4f m (%.4f m after the hit), furthest "
        "x %.2f m, %zu of %zu boxes knocked over 0.5 m\n",
        100 * worstStretch, worstGap, gapAfter, furthest, knocked, boxes);
}
