// main.cpp - bench_compare: the same scenes on Guardian, Bullet and ODE in one process, one thread, dt 1/60,
// engines interleaved within each repetition (Guardian, Bullet, ODE, then again), sleeping off unless a row
// says asleep. For each row: ms per step of each engine (median over repetitions, building not timed),
// Guardian's time ratio to each, and accuracy figures computed the same way from every engine's poses
// (Scene.cpp), each the median over the repetitions' starts 1 um apart (settling is chaotic). Then the
// broadphase row, the landing row (a pile's overlaps while it lands) and the equal-accuracy rows (the awake
// pyramid at the cheapest setting of each engine's own knob that keeps its top within 5 cm, the median of
// three such starts; heavy on light 1:1,000 at the cheapest that keeps the heavy box within 1 cm of where it
// rests). Options: --quick (each row once, fewer steps), --only TEXT (only the rows whose name contains
// TEXT), --no-ccd (Guardian's continuous collision off: not its default, for finding out what that stage
// costs and does here). On Linux the process stays on the CPU it started on: every engine's every row on the
// same core (StayOnThisCpu.h).
#include "../StayOnThisCpu.h"
#include "Scene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <functional>
#include <random>
#include <string>
#include <thread>
#include <vector>

#ifndef COMPARE_BULLET_VERSION
#define COMPARE_BULLET_VERSION "?"
#endif
#ifndef COMPARE_ODE_VERSION
#define COMPARE_ODE_VERSION "?"
#endif

namespace compare {
namespace {

using Clock = std::chrono::steady_clock;

struct Engine {
    EngineInfo info;
    std::function<std::unique_ptr<Sim>(const SceneDesc&, const SimOptions&)> sim;
    std::function<std::unique_ptr<PairFinder>(const SceneDesc&)> pairs;
};

enum class Extra { None, TopDrift, Sink };

struct Row {
    std::string name;
    SceneDesc scene;
    SimOptions options;
    int steps;
    int reps;
    Extra extra;
};

struct Result {
    double ms = 0;     // per step
    Accuracy acc;      // at the end
    double extra = 0;  // top drift, or how far the heavy box ended below its resting height (m)
    double extra2 = 0; // the heavy box's deepest sink during the run (m)
    double extra3 = 0; // how far the heavy box ended sideways of where it started (m): a stack that walks
};

struct Summary {
    std::string name;
    Result r[3];
};

double seconds(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

Result runOnce(const Engine& e, const Row& row, const SimOptions& options) {
    std::unique_ptr<Sim> sim = e.sim(row.scene, options);
    const size_t last = sim->bodyCount() - 1;
    const BodyState start = sim->state(last);
    const double rest = row.scene.bodies.back().pose.p[1];
    Result r;
    double t = 0;
    for (int i = 0; i < row.steps; ++i) {
        Clock::time_point t0 = Clock::now();
        sim->step();
        t += seconds(t0);
        if (row.extra == Extra::Sink) r.extra2 = std::max(r.extra2, rest - sim->state(last).pose.p[1]);
    }
    r.ms = 1000.0 * t / row.steps;
    std::vector<BodyState> end = readAll(*sim);
    r.acc = measure(row.scene, end);
    if (row.extra == Extra::TopDrift) r.extra = distance(start.pose.p, end[last].pose.p);
    if (row.extra == Extra::Sink) {
        r.extra = rest - end[last].pose.p[1];
        r.extra3 = std::hypot(end[last].pose.p[0] - start.pose.p[0], end[last].pose.p[2] - start.pose.p[2]);
    }
    return r;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0 : v[v.size() / 2];
}

const char* extraLabel(Extra x) {
    return x == Extra::TopDrift ? "top drift mm" : x == Extra::Sink ? "sink end / max, sideways mm" : "";
}

// A settling scene is chaotic: started 1 um apart, the pyramid's top drifted 9.6 to 31.6 mm in 10 s in one
// build, and the 1,000-box pile's 99th percentile of ground overlap after 10 s ranged over 2.1-3.3 mm in ten
// starts, with 1 to 26 boxes still moving. A row's later repetitions start every body up to 1 um off in x and
// z (the same start for every engine), and every accuracy figure reported is the median over them.
Row repetition(const Row& row, int rep) {
    if (rep == 0) return row;
    Row out = row;
    std::mt19937 rng{unsigned(rep)};
    std::uniform_real_distribution<double> offset(-1e-6, 1e-6);
    for (BodyDesc& b : out.scene.bodies) {
        b.pose.p[0] += offset(rng);
        b.pose.p[2] += offset(rng);
    }
    return out;
}

Summary runRow(const std::vector<Engine>& engines, const Row& row) {
    std::printf("\n== %s (%zu bodies, %d steps = %.1f s, %d rep%s, sleeping %s)\n", row.name.c_str(),
                row.scene.bodies.size(), row.steps, row.steps * kDt, row.reps,
                row.reps > 1 ? "s, median" : "", row.options.sleeping ? "on" : "off");
    Summary sum;
    sum.name = row.name;
    std::vector<Result> runs[3];
    for (int rep = 0; rep < row.reps; ++rep) {
        const Row run = repetition(row, rep);
        for (size_t e = 0; e < engines.size(); ++e) {
            runs[e].push_back(runOnce(engines[e], run, row.options));
        }
    }
    std::printf("  %-9s %9s %15s %13s %9s %9s %7s  %s\n", "engine", "ms/step", "ground pen mm", "pair pen mm",
                "ground 99", "pair 99", "moving", extraLabel(row.extra));
    for (size_t e = 0; e < engines.size(); ++e) {
        Result& r = sum.r[e];
        // Each figure's median over the starts (not one start's set).
        auto med = [&](auto field) {
            std::vector<double> v;
            for (const Result& x : runs[e]) v.push_back(double(field(x)));
            return median(v);
        };
        r.ms = med([](const Result& x) { return x.ms; });
        r.acc.groundPenetration = med([](const Result& x) { return x.acc.groundPenetration; });
        r.acc.pairPenetration = med([](const Result& x) { return x.acc.pairPenetration; });
        r.acc.groundPenetration99 = med([](const Result& x) { return x.acc.groundPenetration99; });
        r.acc.pairPenetration99 = med([](const Result& x) { return x.acc.pairPenetration99; });
        r.acc.moving = size_t(med([](const Result& x) { return x.acc.moving; }));
        r.extra = med([](const Result& x) { return x.extra; });
        r.extra2 = med([](const Result& x) { return x.extra2; });
        r.extra3 = med([](const Result& x) { return x.extra3; });
        std::printf("  %-9s %9.3f %15.2f %13.2f %9.2f %9.2f %7zu", engines[e].info.name.c_str(), r.ms,
                    1000 * r.acc.groundPenetration, 1000 * r.acc.pairPenetration,
                    1000 * r.acc.groundPenetration99, 1000 * r.acc.pairPenetration99, r.acc.moving);
        if (row.extra == Extra::TopDrift) std::printf("  %.1f", 1000 * r.extra);
        if (row.extra == Extra::Sink)
            std::printf("  %.1f / %.1f, %.1f", 1000 * r.extra, 1000 * r.extra2, 1000 * r.extra3);
        std::printf("\n");
    }
    std::printf("  time ratio Guardian/Bullet %.2f, Guardian/ODE %.2f\n", sum.r[0].ms / sum.r[1].ms,
                sum.r[0].ms / sum.r[2].ms);
    std::fflush(stdout);
    return sum;
}

void broadphaseRow(const std::vector<Engine>& engines, int boxes, int rounds) {
    SceneDesc scene = scatteredBoxes(boxes);
    std::printf(
        "\n== broadphase only: %d randomly turned unit boxes on a 1.5 m grid, %d calls each (median)\n",
        boxes, rounds);
    // The three engines, then Guardian with its octree space, then Guardian's candidate-pair stage alone in
    // each space (interleaved with them, same rounds).
    std::vector<std::unique_ptr<PairFinder>> finders;
    std::vector<std::string> names, notes;
    for (const Engine& e : engines) {
        finders.push_back(e.pairs(scene));
        names.push_back(e.info.name);
        notes.push_back(e.info.pairsNote);
    }
    finders.push_back(makeGuardianOctreePairs(scene));
    names.push_back("G octree");
    notes.push_back("the same with CreateOctreeCollisionSpace (pairs kept between calls)");
    finders.push_back(makeGuardianCandidatePairs(scene, false));
    names.push_back("G SAP");
    notes.push_back("candidate pairs alone, simple space (boxes, sort and sweep: what Bullet's row times)");
    finders.push_back(makeGuardianCandidatePairs(scene, true));
    names.push_back("G tree");
    notes.push_back("candidate pairs alone, octree space (boxes, the persistent tree and its pair set)");
    const size_t n = finders.size();
    std::vector<size_t> first(n), movedPairs(n), stillPairs(n);
    for (size_t e = 0; e < n; ++e) first[e] = finders[e]->findPairs(); // the first call finds every pair
    std::vector<std::vector<double>> moved(n), still(n);
    for (int round = 0; round < rounds; ++round) {
        std::vector<Pose> poses = jiggled(scene, unsigned(round));
        for (size_t e = 0; e < n; ++e) {
            finders[e]->place(poses);
            Clock::time_point t0 = Clock::now();
            movedPairs[e] = finders[e]->findPairs();
            moved[e].push_back(1000 * seconds(t0));
        }
    }
    // Still: each call comes after the other engines' (its data left the cache meanwhile, as in a game's
    // frame); warm: the same call again at once, its data just read.
    std::vector<std::vector<double>> warm(n);
    for (int round = 0; round < rounds; ++round)
        for (size_t e = 0; e < n; ++e) {
            Clock::time_point t0 = Clock::now();
            stillPairs[e] = finders[e]->findPairs();
            still[e].push_back(1000 * seconds(t0));
            t0 = Clock::now();
            finders[e]->findPairs();
            warm[e].push_back(1000 * seconds(t0));
        }
    std::printf("  %-9s %12s %12s %12s %14s  %s\n", "engine", "moved ms", "still ms", "warm ms",
                "found (moved)", "what is timed");
    std::vector<double> m(n), s(n), w(n);
    for (size_t e = 0; e < n; ++e) {
        m[e] = median(moved[e]);
        s[e] = median(still[e]);
        w[e] = median(warm[e]);
        std::printf("  %-9s %12.3f %12.3f %12.3f %14zu  %s (first call %zu, still %zu)\n", names[e].c_str(),
                    m[e], s[e], w[e], movedPairs[e], notes[e].c_str(), first[e], stillPairs[e]);
    }
    std::printf("  time ratio moved: Guardian/Bullet %.2f, Guardian/ODE %.2f; still: Guardian/Bullet %.2f, "
                "Guardian/ODE %.2f\n",
                m[0] / m[1], m[0] / m[2], s[0] / s[1], s[0] / s[2]);
    std::printf("  octree space: moved Guardian/Bullet %.2f, still %.2f\n", m[3] / m[1], s[3] / s[1]);
    std::printf("  candidate pairs alone / Bullet's dbvt: sort and sweep moved %.2f, still %.2f, warm %.2f; "
                "tree moved %.2f, still %.2f, warm %.2f\n",
                m[4] / m[1], s[4] / s[1], w[4] / w[1], m[5] / m[1], s[5] / s[1], w[5] / w[1]);
    std::fflush(stdout);
}

// A pile while it lands (dropped from up to 15 m, columns of boxes are hit from above): the overlapping
// pairs' 99th percentile and deepest every 0.5 s, each engine from the same start in turn (not timed). The
// rows above measure their poses at the end only.
void landingRow(const std::vector<Engine>& engines, const SimOptions& options, int boxes, int steps) {
    const SceneDesc scene = boxPileScene(boxes);
    std::printf("\n== landing: %d boxes dropped into a pile, the overlapping pairs while it lands (99th "
                "percentile / deepest, mm, every 0.5 s from 0.5 s; one start)\n",
                boxes);
    for (const Engine& e : engines) {
        const std::unique_ptr<Sim> sim = e.sim(scene, options);
        std::printf("  %-9s", e.info.name.c_str());
        for (int step = 1; step <= steps; ++step) {
            sim->step();
            if (step % 30) continue;
            const Accuracy a = measure(scene, readAll(*sim));
            std::printf(" %.0f/%.0f", 1000 * a.pairPenetration99, 1000 * a.pairPenetration);
        }
        std::printf("\n");
        std::fflush(stdout);
    }
}

// The cheapest setting of each engine's own knob (its ladder) at which the row's figure (the pyramid's top
// drift, the heavy box's sink at the end) is within bound; each setting runs from that many starts
// (repetition()), its figure and time their medians.
void equalAccuracyRow(const std::vector<Engine>& engines, const Row& row, int starts, double bound,
                      const char* figure) {
    std::printf(
        "\n== equal accuracy: %s, cheapest setting of each engine's knob that keeps the %s within %.0f mm "
        "after %.1f s (median of %d start%s%s)\n",
        row.name.c_str(), figure, 1000 * bound, row.steps * kDt, starts, starts > 1 ? "s" : "",
        starts > 1 ? " 1 um apart" : "");
    std::string summary;
    for (const Engine& e : engines) {
        std::printf("  %-9s (%s):", e.info.name.c_str(), e.info.knob.c_str());
        bool found = false;
        for (int setting : e.info.ladder) {
            SimOptions o = row.options;
            o.iterations = setting;
            std::vector<double> value, ms;
            for (int start = 0; start < starts; ++start) {
                const Result one = runOnce(e, repetition(row, start), o);
                value.push_back(one.extra);
                ms.push_back(one.ms);
            }
            Result r;
            r.extra = median(value);
            r.ms = median(ms);
            std::printf(" %d -> %.1f mm %.3f ms;", setting, 1000 * r.extra, r.ms);
            std::fflush(stdout);
            if (std::fabs(r.extra) <= bound) {
                char line[200];
                std::snprintf(line, sizeof line, "  %-9s setting %3d: %.3f ms/step, %s %.1f mm\n",
                              e.info.name.c_str(), setting, r.ms, figure, 1000 * r.extra);
                summary += line;
                found = true;
                break;
            }
        }
        if (!found)
            summary +=
                "  " + e.info.name + ": no setting on the ladder keeps the " + figure + " within bound\n";
        std::printf("\n");
    }
    std::printf("%s", summary.c_str());
    std::fflush(stdout);
}

void summaryTable(const std::vector<Summary>& rows) {
    std::printf("\n== summary (ms per step; accuracy Guardian / Bullet / ODE)\n");
    std::printf("| row | Guardian ms | Bullet ms | ODE ms | G/B | G/O | ground pen mm | pair pen mm | "
                "ground p99 mm | pair p99 mm | moving | drift or sink mm |\n"
                "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const Summary& s : rows) {
        std::printf("| %s | %.3f | %.3f | %.3f | %.2f | %.2f | %.1f / %.1f / %.1f | %.1f / %.1f / %.1f | "
                    "%.1f / %.1f / %.1f | %.1f / %.1f / %.1f | %zu / %zu / %zu | ",
                    s.name.c_str(), s.r[0].ms, s.r[1].ms, s.r[2].ms, s.r[0].ms / s.r[1].ms,
                    s.r[0].ms / s.r[2].ms, 1000 * s.r[0].acc.groundPenetration,
                    1000 * s.r[1].acc.groundPenetration, 1000 * s.r[2].acc.groundPenetration,
                    1000 * s.r[0].acc.pairPenetration, 1000 * s.r[1].acc.pairPenetration,
                    1000 * s.r[2].acc.pairPenetration, 1000 * s.r[0].acc.groundPenetration99,
                    1000 * s.r[1].acc.groundPenetration99, 1000 * s.r[2].acc.groundPenetration99,
                    1000 * s.r[0].acc.pairPenetration99, 1000 * s.r[1].acc.pairPenetration99,
                    1000 * s.r[2].acc.pairPenetration99, s.r[0].acc.moving, s.r[1].acc.moving,
                    s.r[2].acc.moving);
        if (s.r[0].extra != 0 || s.r[1].extra != 0 || s.r[2].extra != 0)
            std::printf("%.1f / %.1f / %.1f", 1000 * s.r[0].extra, 1000 * s.r[1].extra, 1000 * s.r[2].extra);
        std::printf(" |\n");
    }
}

} // namespace
} // namespace compare

int main(int argc, char** argv) {
    using namespace compare;
    bool quick = false, noCcd = false;
    std::string only;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--quick") == 0)
            quick = true;
        else if (std::strcmp(argv[i], "--no-ccd") == 0)
            noCcd = true;
        else if (std::strcmp(argv[i], "--only") == 0 && i + 1 < argc)
            only = argv[++i];
        else {
            std::printf("usage: %s [--quick] [--no-ccd] [--only TEXT]\n", argv[0]);
            return 2;
        }
    }
    std::vector<Engine> engines = {{guardianInfo(), makeGuardianSim, makeGuardianPairs},
                                   {bulletInfo(), makeBulletSim, makeBulletPairs},
                                   {odeInfo(), makeOdeSim, makeOdePairs}};
    std::time_t now = std::time(nullptr);
    char date[64];
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    const int cpu = stayOnThisCpu();
    const std::string where = cpu >= 0 ? "kept on CPU " + std::to_string(cpu) : "not kept on one CPU";
    std::printf("bench_compare%s%s, %s, %u hardware threads, one thread used (%s), dt 1/60 s\n",
                quick ? " --quick" : "", noCcd ? " --no-ccd (Guardian's continuous collision off)" : "", date,
                std::thread::hardware_concurrency(), where.c_str());
    std::printf("Bullet package %s, ODE package %s\n", COMPARE_BULLET_VERSION, COMPARE_ODE_VERSION);
    for (const Engine& e : engines)
        std::printf("  %-9s %-6s  defaults: %s\n", e.info.name.c_str(), e.info.precision.c_str(),
                    e.info.defaults.c_str());
    std::printf(
        "Friction 0.5 and restitution 0 for every contact; accuracy from the poses at the end: deepest "
        "ground and pair penetration, bodies faster than 0.05 m/s.\n");
    std::fflush(stdout);

    const int pile = quick ? 120 : 600, reps = quick ? 1 : 3, driftReps = quick ? 1 : 5;
    SimOptions awake, asleep;
    awake.continuous = asleep.continuous = !noCcd;
    asleep.sleeping = true;
    const std::vector<Row> rows = {
        {"rain: 1,000 spheres", rainScene(1000), awake, pile, reps, Extra::None},
        {"box pile: 1,000 boxes", boxPileScene(1000), awake, pile, reps, Extra::None},
        {"box pile: 4,000 boxes", boxPileScene(4000), awake, pile, reps, Extra::None},
        {"pyramid 210 awake", pyramidScene(20), awake, pile, driftReps, Extra::TopDrift},
        {"pyramid 210 asleep", pyramidScene(20), asleep, pile, driftReps, Extra::TopDrift},
        {"heavy on light 1:1,000", heavyOnLightScene(1000), awake, quick ? 120 : 300, reps, Extra::Sink},
        {"heavy on light 1:10,000", heavyOnLightScene(10000), awake, quick ? 120 : 300, reps, Extra::Sink},
    };
    std::vector<Summary> done;
    for (const Row& row : rows)
        if (only.empty() || row.name.find(only) != std::string::npos) done.push_back(runRow(engines, row));
    if (only.empty() || std::string("broadphase").find(only) != std::string::npos)
        broadphaseRow(engines, 10000, quick ? 3 : 10);
    if (only.empty() || std::string("landing").find(only) != std::string::npos)
        landingRow(engines, awake, 1000, quick ? 120 : 360);
    if (only.empty() || std::string("equal accuracy").find(only) != std::string::npos)
        equalAccuracyRow(engines,
                         {"the awake 210-box pyramid", pyramidScene(20), awake, pile, 1, Extra::TopDrift},
                         quick ? 1 : 3, 0.05, "top drift");
    // Bullet and ODE let the light box through at their defaults (1 m): is there a setting that holds it?
    // (One start: the two-body row is not chaotic.)
    if (only.empty() || std::string("equal accuracy heavy").find(only) != std::string::npos)
        equalAccuracyRow(
            engines,
            {"heavy on light 1:1,000", heavyOnLightScene(1000), awake, quick ? 120 : 300, 1, Extra::Sink}, 1,
            0.01, "sink");
    if (!done.empty()) summaryTable(done);
    return 0;
}
