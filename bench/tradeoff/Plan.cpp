// Plan.cpp - the settings each bench_tradeoff scene is run under (Plan.h). Knobs the settings interface
// does not have (per-step validation and interpolation are always on) get no rows.
#include "Plan.h"

#include <functional>
#include <vector>

namespace tradeoff {
namespace {

bool hasContacts(const std::string& name) {
    return name == "rebound" || name == "slide" || name == "roll" || name == "stack" || name == "pyramid" ||
           name == "tunnel";
}

class Planner {
public:
    explicit Planner(const Knobs& base) : m_base(base) {}
    void add(const std::string& varied, const std::function<void(Knobs&)>& edit) {
        Knobs k = m_base;
        edit(k);
        out.push_back({varied, k});
    }
    std::vector<Setting> out;

private:
    Knobs m_base;
};

} // namespace

std::vector<Setting> planFor(const SceneInfo& scene, bool quick) {
    Planner p(scene.baseline);
    const std::string& n = scene.name;
    p.add("baseline", [](Knobs&) {});
    if (!hasContacts(n)) {
        const auto rates = quick ? std::vector<int>{30, 120} : std::vector<int>{30, 60, 120, 240, 480};
        for (Integrator i : {INTEGRATOR_SemiImplicitEuler, INTEGRATOR_ExplicitEuler,
                             INTEGRATOR_VelocityVerlet, INTEGRATOR_RK4}) {
            if (quick && i == INTEGRATOR_ExplicitEuler) continue;
            for (int hz : rates) {
                if (i == INTEGRATOR_SemiImplicitEuler && hz == scene.baseline.stepRate)
                    continue; // the baseline
                p.add("integrator*step_hz", [=](Knobs& k) {
                    k.integrator = i;
                    k.stepRate = hz;
                });
            }
        }
    } else {
        const auto rates = quick ? std::vector<int>{30, 120} : std::vector<int>{30, 60, 120, 240};
        const auto iters = quick ? std::vector<int>{1, 16} : std::vector<int>{1, 2, 4, 8, 16};
        for (int hz : rates)
            for (int it : iters) {
                if (hz == scene.baseline.stepRate && it == scene.baseline.iterations) continue;
                p.add("step_hz*iterations", [=](Knobs& k) {
                    k.stepRate = hz;
                    k.iterations = it;
                });
            }
        if (!quick) {
            p.add("integrator", [](Knobs& k) { k.integrator = INTEGRATOR_VelocityVerlet; });
            p.add("integrator", [](Knobs& k) { k.integrator = INTEGRATOR_RK4; });
        }
    }
    // The collision space and its sampling, listeners: every scene has geometry in a space.
    if (n != "spring" && n != "top" && n != "slow_game") {
        p.add("space", [](Knobs& k) { k.space = SpaceKind::Octree; });
        p.add("listeners", [](Knobs& k) { k.listeners = true; });
        if (!quick)
            for (int s : {0, 240, 1000}) p.add("samples_per_s", [=](Knobs& k) { k.samplesPerSecond = s; });
    }
    if (n == "drag_fall") p.add("drag_cd", [](Knobs& k) { k.drag = 0.0f; });
    if (n == "slow_game") {
        for (int m : {1, 2, 4}) p.add("max_steps", [=](Knobs& k) { k.maxSteps = m; });
        for (int m : {4, 8, 16})
            p.add("step_hz*max_steps", [=](Knobs& k) {
                k.stepRate = 240;
                k.maxSteps = m;
            });
    }
    if (n == "rebound") {
        for (CombineRule r : {COMBINE_Average, COMBINE_Min, COMBINE_Product, COMBINE_GeometricMean})
            p.add("restitution_rule", [=](Knobs& k) { k.restitutionRule = r; });
    }
    if (n == "slide" || n == "roll") {
        for (CombineRule r :
             {COMBINE_Average, COMBINE_Max, COMBINE_Min, COMBINE_Product, COMBINE_GeometricMean}) {
            if (quick && r != COMBINE_Product) continue;
            p.add("friction_rule", [=](Knobs& k) { k.frictionRule = r; });
        }
    }
    if (hasContacts(n)) {
        p.add("continuous", [](Knobs& k) { k.continuous = false; });
        p.add("sleeping", [](Knobs& k) { k.sleeping = false; });
    }
    if ((n == "stack" || n == "pyramid") && !quick) {
        for (int it : {1, 8, 16})
            p.add("sleeping*iterations", [=](Knobs& k) {
                k.sleeping = false;
                k.iterations = it;
            });
    }
    if (n == "tunnel") {
        for (int s : {0, 60, 240, 1000})
            p.add("continuous*samples_per_s", [=](Knobs& k) {
                k.continuous = false;
                k.samplesPerSecond = s;
            });
        for (int hz : {120, 240, 480})
            p.add("continuous*step_hz", [=](Knobs& k) {
                k.continuous = false;
                k.stepRate = hz;
            });
        p.add("continuous*space", [](Knobs& k) {
            k.continuous = false;
            k.space = SpaceKind::Octree;
        });
    }
    return p.out;
}

} // namespace tradeoff
