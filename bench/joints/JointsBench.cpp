// JointsBench.cpp - what joints cost: a scene of chains of one joint kind against the same bodies with no
// joints (falling freely, not solved), the two stepped alternately in the same run (so contention on a shared
// machine hits both alike); and the iterations knob (setSolverIterations 2, 4, 8) on hinge chains, with the
// chains' stretch, so that the speed/accuracy trade is seen in one table. Scenes:
//  * 10 chains of 20 links (200 bodies, 200 joints: the top link to the world, each other to the one
//    above): 0.5 kg boxes 0.1 m long (JointTestSupport.h's way: CreateRigidBody without geometry, so no
//    collision), hanging straight down, the last link of each kicked sideways at 0.5 m/s so that the chains
//    swing; sleeping off (every step solves every joint). Ball, hinge (axis z), slider (axis x) and fixed
//    joints join at the shared end point; distance joints and springs (200 N/m, 10 N s/m, at rest) join a
//    link's top to the bottom of the one above across a 2 cm gap. SpringStiff: the same springs at
//    2,000 N/m, a chain that gains energy until its states are NaN (errors_per_step: the scene's validation
//    reports and restores them), kept here as the reproducer;
//  * tethers (Physics/JointTethers.cpp): 10 chains of 10 ball-jointed links with an 11th body at the bottom,
//    a link's box and joint, kicked like the others: BallHeavyEnd 5 kg (10 times a link: a tether from the
//    world to each), BallLikeEnd 0.5 kg (a like link: no tether, only the scan of the masses), each against
//    the same bodies unjoined, so that the two rows set heavy-ended against like-ended at 110 joints each;
//  * 60 steps at 60 Hz untimed, then 600 timed. BM_Chains/<kind> steps one kind against the free bodies;
//    BM_AllKinds steps the six kinds and the free bodies in turn (the README's table).
// Counters: ms per step of each scene; ratio (jointed / free); ns_per_joint_step, the added time per joint
// and step ((jointed - free) / 200, or / 110); allocs_per_step (operator new calls inside the timed steps,
// from this program's counting operator new); errors_per_step (error() reports inside them; a counting
// handler replaces the stderr line); finite (1 when every body's state is finite at the end); gap and
// gap_swinging (ball, hinge, fixed: the largest anchor separation / link length after any step, and after any
// timed step). The knob: ms and ratio to 4 iterations, ns per joint-step against the free scene, stretch
// (largest anchor separation after any step, from the first, / link length) and stretch_swinging (after the
// warm-up).
#include "RBDynamics.h"
#include "World.h"
#include "iBallJoint.h"
#include "iDistanceJoint.h"
#include "iFixedJoint.h"
#include "iHingeJoint.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneSettings.h"
#include "iRigidBody.h"
#include "iSliderJoint.h"
#include "iSpring.h"
#include "iUtilities.h"

#include "../TimedScene.h"

#include "../PinnedBenchmarkMain.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <new>
#include <string>
#include <vector>

// Every operator new of this program counted: the steps' allocations are the count's change across them.
// Not inlined, so that the compiler pairs new with delete, not with the malloc and free inside them.
namespace {
std::atomic<long> g_allocations{0};
}
[[gnu::noinline]] void* operator new(std::size_t n) {
    g_allocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
[[gnu::noinline]] void operator delete(void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace {

enum class Kind { None, Ball, Hinge, Slider, Fixed, Distance, Spring, SpringStiff };

constexpr int kChains = 10, kLinks = 20;
constexpr float kHalf = 0.05f, kLink = 2 * kHalf, kGap = 0.02f, kMass = 0.5f, kKick = 0.5f;
constexpr int kWarmup = 60, kSteps = 600;

// Each chain's bodies and the mass of its last one (the others are links of kMass).
struct Shape {
    int bodies;
    float endMass;
};
constexpr Shape kPlain{kLinks, kMass}, kHeavyEnd{11, 5.0f}, kLikeEnd{11, kMass};

// A box of mass m 0.1 m tall (half extents 0.02, 0.05, 0.02) at p, with a box's inertia and no geometry.
iRigidBody* linkBody(const Vector& p, float m = kMass) {
    iRigidBody* b = CreateRigidBody(nullptr);
    RBDynamics& d = b->getDynamics();
    d.mass = m;
    d.position = p;
    const float hx = 0.02f, hy = kHalf, hz = 0.02f;
    Matrix inertia(1);
    inertia.m11 = m * (hy * hy + hz * hz) / 3;
    inertia.m22 = m * (hx * hx + hz * hz) / 3;
    inertia.m33 = m * (hx * hx + hy * hy) / 3;
    d.setInertiaTensor(inertia);
    return b;
}

// A joint's anchor on body (nullptr: the world) in world coordinates, at the body's pose now.
Vector worldAnchor(const iRigidBody* body, const Vector& local) {
    if (!body) return local;
    const RBDynamics& d = body->getDynamics();
    return d.position + local * d.orientation;
}

bool finite(const Vector& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The chains of one kind and shape (None: the same bodies, unjoined) in a scene of their own, at n solver
// iterations.
class ChainScene {
public:
    ChainScene(Kind kind, int iterations, Shape shape = kPlain) : m_kind(kind), m_shape(shape) {
        m_timed = std::make_unique<TimedScene>([&](World& w) {
            settingsOf(w.scene())->setSleepingEnabled(false);
            settingsOf(w.scene())->setSolverIterations(iterations);
            build();
        });
    }
    ~ChainScene() {
        for (iJoint* j : m_joints) j->Delete();
        m_timed.reset(); // the scene deletes its bodies
    }
    ChainScene(const ChainScene&) = delete;
    ChainScene& operator=(const ChainScene&) = delete;

    double step(int i) { return m_timed->step(i); }
    size_t jointCount() const { return m_joints.size(); }
    // The largest anchor separation of the point joints (ball, hinge, fixed) now, over the link length.
    float gap() const {
        if (m_kind != Kind::Ball && m_kind != Kind::Hinge && m_kind != Kind::Fixed) return 0;
        float worst = 0;
        for (const iJoint* j : m_joints) {
            const Vector a = worldAnchor(j->getBodyA(), j->getLocalAnchorA());
            const Vector b = worldAnchor(j->getBodyB(), j->getLocalAnchorB());
            worst = std::max(worst, (a - b).length());
        }
        return worst / kLink;
    }
    bool allFinite() const {
        for (const iRigidBody* b : m_links) {
            const RBDynamics& d = b->getDynamics();
            if (!finite(d.position) || !finite(d.velocity)) return false;
        }
        for (const iJoint* j : m_joints)
            if (!finite(j->getReactionForce()) || !finite(j->getReactionTorque())) return false;
        return true;
    }

private:
    void build() {
        const bool gapped = m_kind == Kind::Distance || m_kind == Kind::Spring || m_kind == Kind::SpringStiff;
        const float pitch = gapped ? kLink + kGap : kLink;
        for (int c = 0; c < kChains; ++c) {
            const float x = float(c);
            iRigidBody* above = nullptr;
            for (int i = 0; i < m_shape.bodies; ++i) {
                const float top = -pitch * float(i) - (gapped ? kGap : 0.0f); // this link's top
                const bool last = i == m_shape.bodies - 1;
                iRigidBody* b = linkBody(Vector(x, top - kHalf, 0), last ? m_shape.endMass : kMass);
                if (last) b->getDynamics().velocity = Vector(kKick, 0, 0);
                m_links.push_back(b);
                // where it hangs from: the bottom of the link above, or the world point (x, 0, 0)
                const Vector hang(x, above ? top + (gapped ? kGap : 0.0f) : 0.0f, 0);
                join(b, above, Vector(x, top, 0), hang);
                above = b;
            }
        }
    }
    void join(iRigidBody* b, iRigidBody* above, const Vector& top, const Vector& hang) {
        iJoint* j = nullptr;
        switch (m_kind) {
        case Kind::None:
            return;
        case Kind::Ball:
            j = CreateBallJoint(b, above, top);
            break;
        case Kind::Hinge:
            j = CreateHingeJoint(b, above, top, Vector(0, 0, 1));
            break;
        case Kind::Slider:
            j = CreateSliderJoint(b, above, top, Vector(1, 0, 0));
            break;
        case Kind::Fixed:
            j = CreateFixedJoint(b, above, top);
            break;
        case Kind::Distance:
            j = CreateDistanceJoint(b, above, top, hang);
            break;
        case Kind::Spring:
            j = CreateSpring(b, above, top, hang, kGap, 200.0f, 10.0f);
            break;
        case Kind::SpringStiff:
            j = CreateSpring(b, above, top, hang, kGap, 2000.0f, 10.0f);
            break;
        }
        if (!j) std::abort(); // a factory refused: the bench's scene is wrong
        m_joints.push_back(j);
    }

    Kind m_kind;
    Shape m_shape;
    std::unique_ptr<TimedScene> m_timed;
    std::vector<iRigidBody*> m_links;
    std::vector<iJoint*> m_joints;
};

// What alternate() measured for each scene.
struct Measured {
    double seconds = 0; // timed steps only
    long allocations = 0;
    unsigned long errors = 0;
    float gap = 0;         // the largest gap() seen after any step, warm-up included
    float gapSwinging = 0; // after any timed step
};

void countOnly(const wchar_t*) {} // error() still counts (errorCount()); nothing printed

// Steps every scene warmup + steps times, rotating which goes first each step; times the last steps.
std::vector<Measured> alternate(const std::vector<ChainScene*>& scenes, int warmup, int steps) {
    const ErrorHandler old = setErrorHandler(&countOnly);
    std::vector<Measured> m(scenes.size());
    const size_t n = scenes.size();
    for (int i = 1; i <= warmup + steps; ++i) {
        for (size_t k = 0; k < n; ++k) {
            const size_t s = (k + size_t(i)) % n;
            const long before = g_allocations.load(std::memory_order_relaxed);
            const unsigned long errorsBefore = errorCount();
            const double t = scenes[s]->step(i);
            const float gap = scenes[s]->gap();
            if (i > warmup) {
                m[s].seconds += t;
                m[s].allocations += g_allocations.load(std::memory_order_relaxed) - before;
                m[s].errors += errorCount() - errorsBefore;
                m[s].gapSwinging = std::max(m[s].gapSwinging, gap);
            }
            m[s].gap = std::max(m[s].gap, gap);
        }
    }
    setErrorHandler(old);
    return m;
}

// One kind's chains against the same bodies unjoined.
void BM_Chains(benchmark::State& state, Kind kind, Shape shape = kPlain) {
    std::vector<Measured> m;
    size_t joints = 0;
    bool ok = true;
    for (auto _ : state) {
        state.PauseTiming();
        auto jointed = std::make_unique<ChainScene>(kind, 4, shape);
        auto free = std::make_unique<ChainScene>(Kind::None, 4, shape);
        state.ResumeTiming();
        m = alternate({jointed.get(), free.get()}, kWarmup, kSteps);
        state.PauseTiming(); // the checks and destructors are not measured
        joints = jointed->jointCount();
        ok = jointed->allFinite() && free->allFinite();
        jointed.reset();
        free.reset();
        state.ResumeTiming();
    }
    const double perStep = 1.0 / double(kSteps);
    state.counters["ms_jointed"] = 1e3 * m[0].seconds * perStep;
    state.counters["ms_free"] = 1e3 * m[1].seconds * perStep;
    state.counters["ratio"] = m[1].seconds > 0 ? m[0].seconds / m[1].seconds : 0.0;
    state.counters["ns_per_joint_step"] = 1e9 * (m[0].seconds - m[1].seconds) * perStep / double(joints);
    state.counters["allocs_per_step"] = double(m[0].allocations) * perStep;
    state.counters["allocs_per_step_free"] = double(m[1].allocations) * perStep;
    state.counters["errors_per_step"] = double(m[0].errors + m[1].errors) * perStep;
    state.counters["finite"] = ok ? 1 : 0;
    state.counters["gap"] = m[0].gap;
    state.counters["gap_swinging"] = m[0].gapSwinging;
}

// Every kind's chains (SpringStiff aside) and the free bodies, the seven stepped in turn: the kinds against
// each other and against the same bodies unjoined, all in one run. Counters per kind: ns_<kind> (per
// joint-step, against the free scene), x_<kind> (the kind's scene / the free one).
void BM_AllKinds(benchmark::State& state) {
    const Kind kinds[] = {Kind::Ball, Kind::Hinge, Kind::Slider, Kind::Fixed, Kind::Distance, Kind::Spring};
    const char* names[] = {"ball", "hinge", "slider", "fixed", "distance", "spring"};
    std::vector<Measured> m;
    size_t joints = 0;
    bool ok = true;
    for (auto _ : state) {
        state.PauseTiming();
        std::vector<std::unique_ptr<ChainScene>> owned;
        for (Kind k : kinds) owned.push_back(std::make_unique<ChainScene>(k, 4));
        owned.push_back(std::make_unique<ChainScene>(Kind::None, 4));
        std::vector<ChainScene*> scenes;
        for (auto& s : owned) scenes.push_back(s.get());
        state.ResumeTiming();
        m = alternate(scenes, kWarmup, kSteps);
        state.PauseTiming();
        joints = owned[0]->jointCount();
        ok = true;
        for (auto& s : owned) ok = ok && s->allFinite();
        owned.clear();
        state.ResumeTiming();
    }
    const double perStep = 1.0 / double(kSteps), free = m.back().seconds;
    long allocations = 0;
    unsigned long errors = 0;
    for (size_t k = 0; k < 6; ++k) {
        state.counters[std::string("ns_") + names[k]] =
            1e9 * (m[k].seconds - free) * perStep / double(joints);
        state.counters[std::string("x_") + names[k]] = free > 0 ? m[k].seconds / free : 0.0;
        allocations += m[k].allocations;
        errors += m[k].errors;
    }
    state.counters["ms_free"] = 1e3 * free * perStep;
    state.counters["allocs_per_step"] = double(allocations + m.back().allocations) * perStep;
    state.counters["errors_per_step"] = double(errors + m.back().errors) * perStep;
    state.counters["finite"] = ok ? 1 : 0;
}

// Hinge chains at 2, 4 and 8 solver iterations and the free bodies, the four stepped in turn.
void BM_HingeIterations(benchmark::State& state) {
    const int iterations[] = {2, 4, 8};
    std::vector<Measured> m;
    size_t joints = 0;
    bool ok = true;
    for (auto _ : state) {
        state.PauseTiming();
        std::vector<std::unique_ptr<ChainScene>> owned;
        for (int n : iterations) owned.push_back(std::make_unique<ChainScene>(Kind::Hinge, n));
        owned.push_back(std::make_unique<ChainScene>(Kind::None, 4));
        std::vector<ChainScene*> scenes;
        for (auto& s : owned) scenes.push_back(s.get());
        state.ResumeTiming();
        m = alternate(scenes, kWarmup, kSteps);
        state.PauseTiming();
        joints = owned[0]->jointCount();
        ok = true;
        for (auto& s : owned) ok = ok && s->allFinite();
        owned.clear();
        state.ResumeTiming();
    }
    const double perStep = 1.0 / double(kSteps), free = m[3].seconds;
    for (size_t k = 0; k < 3; ++k) {
        const std::string n = std::to_string(iterations[k]);
        state.counters["ms_" + n] = 1e3 * m[k].seconds * perStep;
        state.counters["ratio_" + n] = m[1].seconds > 0 ? m[k].seconds / m[1].seconds : 0.0;
        state.counters["ns_per_joint_step_" + n] = 1e9 * (m[k].seconds - free) * perStep / double(joints);
        state.counters["stretch_" + n] = m[k].gap;
        state.counters["stretch_swinging_" + n] = m[k].gapSwinging;
    }
    long allocations = 0;
    unsigned long errors = 0;
    for (const Measured& x : m) {
        allocations += x.allocations;
        errors += x.errors;
    }
    state.counters["ms_free"] = 1e3 * free * perStep;
    state.counters["allocs_per_step"] = double(allocations) * perStep;
    state.counters["errors_per_step"] = double(errors) * perStep;
    state.counters["finite"] = ok ? 1 : 0;
}

} // namespace

BENCHMARK_CAPTURE(BM_Chains, Ball, Kind::Ball)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(BM_Chains, Hinge, Kind::Hinge)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(BM_Chains, Slider, Kind::Slider)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(BM_Chains, Fixed, Kind::Fixed)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(BM_Chains, Distance, Kind::Distance)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(BM_Chains, Spring, Kind::Spring)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(BM_Chains, SpringStiff, Kind::SpringStiff)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(BM_Chains, BallHeavyEnd, Kind::Ball, kHeavyEnd)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_Chains, BallLikeEnd, Kind::Ball, kLikeEnd)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_AllKinds)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_HingeIterations)->Unit(benchmark::kMillisecond)->Iterations(1);

GUARDIAN_PINNED_BENCHMARK_MAIN()
