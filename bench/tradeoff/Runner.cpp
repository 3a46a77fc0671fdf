// Runner.cpp - builds a scene through the public API with a setting's knobs, times its updates with a
// steady clock and compares it with the baseline in interleaved pairs (Runner.h).
#include "Runner.h"

#include "RBDynamics.h"
#include "World.h"
#include "iCollisionListener.h"
#include "iOctreeCollisionSpace.h"
#include "iPhysicsFrame.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneSettings.h"
#include "iPhysicsSceneStats.h"
#include "iRigidBody.h"
#include "iSimpleCollisionSpace.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

namespace tradeoff {
namespace {

// What a game's listener does at the least: notice the hit.
class CountingListener final : public iCollisionListener {
public:
    void HitWall(iRigidBody*, Vector, Vector) override { ++hits; }
    long long hits = 0;
};

double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

} // namespace

RunResult runOnce(const SceneInfo& info, const Knobs& k) {
    iPhysicsScene* scene = CreatePhysicsScene(nullptr);
    iPhysicsSceneSettings* s = settingsOf(scene);
    s->setIntegrator(k.integrator);
    s->setStepRate(k.stepRate);
    s->setSolverIterations(k.iterations);
    s->setMaxStepsPerUpdate(k.maxSteps);
    s->setFrictionRule(k.frictionRule);
    s->setRestitutionRule(k.restitutionRule);
    s->setSleepingEnabled(k.sleeping);
    s->setContinuousCollisionEnabled(k.continuous);
    const size_t samples = size_t(k.samplesPerSecond);
    iCollisionSpace* space = k.space == SpaceKind::Simple ? CreateSimpleCollisionSpace(samples)
                                                          : CreateOctreeCollisionSpace(samples);
    RunResult r;
    CountingListener listener;
    {
        auto trial = info.make();
        World world(scene, space); // owns the space from here
        trial->build(world, k);
        for (iPhysicsFrame* f : world.bodies()) {
            RBDynamics* d = f->getDynamics();
            if (d->physicsType == PHYS_FixedInSpace) continue;
            ++r.bodies;
            if (k.drag > 0) d->dragCoefficient = k.drag;
            if (k.listeners) f->getRB()->attachListener(&listener);
        }
        const iPhysicsSceneStats* stats = statsOf(scene);
        scene->update(0); // sets the time base only
        const int frames = int(info.seconds * 1000.0 / k.frameMs + 0.5);
        using Clock = std::chrono::steady_clock;
        Clock::duration spent{};
        for (int i = 1; i <= frames; ++i) {
            const auto t0 = Clock::now();
            scene->update(i * k.frameMs);
            spent += Clock::now() - t0;
            trial->observe(world, double(stats->getStepCount()) / k.stepRate);
        }
        r.seconds = std::chrono::duration<double>(spent).count();
        r.steps = stats->getStepCount();
        r.dropped = stats->getDroppedStepCount();
        r.error = trial->error(world, k, double(r.steps) / k.stepRate, frames * k.frameMs / 1000.0);
        for (iPhysicsFrame* f : world.bodies()) f->getRB()->detachListener(&listener);
    } // the world deletes its bodies, shapes and space; then the trial (its force generators) goes
    scene->Delete();
    return r;
}

RunResult runRepeated(const SceneInfo& info, const Knobs& k, int runs) {
    RunResult total = runOnce(info, k);
    for (int i = 1; i < runs; ++i) {
        const RunResult r = runOnce(info, k);
        total.seconds += r.seconds;
        total.steps += r.steps;
        total.dropped += r.dropped;
        ++total.runs;
    }
    return total;
}

int runsForSample(const SceneInfo& info, double targetSeconds) {
    runOnce(info, info.baseline); // warm-up: first allocations, caches
    const double one = runOnce(info, info.baseline).seconds;
    return one <= 0 ? 1 : std::max(1, int(std::ceil(targetSeconds / one)));
}

Comparison compareWithBaseline(const SceneInfo& info, const Knobs& k, int repeats, int runs) {
    std::vector<double> ratios, ns;
    Comparison c{};
    for (int i = 0; i < repeats; ++i) {
        RunResult base, set;
        if (i % 2 == 0) {
            base = runRepeated(info, info.baseline, runs);
            set = runRepeated(info, k, runs);
        } else {
            set = runRepeated(info, k, runs);
            base = runRepeated(info, info.baseline, runs);
        }
        ratios.push_back(base.seconds > 0 ? set.seconds / base.seconds : 0);
        ns.push_back(set.nsPerBodyStep());
        c.setting = set;
    }
    c.costRatio = median(ratios);
    c.nsPerBodyStep = median(ns);
    return c;
}

} // namespace tradeoff
