// main.cpp - bench_tradeoff: the speed/accuracy trade of every knob as a map. Runs each scene with a known
// truth (TrialScene.h) under the settings of Plan.cpp, each compared with the scene's baseline in
// interleaved pairs (Runner.h), and writes one CSV row per setting: the knobs, ns per body-step, the cost
// ratio to the baseline, the error against the truth and its unit, and whether the setting is on the
// scene's Pareto front (cost ratio, error). scripts/tradeoff.sh builds it, runs it and plots the CSV.
#include "../StayOnThisCpu.h"
#include "Pareto.h"
#include "Plan.h"
#include "Runner.h"

#include "iUtilities.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

using namespace tradeoff;

namespace {

struct Row {
    std::string scene, varied, unit, knobs;
    Comparison c;
};

long long g_engineErrors = 0;

bool changesTruth(const std::string& varied) {
    return varied.find("rule") != std::string::npos || varied.find("drag_cd") != std::string::npos;
}

std::string threeDigits(double x) {
    char b[32];
    std::snprintf(b, sizeof b, "%.3g", x);
    return b;
}

int usage(int code) {
    std::fprintf(code ? stderr : stdout,
                 "usage: bench_tradeoff [--quick] [--out FILE.csv] [--repeats N] [--scene NAME]\n"
                 "  --quick      a few settings a scene and one pair each: a smoke run of about 30 s\n"
                 "  --out FILE   where the CSV goes (default: tradeoff.csv)\n"
                 "  --repeats N  baseline/setting pairs per setting, N >= 1 (default 5; quick: 1)\n"
                 "  --scene NAME only this scene (projectile, drag_fall, orbit, spring, top, slow_game,\n"
                 "               rebound, slide, roll, stack, pyramid, tunnel)\n");
    return code;
}

} // namespace

int main(int argc, char** argv) {
    // Each setting and its baseline are timed in interleaved pairs: both on one core (StayOnThisCpu.h).
    const int cpu = stayOnThisCpu();
    if (cpu >= 0)
        std::fprintf(stderr, "bench_tradeoff: kept on CPU %d\n", cpu);
    else
        std::fprintf(stderr, "bench_tradeoff: not kept on one CPU\n");
    bool quick = false;
    int repeats = -1;
    std::string out = "tradeoff.csv", only;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--quick") {
            quick = true;
        } else if (a == "--out" && i + 1 < argc) {
            out = argv[++i];
        } else if (a == "--repeats" && i + 1 < argc) {
            repeats = std::atoi(argv[++i]);
            if (repeats < 1) return usage(2);
        } else if (a == "--scene" && i + 1 < argc) {
            only = argv[++i];
        } else if (a == "--help" || a == "-h") {
            return usage(0);
        } else {
            return usage(2);
        }
    }
    if (repeats < 0) repeats = quick ? 1 : 5;
    // The engine's error() reports are counted, not printed: each slow_game run that drops a second of
    // steps says so once (as a game would hear), and those runs are repeated many times.
    setErrorHandler([](const wchar_t*) { ++g_engineErrors; });

    std::vector<SceneInfo> scenes = analyticScenes();
    for (auto& s : contactScenes()) scenes.push_back(std::move(s));
    std::vector<Row> rows;
    const auto t0 = std::chrono::steady_clock::now();
    for (const SceneInfo& scene : scenes) {
        if (!only.empty() && scene.name != only) continue;
        const std::vector<Setting> plan = planFor(scene, quick);
        const auto s0 = std::chrono::steady_clock::now();
        const int runs = runsForSample(scene, quick ? 0.02 : 0.03);
        for (const Setting& s : plan) {
            rows.push_back({scene.name, s.varied, scene.unit, knobsCsv(s.knobs),
                            compareWithBaseline(scene, s.knobs, repeats, runs)});
        }
        std::fprintf(stderr, "%-11s %3zu settings, samples of %d runs, in %5.1f s\n", scene.name.c_str(),
                     plan.size(), runs,
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - s0).count());
    }
    if (rows.empty()) return usage(2);

    // The Pareto front of each scene over (cost ratio, error), errors rounded to 3 significant digits:
    // float round-off (a ball stopped 0.20001 or 0.19999 mm in) is not a difference worth paying for.
    // Rows that change the physics, and so the truth (a combine rule, the drag coefficient), solve another
    // problem: they are measured but never on the front.
    std::vector<bool> front(rows.size(), false);
    for (size_t b = 0; b < rows.size();) {
        size_t e = b;
        std::vector<CostError> pts;
        while (e < rows.size() && rows[e].scene == rows[b].scene) {
            const bool otherProblem = changesTruth(rows[e].varied);
            pts.push_back({otherProblem ? 1e300 : rows[e].c.costRatio,
                           otherProblem ? 1e300 : std::stod(threeDigits(rows[e].c.setting.error))});
            ++e;
        }
        for (size_t i : paretoFront(pts)) front[b + i] = true;
        b = e;
    }

    std::ofstream csv(out);
    if (!csv) {
        std::fprintf(stderr, "bench_tradeoff: cannot write %s\n", out.c_str());
        return 1;
    }
    csv << "scene,varied," << knobsCsvHeader()
        << ",bodies,steps,dropped_steps,ns_per_body_step,cost_ratio,error,error_unit,pareto\n";
    for (size_t i = 0; i < rows.size(); ++i) {
        const Row& r = rows[i];
        char nums[256];
        std::snprintf(nums, sizeof nums, "%d,%lld,%lld,%.1f,%.4f,%.6g", r.c.setting.bodies,
                      r.c.setting.steps / r.c.setting.runs, r.c.setting.dropped / r.c.setting.runs,
                      r.c.nsPerBodyStep, r.c.costRatio, r.c.setting.error);
        csv << r.scene << "," << r.varied << "," << r.knobs << "," << nums << "," << r.unit << ","
            << (front[i] ? 1 : 0) << "\n";
    }
    std::fprintf(stderr,
                 "bench_tradeoff: %zu rows in %.1f s -> %s (repeats %d; the machine may be busy: "
                 "compare cost ratios, measured in interleaved pairs)\n",
                 rows.size(), std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
                 out.c_str(), repeats);
    std::fprintf(stderr,
                 "bench_tradeoff: the engine reported %lld error()s (expected: one per slow_game run that "
                 "dropped a second of steps)\n",
                 g_engineErrors);
    return 0;
}
