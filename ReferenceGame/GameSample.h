// GameSample.h - what the reference game measures of a running scene at one frame: the numbers behind its
// per-second summary line and the rows of its CSV (CsvLog.h).
#pragma once

#include <cstddef>
#include <cstdio>

struct GameSample {
    double time = 0;        // game time since the scene started, s (the stepped clock's)
    double simTime = 0;     // physics time: fixed steps taken times the step length, s
    int frame = 0;          // frames run
    float kinetic = 0;      // translational + rotational energy of the moving bodies, J
    float mechanical = 0;   // kinetic + potential against gravity, J
    size_t awake = 0;       // moving bodies not asleep
    size_t moving = 0;      // bodies that are not fixed in space (those that can be awake)
    size_t bodies = 0;      // bodies simulated (fixed ones included)
    size_t contacts = 0;    // contacts of the last step (asleep bodies are not tested: 0 when all sleep)
    float overlap = 0;      // deepest overlap the solver left this step, m
    float worstOverlap = 0; // deepest overlap since the start, m
    long hits = 0;          // HitWall calls heard since the start
    bool allAsleep() const { return awake == 0 && moving > 0; }
};

// The per-second summary line of s (the live run's and --replay's): t, awake/moving bodies, contacts, KE,
// deepest overlap so far, hits, and the wall time per frame (the only field that is not deterministic).
void printSummaryLine(std::FILE* out, const GameSample& s, double msPerFrame);
