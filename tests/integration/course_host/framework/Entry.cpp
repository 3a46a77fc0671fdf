// Entry.cpp - the test host's entry point: set up, run, suspend and restore, reset, shut down.
#include "iContext.h"
#include "iEngine.h"
#include "iObject.h"

#include <cstdio>

int main() {
    iContext* context = CreateContext();
    iEngine* engine = CreateEngine(context);
    if (!engine->setup(0)) return 3;
    engine->run(60, 16);
    engine->suspend();
    engine->restore(engine->time() + 5000);
    engine->run(60, 16);
    engine->reset(engine->time());
    engine->Delete();
    context->Delete();
    std::printf("course host: %d draws\n", drawsRecorded());
    return drawsRecorded() == 240 ? 0 : 1;
}
