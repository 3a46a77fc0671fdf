// main.cpp - the reference game, headless: the course engine loop (physicsScene->update(now), then
// design->update(now)) on a stepped 16 ms clock, for one named scene or all of them.
//
// Usage: ReferenceGame [--scene NAME|all] [--frames N] [--image DIR [--image-every N]] [--list] [--help]
// Each scene ends with a verdict line on stdout: "OK <scene>" or "FAIL <scene>: <reason>".
// Exit status: 0 when every scene held together (and for --list, --help), 1 when one blew up (NaN, energy
// growth, deep penetration), 2 on bad arguments.
#include "GameDesign.h"
#include "Scenes.h"
#include "iClock.h"
#include "iContext.h"
#include "iEngine.h"
#include "iPhysicsScene.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

const char* const kUsage =
    "usage: ReferenceGame [--scene NAME|all] [--frames N] [--image DIR [--image-every N]] [--list] [--help]\n"
    "  --scene NAME|all  the scene to run, or every scene in turn (default: pyramid)\n"
    "  --frames N        frames per scene on a stepped 16 ms clock, N > 0 (default: 600, about 10 s)\n"
    "  --image DIR       write the scene's debug drawing as DIR/<scene>_<frame>.svg (DIR must exist)\n"
    "  --image-every N   ... every N frames, N > 0, and at the last frame (default: 60)\n"
    "  --list            name and describe the scenes, then exit\n"
    "  --help            print this and exit\n"
    "Each scene ends with \"OK <scene>\" or \"FAIL <scene>: <reason>\".\n"
    "Exit status: 0 every scene held together, 1 a scene blew up, 2 bad arguments.\n";

int usage() { // bad arguments
    std::fputs(kUsage, stderr);
    return 2;
}

struct ImageOptions { // --image DIR [--image-every N]
    std::string dir;  // empty: no pictures
    int every = 60;
};

bool runScene(const SceneSpec& spec, int frames, const ImageOptions& images) {
    iContext* context = CreateContext();
    iPhysicsScene* scene = CreatePhysicsScene(context); // the course Engine makes it in its constructor
    GameDesign* design = new GameDesign(scene, spec, frames);
    if (!images.dir.empty()) design->writeImages(images.dir, images.every);
    iEngine* engine = CreateEngine(context, design, scene, CreateSteppedClock(16));
    engine->setup();
    engine->run(frames);
    const char* failure = design->failure();
    if (failure)
        std::printf("FAIL %s: %s\n", spec.name, failure);
    else
        std::printf("OK %s\n", spec.name);
    std::fflush(stdout);
    bool ok = failure == nullptr;
    engine->Delete(); // deletes the design, then the scene
    context->Delete();
    return ok;
}

} // namespace

int main(int argc, char** argv) {
    std::string name = "pyramid";
    int frames = 600;
    ImageOptions images;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--scene") && i + 1 < argc) {
            name = argv[++i];
        } else if (!std::strcmp(argv[i], "--frames") && i + 1 < argc) {
            frames = std::atoi(argv[++i]);
            if (frames <= 0) return usage();
        } else if (!std::strcmp(argv[i], "--image") && i + 1 < argc) {
            images.dir = argv[++i];
        } else if (!std::strcmp(argv[i], "--image-every") && i + 1 < argc) {
            images.every = std::atoi(argv[++i]);
            if (images.every <= 0) return usage();
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
    bool ok = true;
    if (name == "all") {
        for (const SceneSpec& s : allScenes()) ok = runScene(s, frames, images) && ok;
    } else if (const SceneSpec* s = findScene(name)) {
        ok = runScene(*s, frames, images);
    } else {
        std::fprintf(stderr, "no scene '%s' (try --list)\n", name.c_str());
        return 2;
    }
    return ok ? 0 : 1;
}
