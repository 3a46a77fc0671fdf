// SoftSceneTest.cpp - the rope and soft body scenes (ReferenceGame/JointScenes.h) run as the game runs them,
// watched every physics step: the rope bridge carries its box without a link stretching, the cloth drapes
// over the sphere instead of falling through it, and the soft blob comes to rest on the floor keeping its
// shape.
#include "SceneProbe.h"

#include "JointScenes.h"
#include "iDistanceJoint.h"
#include "iRope.h"

#include <algorithm>
#include <cmath>

using namespace game_test;

namespace {

// Every body of w (frames and parts) asleep or under the sleep speed (0.05 m/s).
bool allStill(const World& w) {
    for (const iPhysicsFrame* f : w.bodies())
        if (!f->getDynamics()->sleeping && length(f->getDynamics()->velocity) >= 0.05f) return false;
    for (const World::Part& p : w.parts())
        if (!p.body->getDynamics().sleeping && length(p.body->getDynamics().velocity) >= 0.05f) return false;
    return true;
}

} // namespace

// The rope bridge run as the game runs it for 360 frames (5.8 s), watched every step.
struct BridgeRun {
    RunStatus status = RUN_BAD_ARGUMENTS;
    int links = 0;
    bool dropped = false;
    float worstStretch = 0, lowestBox = 1e9f; // a link over its length (its maximum); the box's lowest corner
    long worstStep = -1;
};

const BridgeRun& bridgeRun() {
    static BridgeRun run = [] {
        BridgeRun r;
        r.status = runProbed("rope-bridge", 360, [&r](const World& w, long step) {
            if (w.ropes().size() != 1) return;
            const iRope* rope = w.ropes().front();
            r.links = rope->getSegmentCount() - 1;
            for (int i = 0; i < r.links; ++i) {
                const iDistanceJoint* link = rope->getLink(i);
                const float stretch = link->getLength() / link->getMaxLength() - 1;
                if (stretch > r.worstStretch) r.worstStretch = stretch, r.worstStep = step;
            }
            if (const iPhysicsFrame* box = w.named("box")) {
                r.dropped = true;
                const World::Shape& s = w.shapes().back(); // the box, the last shape built
                const RBDynamics& d = *box->getDynamics();
                // Its lowest corner: the centre less the half extents along the box's axes, seen along y
                // (row i of the orientation is local axis i in world axes).
                const Matrix m = d.getWorldOrientation();
                const float reach =
                    s.size.x * std::fabs(m.m12) + s.size.y * std::fabs(m.m22) + s.size.z * std::fabs(m.m32);
                r.lowestBox = std::min(r.lowestBox, d.position.y - reach);
            }
        });
        std::printf("rope-bridge: worst link stretch %.3f %% (step %ld), box's lowest corner %.3f m\n",
                    100 * r.worstStretch, r.worstStep, r.lowestBox);
        return r;
    }();
    return run;
}

// A rope pinned at both ends carries a 2 kg box dropped on its middle: the box never reaches the ground.
TEST(SoftScenes, RopeBridgeCarriesItsBox) {
    const BridgeRun& r = bridgeRun();
    ASSERT_EQ(r.status, RUN_OK);
    ASSERT_TRUE(r.dropped);
    EXPECT_EQ(r.links, 29);
    EXPECT_GT(r.lowestBox, 0.0f);
}

// A known limit (README, "Known limits"): the rope's links stretch under load. The truth is no stretch;
// measured at the defaults: 4.2 % under the box as it lands (3 m/s, 10 times a segment's mass; 8.4 % before
// the step closed the joints of the segments its projection pushed out of the box alone, JointClosing.h). A
// long chain of distance joints carrying a heavy load converges slowly in the sub-stepped sequential solve.
// Asserted: the measured bound, so a regression shows.
TEST(SoftScenes, RopeBridgeLinksStretchWithinTheKnownBound) {
    const BridgeRun& r = bridgeRun();
    ASSERT_EQ(r.status, RUN_OK);
    EXPECT_LT(r.worstStretch, 0.06f);
    RecordProperty("worst_stretch", std::to_string(r.worstStretch));
}

// A cloth dropped on a fixed sphere drapes over it, and stays on it: no cloth body's centre ever more than
// 1 cm inside the sphere (its own sphere overlapping by more than its radius plus 1 cm: falling through),
// and at the end its middle rests on the sphere's top.
TEST(SoftScenes, ClothDrapesOverTheSphere) {
    float worstOverlap = -1e9f, partRadius = 0, sphereRadius = 0, middleGap = 1e9f;
    size_t bodies = 0;
    const RunStatus status = runProbed("cloth", 300, [&](const World& w, long) {
        const iPhysicsFrame* sphere = w.named("sphere");
        ASSERT_NE(sphere, nullptr);
        const Vector centre = sphere->getDynamics()->position;
        sphereRadius = w.shapes().back().size.x; // the sphere, the last World shape built
        bodies = w.parts().size();
        middleGap = 1e9f;
        for (const World::Part& p : w.parts()) {
            const Vector at = p.body->getDynamics().position;
            worstOverlap = std::max(worstOverlap, sphereRadius + p.radius - length(at - centre));
            partRadius = p.radius;
            // The body nearest the sphere's top: how far its sphere is from resting on it.
            if (std::fabs(at.x - centre.x) < 0.1f && std::fabs(at.z - centre.z) < 0.1f)
                middleGap = std::min(middleGap, length(at - centre) - sphereRadius - p.radius);
        }
    });
    ASSERT_EQ(status, RUN_OK);
    EXPECT_EQ(bodies, 100u);
    EXPECT_LT(worstOverlap, partRadius + 0.01f);
    EXPECT_NEAR(middleGap, 0.0f, 0.01f);
    std::printf(
        "cloth: deepest overlap with the sphere %.4f m (a body's radius %.3f m), the middle %.4f m off "
        "the sphere's top at the end\n",
        worstOverlap, partRadius, middleGap);
}

// A round soft body dropped tilted on the floor: it ends at rest on the floor (every body still, the lowest
// sphere touching the floor within 1 cm), and at no step is its extent (the greatest distance between two of
// its bodies) under 70 % of its width as built: it squashes, it does not collapse.
TEST(SoftScenes, SoftBlobRestsOnTheFloorKeepingItsShape) {
    float width0 = 0, least = 1e9f, restingLow = 0;
    bool still = false, finite = true;
    const RunStatus status = runProbed("soft-blob", 300, [&](const World& w, long step) {
        float extent = 0, low = 1e9f;
        const auto& parts = w.parts();
        for (size_t i = 0; i < parts.size(); ++i) {
            const Vector at = parts[i].body->getDynamics().position;
            low = std::min(low, at.y - parts[i].radius);
            for (size_t j = i + 1; j < parts.size(); ++j)
                extent = std::max(extent, length(parts[j].body->getDynamics().position - at));
        }
        if (step == 0) width0 = extent;
        least = std::min(least, extent);
        restingLow = low;
        still = allStill(w);
        finite = finite && w.allFinite();
    });
    ASSERT_EQ(status, RUN_OK);
    ASSERT_GT(width0, 0.0f);
    EXPECT_TRUE(finite);
    EXPECT_TRUE(still);
    EXPECT_NEAR(restingLow, 0.0f, 0.01f);
    EXPECT_GT(least, 0.7f * width0);
    std::printf(
        "soft-blob: width as built %.3f m, least extent %.3f m (%.0f %%), lowest sphere at rest %.4f m\n",
        width0, least, 100 * least / width0, restingLow);
}
