// Knobs.h - one setting of every knob bench_tradeoff turns: what a game sets on settingsOf(scene), on its
// collision space and on its bodies. The tool varies one or two of them at a time around a baseline
// (the engine's defaults), so each row of its CSV differs from the baseline in what its label says.
#pragma once

#include "iContactSettings.h"
#include "iPhysicsSettings.h"

#include <string>

namespace tradeoff {

enum class SpaceKind { Simple, Octree };

struct Knobs {
    Integrator integrator = INTEGRATOR_SemiImplicitEuler;
    int stepRate = 60;                         // Hz
    int iterations = 4;                        // solver sub-steps
    int samplesPerSecond = 60;                 // the space's motion sampling (0: never)
    SpaceKind space = SpaceKind::Simple;       //
    int maxSteps = 8;                          // most steps one update takes
    float drag = 0.0f;                         // every body's dragCoefficient (scenes that use one)
    bool listeners = false;                    // a counting listener on every body
    CombineRule frictionRule = COMBINE_Sum;    // the engine's defaults
    CombineRule restitutionRule = COMBINE_Max; //
    bool sleeping = true;                      //
    bool continuous = true;                    //
    int frameMs = 10;                          // the game's frame: update(now) every frameMs
};

inline const char* integratorName(Integrator i) {
    switch (i) {
    case INTEGRATOR_ExplicitEuler:
        return "euler";
    case INTEGRATOR_VelocityVerlet:
        return "verlet";
    case INTEGRATOR_RK4:
        return "rk4";
    default:
        return "semi";
    }
}

inline const char* ruleName(CombineRule r) {
    static const char* names[] = {"sum", "average", "max", "min", "product", "geomean"};
    return (r >= COMBINE_Sum && r <= COMBINE_GeometricMean) ? names[r] : "?";
}

// The CSV columns the knobs fill, in order (csvHeader names them).
inline std::string knobsCsvHeader() {
    return "integrator,step_hz,iterations,samples_per_s,space,max_steps,drag_cd,listeners,friction_rule,"
           "restitution_rule,sleeping,continuous,frame_ms";
}
inline std::string knobsCsv(const Knobs& k) {
    return std::string(integratorName(k.integrator)) + "," + std::to_string(k.stepRate) + "," +
           std::to_string(k.iterations) + "," + std::to_string(k.samplesPerSecond) + "," +
           (k.space == SpaceKind::Simple ? "simple" : "octree") + "," + std::to_string(k.maxSteps) + "," +
           std::to_string(k.drag) + "," + (k.listeners ? "on" : "off") + "," + ruleName(k.frictionRule) +
           "," + ruleName(k.restitutionRule) + "," + (k.sleeping ? "on" : "off") + "," +
           (k.continuous ? "on" : "off") + "," + std::to_string(k.frameMs);
}

} // namespace tradeoff
