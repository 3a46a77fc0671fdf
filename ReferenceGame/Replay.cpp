// Replay.cpp - playing a recording back: the summary's numbers recomputed from the recorded bodies, contacts
// and events as GameDesign measures them live, and the pictures drawn from the recorded poses.
#include "Replay.h"

#include "GameSample.h"
#include "MathDefinitions.h"
#include "PhysicsConstants.h"
#include "RecordingDraw.h"
#include "RecordingReader.h"
#include "SvgDebugDraw.h"

#include <chrono>

namespace {

// As World::kineticEnergy, term for term (the same float sum, so the same KE as the live summary's).
float replayKineticEnergy(const RecordedFrame& f, const std::vector<float>& mass) {
    float e = 0;
    for (size_t i = 0; i < f.bodies.size(); ++i) {
        const RecordedBody& b = f.bodies[i];
        if (b.fixed() || !(mass[i] < INFINITE_MASS)) continue;
        e += 0.5f * mass[i] * b.velocity.lengthSquared() + 0.5f * dot(b.angularVelocity, b.angularMomentum);
    }
    return e;
}

bool replayImage(const GameOptions& options, const RecordingReader& reader, const RecordedFrame& f) {
    SvgDebugDraw picture;
    drawRecordedFrame(picture, reader.shapes(), f);
    char name[64];
    std::snprintf(name, sizeof name, "_%05d.svg", f.frame);
    const std::string path = options.imageDir + "/" + reader.scene() + name;
    if (picture.write(path)) return true;
    std::fprintf(options.err, "cannot write %s\n", path.c_str());
    return false;
}

} // namespace

RunStatus replayRecording(const GameOptions& options) {
    RecordingReader reader;
    if (!reader.open(options.replay)) {
        std::fprintf(options.err, "ReferenceGame: --replay: %s\n", reader.error().c_str());
        return RUN_BAD_ARGUMENTS;
    }
    const std::string& scene = reader.scene();
    std::fprintf(options.out, "replay of scene %s (%s); %zu bodies\n", scene.c_str(), options.replay.c_str(),
                 reader.initialBodies());
    RecordedFrame f;
    std::vector<float> mass;
    long hits = 0;
    float worst = 0;
    int lastSecond = 0, framesThisSecond = 0;
    auto wallStart = std::chrono::steady_clock::now();
    bool imagesFailed = false;
    while (reader.next(f)) {
        for (const RecordedShape& s : reader.shapes())
            if (s.body >= 0 && size_t(s.body) >= mass.size()) mass.push_back(s.mass);
        hits += long(f.events.size());
        if (f.overlap > worst) worst = f.overlap;
        if (f.frame == 0) continue; // the scene as built: a live run prints and draws nothing for it
        ++framesThisSecond;
        const int second = f.timeMs / 1000;
        if (second != lastSecond || reader.lastFrame()) {
            GameSample s;
            s.time = f.timeMs / 1000.0;
            s.frame = f.frame;
            s.kinetic = replayKineticEnergy(f, mass);
            for (const RecordedBody& b : f.bodies) {
                s.awake += !b.fixed() && !b.asleep();
                s.moving += !b.fixed();
            }
            s.bodies = f.bodies.size();
            s.contacts = f.contacts.size();
            s.overlap = f.overlap;
            s.worstOverlap = worst;
            s.hits = hits;
            auto wall = std::chrono::steady_clock::now();
            printSummaryLine(options.out, s,
                             std::chrono::duration<double, std::milli>(wall - wallStart).count() /
                                 framesThisSecond);
            wallStart = wall;
            framesThisSecond = 0;
            lastSecond = second;
        }
        if (!options.imageDir.empty() && !imagesFailed &&
            (f.frame % options.imageEvery == 0 || reader.lastFrame()))
            imagesFailed = !replayImage(options, reader, f);
    }
    if (!reader.error().empty()) {
        std::fflush(options.out);
        std::fprintf(options.err, "ReferenceGame: --replay: %s\n", reader.error().c_str());
        return RUN_BAD_ARGUMENTS;
    }
    const std::string& verdict = reader.verdict();
    const bool ok = verdict == "OK";
    if (ok)
        std::fprintf(options.out, "OK %s\n", scene.c_str());
    else
        std::fprintf(options.out, "FAIL %s: %s\n", scene.c_str(), verdict.substr(5).c_str());
    std::fflush(options.out);
    if (imagesFailed) return RUN_BLEW_UP; // as a live run: a picture that cannot be written fails it
    return ok ? RUN_OK : RUN_BLEW_UP;
}
