// Runner.h - one timed run of a scene under one setting, and the paired comparison with the baseline:
// baseline and setting runs alternate (baseline first, then setting first...), so that a shared, noisy
// machine slows both alike; the cost ratio is the median of the pairs' ratios.
#pragma once

#include "Knobs.h"
#include "TrialScene.h"

namespace tradeoff {

struct RunResult {
    double seconds = 0;    // wall time spent inside update() (steady clock)
    int runs = 1;          // runs added up (runRepeated)
    long long steps = 0;   // fixed steps taken, all runs
    long long dropped = 0; // steps dropped by the max-steps cap, all runs
    int bodies = 0;        // moving bodies
    double error = 0;      // against the truth, in the scene's unit
    double nsPerBodyStep() const {
        return steps > 0 && bodies > 0 ? 1e9 * seconds / double(steps * bodies) : 0;
    }
};

// Builds the scene under k (untimed), runs it for info.seconds of engine time (timed) and measures the error.
RunResult runOnce(const SceneInfo& info, const Knobs& k);
// runOnce `runs` times (a fresh scene each time, identical results): the seconds and steps add up.
RunResult runRepeated(const SceneInfo& info, const Knobs& k, int runs);

struct Comparison {
    RunResult setting;    // the last run of the setting (its error; steps)
    double nsPerBodyStep; // median over the repeats
    double costRatio;     // median over the repeats of setting time / baseline time, same engine time
};

// repeats pairs of (baseline, setting) samples, each sample `runs` runs long.
Comparison compareWithBaseline(const SceneInfo& info, const Knobs& k, int repeats, int runs);
// How many runs of the baseline make a sample of at least targetSeconds (its first run warms up).
int runsForSample(const SceneInfo& info, double targetSeconds);

} // namespace tradeoff
