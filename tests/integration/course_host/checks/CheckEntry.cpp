// CheckEntry.cpp - runs the merged host's engine with the check design: 60 frames, a suspension of 5 s,
// one frame, then 300 more; the checks decide the exit code.
#include "Checks.h"
#include "iContext.h"
#include "iEngine.h"

int checkFailures = 0;

int main() {
    iContext* context = CreateContext();
    iEngine* engine = CreateEngine(context);
    if (!engine->setup(0)) return 3;
    engine->run(60, 16);
    checkAfterFirstSecond();
    engine->suspend();
    engine->restore(engine->time() + 5000); // nothing may be integrated for the time suspended
    engine->run(1, 16);
    checkAfterRestore();
    engine->run(300, 16);
    checkAtEnd();
    engine->Delete();
    context->Delete();
    std::printf("%s\n", checkFailures == 0 ? "PASS" : "FAIL");
    return checkFailures == 0 ? 0 : 1;
}
