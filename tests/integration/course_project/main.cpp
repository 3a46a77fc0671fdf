// main.cpp - the course project's entry point: the headless engine runs the Design for a fixed number of
// frames on a stepped clock; the Design's own checks decide the exit code.
#include "CourseDesign.h"
#include "iClock.h"
#include "iContext.h"
#include "iEngine.h"

#include <cstdio>

int main() {
    iContext* context = CreateContext();
    CourseSetup setup = createCourseDesign(context);
    iEngine* engine = CreateEngine(context, setup.design, setup.scene, CreateSteppedClock(16));
    if (!engine->setup()) return 3;
    int frames = engine->run(setup.frames);
    int verdict = courseVerdict();
    engine->Delete();
    context->Delete();
    std::printf("course project: %d frames, verdict %s\n", frames, verdict == 0 ? "PASS" : "FAIL");
    return verdict;
}
