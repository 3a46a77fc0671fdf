// PrecisionReport.cpp - prints the precision scenes' measurements (PrecisionScenes.h) for the library it is
// linked with; built twice, precision_report (float) and precision_report_double, and run back to back by
// scripts/precision.sh for README.md (Double precision)'s table.
#include "PrecisionScenes.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

#if defined(GUARDIAN_DOUBLE) && GUARDIAN_DOUBLE
static const char* kBuild = "double";
#else
static const char* kBuild = "float";
#endif

int main(int argc, char** argv) {
    using namespace precision;
    // "pyramid": the step time alone (scripts/precision.sh interleaves the two builds' timings); a number:
    // every measurement, the pyramid timed that many times.
    const bool timingOnly = argc > 1 && std::strcmp(argv[1], "pyramid") == 0;
    const int pyramidRuns = timingOnly ? 1 : argc > 1 ? std::atoi(argv[1]) : 3;
    if (timingOnly) {
        std::printf("%s awake 210-box pyramid: %.3f ms per step\n", kBuild, awakePyramidStepMs());
        return 0;
    }
    for (float offset : {0.0f, 1e3f, 1e4f, 1e5f}) {
        std::printf("%s offset %g: slow roll distance / (v t) = %.4f (offset in every axis: %.4f)\n", kBuild,
                    offset, slowRoll(offset, 0.01f, 60.0), slowRoll(offset, 0.01f, 60.0, true));
        const Rest r = restingBox(offset);
        std::printf("%s offset %g: resting box height error = %.3g m, max speed = %.3g m/s\n", kBuild, offset,
                    r.heightError, r.maxSpeed);
        std::printf("%s offset %g: projectile worst distance from the parabola = %.3g m\n", kBuild, offset,
                    projectile(offset));
    }
    for (float ratio : {1e3f, 1e4f})
        for (int iterations : {4, 16}) {
            const Stack s = heavyOnLight(ratio, iterations, 5.0);
            std::printf("%s heavy on light 1:%g at %d iterations: sink = %.3g m, drift = %.3g m\n", kBuild,
                        ratio, iterations, s.sink, s.drift);
        }
    double best = 1e30;
    for (int i = 0; i < pyramidRuns; ++i) best = std::min(best, awakePyramidStepMs());
    std::printf("%s awake 210-box pyramid: %.3f ms per step (best of %d)\n", kBuild, best, pyramidRuns);
    return 0;
}
