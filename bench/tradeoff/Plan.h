// Plan.h - which settings bench_tradeoff runs for a scene: not the full cross product, but the knobs that
// matter to that scene, one or two at a time around its baseline, plus a small grid (integrator x step
// rate for the scenes without contacts, step rate x solver iterations for those with contacts).
#pragma once

#include "Knobs.h"
#include "TrialScene.h"

#include <string>
#include <vector>

namespace tradeoff {

struct Setting {
    std::string varied; // what differs from the baseline, e.g. "integrator*step_hz" ("baseline": none)
    Knobs knobs;
};

// quick: a handful of settings a scene, for a smoke run of about 30 s.
std::vector<Setting> planFor(const SceneInfo& scene, bool quick);

} // namespace tradeoff
