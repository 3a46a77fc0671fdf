// Checks.h - what a check design reports to the check entry point: each check prints one line and counts.
#pragma once

#include <cmath>
#include <cstdio>

// Records one check: prints "ok" or "FAIL" with the measured and expected values; returns ok.
inline bool check(const char* what, float measured, float expected, float tolerance) {
    extern int checkFailures;
    bool ok = std::fabs(measured - expected) <= tolerance;
    std::printf("%s %s: %.4f (expected %.4f +- %.4f)\n", ok ? "ok  " : "FAIL", what, measured, expected,
                tolerance);
    if (!ok) ++checkFailures;
    return ok;
}

// The check design's phases, driven by CheckEntry.cpp through the host's engine.
void checkAfterFirstSecond(); // after 60 frames of 16 ms (0.96 s)
void checkAfterRestore();     // suspended, restored 5 s later, then one more frame
void checkAtEnd();            // after 300 more frames (4.8 s)
