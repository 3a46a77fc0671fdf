// GameRecordTest.cpp - --record against physics and --replay against the live run: a recorded falling ball's
// heights are semi-implicit Euler's exact result and its landing is recorded as floor contacts and HitWall
// calls from the plane; a recorded pile (with a ball added mid-run) reads back with every pose bit for bit as
// the live bodies had it, and its replay prints the live summary lines and writes the live pictures byte
// for byte.
#include "GameTestSupport.h"

#include "RBDynamics.h"
#include "RecordingReader.h"
#include "Replay.h"
#include "iPhysicsFrame.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <dirent.h>
#include <regex>
#include <sys/stat.h>

using namespace game_test;

namespace {

// Every frame's live bodies, as the scene's act sees them (act runs in the same update as the recording,
// before it, and this scene's act changes nothing it has recorded).
struct LivePose {
    Vector origin, velocity, angularVelocity, angularMomentum;
    Matrix rotation;
};
std::vector<std::vector<LivePose>>& livePoses() {
    static std::vector<std::vector<LivePose>> poses;
    return poses;
}

void captureLive(World& w) {
    livePoses().emplace_back();
    for (const iPhysicsFrame* f : w.bodies()) {
        const RBDynamics& d = *f->getDynamics();
        livePoses().back().push_back(
            {d.getWorldOrigin(), d.velocity, d.angularVelocity, d.angularMomentum, d.getWorldOrientation()});
    }
}

// A 6-row pyramid on a floor that falls asleep; at frame 40 a ball is dropped on it, which wakes it.
void buildRecPile(World& w) {
    buildPyramid(w, 6);
    livePoses().clear();
    captureLive(w); // frame 0
}
void actRecPile(World& w, int frame) {
    if (frame == 40) w.name(w.sphere(Vector(0.2f, 8, 0.1f), 0.5f, 1.0f), "ball");
    captureLive(w);
}

bool sameBits(const float* a, const float* b, size_t n) { return std::memcmp(a, b, n * sizeof(float)) == 0; }

std::vector<std::string> filesIn(const std::string& dir) {
    std::vector<std::string> names;
    if (DIR* d = ::opendir(dir.c_str())) {
        while (const dirent* e = ::readdir(d))
            if (e->d_name[0] != '.') names.push_back(e->d_name);
        ::closedir(d);
    }
    std::sort(names.begin(), names.end());
    return names;
}

std::string fileText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// The summary lines of a run's output without their wall-time column.
std::vector<std::string> summaryLines(const std::string& text) {
    std::vector<std::string> lines;
    const std::regex line(R"(\nt [^|\n]*\|)");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), line); it != std::sregex_iterator(); ++it)
        lines.push_back(it->str());
    return lines;
}

} // namespace

TEST(GameRecord, AFallingBallsRecordedHeightsAreSemiImplicitEulersExactResult) {
    const std::string path = scratch("drop.rec");
    GameOptions o;
    o.frames = 330; // 5.28 s: it lands at about 4.5 s
    o.record = path;
    o.out = std::tmpfile();
    ASSERT_EQ(runScene(dropScene(), o), RUN_OK);
    std::fclose(o.out);
    RecordingReader r;
    ASSERT_TRUE(r.open(path)) << r.error();
    EXPECT_EQ(r.scene(), "drop");
    ASSERT_EQ(r.shapes().size(), 2u); // the floor, then the ball, as World built them
    EXPECT_EQ(r.shapes()[0].kind, RecordedShape::Plane);
    EXPECT_EQ(r.shapes()[1].kind, RecordedShape::Sphere);
    EXPECT_EQ(r.shapes()[1].size.x, kBallRadius);
    EXPECT_EQ(r.shapes()[1].mass, kBallMass);
    RecordedFrame f;
    int frames = 0, floorHits = 0;
    double landedAt = -1;
    while (r.next(f)) {
        EXPECT_EQ(f.frame, frames++);
        ASSERT_EQ(f.bodies.size(), 1u);
        const RecordedBody& ball = f.bodies[0];
        const double n = double(f.steps), t = n * kStep;
        EXPECT_LE(t, f.timeMs / 1000.0 + 1e-9); // the physics is at most one step behind the clock
        EXPECT_GT(t, f.timeMs / 1000.0 - kStep - 1e-9);
        // Landed: touching the floor (continuous collision stops it at first touch, before any contact).
        if (landedAt < 0 && (ball.origin.y < kBallRadius + 0.01f || !f.contacts.empty() || !f.events.empty()))
            landedAt = t;
        if (landedAt < 0) {
            // In free fall: semi-implicit Euler under constant g gives, after n whole steps, exactly
            // h - g dt^2 n (n + 1) / 2 = h - g t^2 / 2 - g dt t / 2; the float state keeps within 0.5 mm of
            // it.
            EXPECT_NEAR(ball.origin.y, kDropHeight - 0.5 * kG * t * t - 0.5 * kG * kStep * t, 5e-4)
                << "t " << t;
            EXPECT_NEAR(ball.velocity.y, -kG * t, 1e-4 * kG * t + 1e-6) << "t " << t;
            EXPECT_EQ(ball.origin.x, 0.0f);
            EXPECT_EQ(ball.origin.z, 0.0f);
        }
        EXPECT_GE(ball.origin.y, kBallRadius - 0.01f) << "through the floor at t " << t;
        for (const RecordedContact& c : f.contacts) { // ball on floor: at the floor, normal along y
            EXPECT_NEAR(c.point.y, 0.0, 0.01);
            EXPECT_NEAR(std::fabs(c.normal.y), 1.0, 1e-6);
        }
        for (const RecordedEvent& e : f.events) { // the ball heard the floor, which has no body
            EXPECT_EQ(e.body, 0);
            EXPECT_EQ(e.other, -1);
            EXPECT_NEAR(e.point.y, 0.0, 0.01);
            ++floorHits;
        }
        EXPECT_EQ(r.lastFrame(), f.frame == o.frames);
    }
    EXPECT_EQ(r.error(), "");
    EXPECT_EQ(r.verdict(), "OK");
    EXPECT_EQ(frames, o.frames + 1); // frame 0 (as built) and every frame
    // It touches the floor when its centre has fallen h - r: at t = sqrt(2 (h - r) / g), give or take the
    // frame (16 ms) in which it is seen.
    EXPECT_NEAR(landedAt, std::sqrt(2 * (kDropHeight - kBallRadius) / kG), 0.04);
    EXPECT_GE(floorHits, 1);
    std::remove(path.c_str());
}

TEST(GameReplay, RecordThenReplayGivesTheLivePosesBitsSummaryAndPicturesBytes) {
    registerScene({"recpile", "a 6-row pyramid, a ball dropped on it at frame 40", buildRecPile, actRecPile});
    const std::string path = scratch("pile.rec"), live = scratch("live"), replayed = scratch("replayed");
    ::mkdir(live.c_str(), 0755);
    ::mkdir(replayed.c_str(), 0755);
    GameOptions o;
    o.frames = 150;
    o.record = path;
    o.imageDir = live;
    o.imageEvery = 25;
    o.out = std::tmpfile();
    ASSERT_EQ(runScene(*findScene("recpile"), o), RUN_OK);
    const std::string liveText = readBack(o.out);
    std::fclose(o.out);

    // Read back: every recorded pose, velocity and momentum is the live body's, bit for bit.
    RecordingReader r;
    ASSERT_TRUE(r.open(path)) << r.error();
    ASSERT_EQ(livePoses().size(), size_t(o.frames) + 1);
    RecordedFrame f;
    bool sawSleep = false, sawBall = false;
    size_t contacts = 0;
    while (r.next(f)) {
        const std::vector<LivePose>& want = livePoses()[size_t(f.frame)];
        ASSERT_EQ(f.bodies.size(), want.size()) << "frame " << f.frame;
        for (size_t i = 0; i < want.size(); ++i) {
            const RecordedBody& b = f.bodies[i];
            const Matrix rot = want[i].rotation.rotation();
            const float liveRot[9] = {rot.m11, rot.m12, rot.m13, rot.m21, rot.m22,
                                      rot.m23, rot.m31, rot.m32, rot.m33};
            const float gotRot[9] = {b.rotation.m11, b.rotation.m12, b.rotation.m13,
                                     b.rotation.m21, b.rotation.m22, b.rotation.m23,
                                     b.rotation.m31, b.rotation.m32, b.rotation.m33};
            EXPECT_TRUE(sameBits(&b.origin.x, &want[i].origin.x, 3)) << "frame " << f.frame << " body " << i;
            EXPECT_TRUE(sameBits(gotRot, liveRot, 9)) << "frame " << f.frame << " body " << i;
            EXPECT_TRUE(sameBits(&b.velocity.x, &want[i].velocity.x, 3));
            EXPECT_TRUE(sameBits(&b.angularVelocity.x, &want[i].angularVelocity.x, 3));
            EXPECT_TRUE(sameBits(&b.angularMomentum.x, &want[i].angularMomentum.x, 3));
            sawSleep |= b.asleep();
        }
        sawBall |= f.bodies.size() == 22;
        contacts += f.contacts.size();
    }
    EXPECT_EQ(r.error(), "");
    EXPECT_TRUE(sawSleep);   // the pictures below show sleeping bodies...
    EXPECT_TRUE(sawBall);    // ... a body added mid-run (a sphere)...
    EXPECT_GT(contacts, 0u); // ... and contacts

    // Replayed: the same summary lines (all but the wall time) and the same pictures, byte for byte.
    GameOptions p;
    p.replay = path;
    p.imageDir = replayed;
    p.imageEvery = 25;
    p.out = std::tmpfile();
    ASSERT_EQ(replayRecording(p), RUN_OK);
    const std::string replayText = readBack(p.out);
    std::fclose(p.out);
    EXPECT_EQ(summaryLines(replayText), summaryLines(liveText)) << liveText << "\n---\n" << replayText;
    EXPECT_EQ(summaryLines(liveText).size(), 3u); // 1 s, 2 s and the last frame
    EXPECT_NE(replayText.find("\nOK recpile\n"), std::string::npos) << replayText;
    const std::vector<std::string> pictures = filesIn(live);
    const std::vector<std::string> want = {"recpile_00025.svg", "recpile_00050.svg", "recpile_00075.svg",
                                           "recpile_00100.svg", "recpile_00125.svg", "recpile_00150.svg"};
    EXPECT_EQ(pictures, want);
    EXPECT_EQ(filesIn(replayed), want);
    bool drewSleep = false;
    for (const std::string& name : pictures) {
        const std::string a = fileText(live + "/" + name), b = fileText(replayed + "/" + name);
        EXPECT_GT(a.size(), 1000u) << name;
        EXPECT_TRUE(a == b) << name << " differs";
        drewSleep |= a.find(">zz</text>") != std::string::npos;
        std::remove((live + "/" + name).c_str());
        std::remove((replayed + "/" + name).c_str());
    }
    EXPECT_TRUE(drewSleep); // a picture with sleeping bodies was compared
    ::rmdir(live.c_str());
    ::rmdir(replayed.c_str());
    std::remove(path.c_str());
}
