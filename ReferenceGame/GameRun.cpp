// GameRun.cpp - the engine loop around GameDesign for one scene.
#include "GameRun.h"

#include "CsvLog.h"
#include "GameDesign.h"
#include "RecordingWriter.h"
#include "iClock.h"
#include "iContext.h"
#include "iEngine.h"
#include "iPhysicsScene.h"

RunStatus runScene(const SceneSpec& spec, const GameOptions& options) {
    CsvLog csv;
    if (!options.csv.empty() && !csv.open(options.csv)) {
        std::fprintf(options.err, "ReferenceGame: cannot write %s\n", options.csv.c_str());
        return RUN_BAD_ARGUMENTS;
    }
    RecordingWriter recording;
    if (!options.record.empty() && !recording.open(options.record)) {
        std::fprintf(options.err, "ReferenceGame: cannot write %s\n", options.record.c_str());
        return RUN_BAD_ARGUMENTS;
    }
    iContext* context = CreateContext();
    iPhysicsScene* scene = CreatePhysicsScene(context); // the course Engine makes it in its constructor
    GameDesign* design = new GameDesign(scene, spec, options, options.csv.empty() ? nullptr : &csv);
    if (!options.record.empty()) design->record(&recording);
    if (!options.imageDir.empty()) design->writeImages(options.imageDir, options.imageEvery);
    iEngine* engine = CreateEngine(context, design, scene, CreateSteppedClock(16));
    engine->setup();
    engine->run(options.frames);
    const char* failure = design->failure();
    recording.end(failure);
    if (failure)
        std::fprintf(options.out, "FAIL %s: %s\n", spec.name, failure);
    else
        std::fprintf(options.out, "OK %s\n", spec.name);
    std::fflush(options.out);
    engine->Delete(); // deletes the design, then the scene
    context->Delete();
    return failure ? RUN_BLEW_UP : RUN_OK;
}
