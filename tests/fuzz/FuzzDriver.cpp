// FuzzDriver.cpp - guardian_fuzz: runs fuzz sequences for a range of seeds (FuzzWorld.h).
//
//   guardian_fuzz --first-seed A --count N [--calls 300] [--verbose]
//
// Each seed is one independent sequence; the same seed replays the same calls. A crash or sanitizer report
// stops the process: the last "seed" line printed (--verbose) or the range bisected names the culprit.
#include "FuzzWorld.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>

int main(int argc, char** argv) {
    unsigned long long first = 1, count = 100;
    int calls = 300;
    bool verbose = false;
    for (int i = 1; i < argc; ++i) {
        const char* a = argv[i];
        bool hasValue = i + 1 < argc;
        if (!std::strcmp(a, "--first-seed") && hasValue)
            first = std::strtoull(argv[++i], nullptr, 10);
        else if (!std::strcmp(a, "--count") && hasValue)
            count = std::strtoull(argv[++i], nullptr, 10);
        else if (!std::strcmp(a, "--calls") && hasValue)
            calls = std::atoi(argv[++i]);
        else if (!std::strcmp(a, "--verbose"))
            verbose = true;
        else {
            std::fprintf(stderr, "usage: guardian_fuzz --first-seed A --count N [--calls 300] [--verbose]\n");
            return !std::strcmp(a, "--help") ? 0 : 2;
        }
    }
    if (calls < 1) calls = 1;
    auto start = std::chrono::steady_clock::now();
    fuzz::SequenceStats total;
    for (unsigned long long s = first; s < first + count; ++s) {
        if (verbose) {
            std::printf("seed %llu\n", s);
            std::fflush(stdout);
        }
        fuzz::SequenceStats st = fuzz::runSequence(s, calls);
        total.calls += st.calls;
        total.errors += st.errors;
        total.steps += st.steps;
        total.callbacks += st.callbacks;
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("OK seeds %llu..%llu (%llu sequences of %d calls): %lu calls, %lu steps, %lu callbacks, %lu "
                "refusals, %.1f s\n",
                first, first + count - 1, count, calls, total.calls, total.steps, total.callbacks,
                total.errors, seconds);
    return 0;
}
