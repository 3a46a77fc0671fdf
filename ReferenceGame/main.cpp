// main.cpp - the reference game, headless: the course engine loop (physicsScene->update(now), then
// design->update(now)) on a stepped 16 ms clock, for one named scene or all of them.
//
// Usage: ReferenceGame [--scene NAME|all] [--frames N] [--csv FILE] [--csv-every N] [--track NAME]...
//                      [--image DIR] [--image-every N] [--profile] [--record FILE] [--list] [--help]
//        ReferenceGame --replay FILE [--image DIR] [--image-every N]
// Each scene ends with a verdict line on stdout: "OK <scene>" or "FAIL <scene>: <reason>". --csv writes the
// per-second measurements as CSV (CsvLog.h: columns; scripts/plot.sh plots them), --track prints the position
// of a body a scene named (World::name) each second, --image writes debug drawings as SVG (SvgDebugDraw.h),
// --profile prints where each second's step time went (iPhysicsSceneProfile.h), --record writes every frame
// (RecordingWriter.h: the format) and --replay plays such a file back without the engine (Replay.h). The run
// itself is GameRun.h's runScene. Exit status: 0 when every scene held together (and for --list, --help), 1
// when one blew up (NaN, energy growth, deep penetration; for --replay: the recorded run did), 2 on bad
// arguments (and a recording that cannot be read whole).
#include "CsvLog.h"
#include "GameRun.h"
#include "Replay.h"
#include "Scenes.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

const char* const kUsage =
    "usage: ReferenceGame [--scene NAME|all] [--frames N] [--csv FILE] [--csv-every N] [--track NAME]...\n"
    "                     [--image DIR] [--image-every N] [--profile] [--record FILE] [--list] [--help]\n"
    "       ReferenceGame --replay FILE [--image DIR] [--image-every N]\n"
    "  --scene NAME|all  the scene to run, or every scene in turn (default: pyramid)\n"
    "  --frames N        frames per scene on a stepped 16 ms clock, N > 0 (default: 600, about 10 s)\n"
    "  --csv FILE        also write the measurements as CSV to FILE: a header row, a row at t = 0 and one\n"
    "                    with each summary line; with --scene all one file per scene, the scene's name\n"
    "                    joined before .csv (runs.csv: runs-tower.csv, runs-pyramid.csv, ...)\n"
    "  --csv-every N     a CSV row every N frames instead, N > 0 (1: every frame)\n"
    "  --track NAME      print a body's position each second (and add x, y, z columns to the CSV): a name\n"
    "                    the scene gave it (--list shows them) or its index; may be repeated\n"
    "  --image DIR       write the scene's debug drawing as DIR/<scene>_<frame>.svg (DIR must exist)\n"
    "  --image-every N   ... every N frames, N > 0, and at the last frame (default: 60)\n"
    "  --profile         print each second where the last frame's step time went, phase by phase\n"
    "  --record FILE     write every frame (poses, shapes, contacts, hits) to FILE as text; with --scene\n"
    "                    all one file per scene, the scene's name joined before .rec (as --csv)\n"
    "  --replay FILE     play a --record file back without running the engine: its summary lines and\n"
    "                    verdict, with --image its pictures; only --image and --image-every go with it\n"
    "  --list            name and describe the scenes, then exit\n"
    "  --help            print this and exit\n"
    "Each second: t, awake/moving bodies (\"asleep\" when all sleep), contacts, KE, deepest overlap, hits.\n"
    "Each scene ends with \"OK <scene>\" or \"FAIL <scene>: <reason>\".\n"
    "scripts/plot.sh CSV OUTDIR plots a --csv file.\n"
    "Exit status: 0 every scene held together, 1 a scene blew up, 2 bad arguments (or a damaged "
    "recording).\n";

int usage() { // bad arguments
    std::fputs(kUsage, stderr);
    return 2;
}

} // namespace

int main(int argc, char** argv) {
    std::string name = "pyramid";
    GameOptions options;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--scene") && i + 1 < argc) {
            name = argv[++i];
        } else if (!std::strcmp(argv[i], "--frames") && i + 1 < argc) {
            options.frames = std::atoi(argv[++i]);
            if (options.frames <= 0) return usage();
        } else if (!std::strcmp(argv[i], "--csv") && i + 1 < argc && *argv[i + 1]) { // CsvLog.h
            options.csv = argv[++i];
        } else if (!std::strcmp(argv[i], "--csv-every") && i + 1 < argc) {
            if ((options.csvEvery = std::atoi(argv[++i])) <= 0) return usage();
        } else if (!std::strcmp(argv[i], "--track") && i + 1 < argc && *argv[i + 1]) { // Tracking.h
            options.track.push_back(argv[++i]);
        } else if (!std::strcmp(argv[i], "--image") && i + 1 < argc && *argv[i + 1]) { // SvgDebugDraw.h
            options.imageDir = argv[++i];
        } else if (!std::strcmp(argv[i], "--image-every") && i + 1 < argc) {
            if ((options.imageEvery = std::atoi(argv[++i])) <= 0) return usage();
        } else if (!std::strcmp(argv[i], "--profile")) {
            options.profile = true;
        } else if (!std::strcmp(argv[i], "--record") && i + 1 < argc && *argv[i + 1]) { // RecordingWriter.h
            options.record = argv[++i];
        } else if (!std::strcmp(argv[i], "--replay") && i + 1 < argc && *argv[i + 1]) { // Replay.h
            options.replay = argv[++i];
        } else if (!std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h")) {
            std::fputs(kUsage, stdout);
            return 0;
        } else if (!std::strcmp(argv[i], "--list")) {
            for (const SceneSpec& s : allScenes()) std::printf("%-10s %s\n", s.name, s.description);
            return 0;
        } else {
            return usage();
        }
    }
    if (options.csvEvery > 0 && options.csv.empty()) return usage(); // --csv-every without --csv
    if (!options.replay.empty()) { // only --image and --image-every go with it
        for (int i = 1; i < argc; i += 2)
            if (std::strcmp(argv[i], "--replay") && std::strcmp(argv[i], "--image") &&
                std::strcmp(argv[i], "--image-every"))
                return usage();
        return replayRecording(options);
    }
    int status = RUN_OK;
    if (name == "all") {
        const std::string csv = options.csv, record = options.record;
        for (const SceneSpec& s : allScenes()) {
            if (!csv.empty()) options.csv = csvPathFor(csv, s.name);
            if (!record.empty()) options.record = scenePathFor(record, s.name, ".rec");
            int st = runScene(s, options);
            if (st == RUN_BAD_ARGUMENTS) return st;
            status = st > status ? st : status;
        }
    } else if (const SceneSpec* s = findScene(name)) {
        status = runScene(*s, options);
    } else {
        std::fprintf(stderr, "no scene '%s' (try --list)\n", name.c_str());
        return 2;
    }
    return status;
}
