// TrialScene.h - what a bench_tradeoff scene is: it builds N identical, non-interacting copies of one
// physical situation into a World, may watch them between updates (untimed), and at the end says how far
// the engine landed from the independently computed truth (Truth.h), in the unit it names.
#pragma once

#include "Knobs.h"

#include <memory>
#include <string>
#include <vector>

class World;
class iPhysicsScene;

namespace tradeoff {

class TrialScene {
public:
    virtual ~TrialScene() = default;
    // Builds the bodies (the knobs are already set on the scene and the space is the world's).
    virtual void build(World& world, const Knobs& k) = 0;
    // After every update, outside the timed region; simTime = steps taken / step rate.
    virtual void observe(World&, double /*simTime*/) {}
    // The error against the truth once the run is over (engineTime: seconds of update(now) time).
    virtual double error(World& world, const Knobs& k, double simTime, double engineTime) = 0;
};

struct SceneInfo {
    std::string name;
    std::string unit; // the error's unit, for the CSV
    double seconds;   // engine time each run covers
    Knobs baseline;   // the settings every row of this scene is compared with
    std::unique_ptr<TrialScene> (*make)();
};

// The scenes with closed-form answers and no contacts (AnalyticScenes.cpp) and those with contacts
// (ContactScenes.cpp).
std::vector<SceneInfo> analyticScenes();
std::vector<SceneInfo> contactScenes();

// Where copy i of a scene goes: an 8-wide grid on the floor, `spacing` metres apart.
inline float gridX(int i, float spacing) { return float(i % 8) * spacing; }
inline float gridZ(int i, float spacing) { return float(i / 8) * spacing; }

} // namespace tradeoff
