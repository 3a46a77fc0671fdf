// ContactScenes.cpp - the bench_tradeoff scenes with contacts, each with an independently known answer:
// ball rebound (e^2 h), sliding box (v^2 / (2 mu g) with mu combined by the scene's friction rule),
// rolling ball (5/7 v0), stack and pyramid drift (truth 0), and a tunnelling shot (truth: it stops at the
// wall). A bodiless floor plane has a default body's material (friction 0.25, restitution 0.5).
#include "TrialScene.h"
#include "Truth.h"

#include "RBDynamics.h"
#include "World.h"
#include "iPhysicsFrame.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneSettings.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace tradeoff {
namespace {

constexpr float kContactSpacing = 4.0f;
constexpr float kPlaneFriction = 0.25f, kPlaneRestitution = 0.5f; // RBDynamics' defaults

double gravity(World& w) { return -settingsOf(w.scene())->getGravity().y; }

// 16 spheres of radius 0.5 m and restitution 0.8 dropped from 2 m (bottom above the floor). Error: the
// largest |first rebound's peak - e^2 h| (m), e combined from 0.8 and the floor's 0.5 by the rule.
class Rebound final : public TrialScene {
public:
    void build(World& w, const Knobs&) override {
        w.ground();
        for (int i = 0; i < kCopies; ++i) {
            w.sphere(Vector(gridX(i, kContactSpacing), kH + kR, gridZ(i, kContactSpacing)), kR, 1.0f)
                ->getDynamics()
                ->restitution = kE;
        }
        m_rising.assign(kCopies, 0);
        m_peak.assign(kCopies, 0.0);
    }
    void observe(World& w, double) override {
        for (int i = 0; i < kCopies; ++i) {
            const RBDynamics* d = w.bodies()[size_t(i)]->getDynamics();
            if (m_rising[size_t(i)] == 0 && d->velocity.y > 0) m_rising[size_t(i)] = 1; // bounced
            if (m_rising[size_t(i)] == 1) {
                m_peak[size_t(i)] = std::max(m_peak[size_t(i)], double(d->position.y) - kR);
                if (d->velocity.y < 0) m_rising[size_t(i)] = 2; // past the peak
            }
        }
    }
    double error(World&, const Knobs& k, double, double) override {
        const double truth = reboundHeight(combine(k.restitutionRule, kE, kPlaneRestitution), kH);
        double worst = 0;
        for (double p : m_peak) worst = std::max(worst, std::abs(p - truth));
        return worst;
    }

private:
    static constexpr int kCopies = 16;
    static constexpr float kR = 0.5f, kH = 2.0f, kE = 0.8f;
    std::vector<int> m_rising;
    std::vector<double> m_peak;
};

// 16 unit boxes (friction 0.4) resting on the floor, launched along x at 4 m/s (slide) or 16 spheres of
// radius 0.5 m launched sliding at 5 m/s with no spin (roll). Error: slide, the largest |distance - v^2 /
// (2 mu g)| (m); roll, the largest |speed - 5/7 v0| (m/s).
class Slide final : public TrialScene {
public:
    explicit Slide(bool roll) : m_roll(roll) {}
    void build(World& w, const Knobs&) override {
        w.ground();
        for (int i = 0; i < kCopies; ++i) {
            const Vector at(gridX(i, kContactSpacing), 0.5f, gridZ(i, 2 * kContactSpacing));
            RBDynamics* d = m_roll ? w.sphere(at, 0.5f, 1.0f)->getDynamics()
                                   : w.box(at, Vector(0.5f, 0.5f, 0.5f), 1.0f)->getDynamics();
            d->friction = kFriction;
            d->velocity = Vector(m_roll ? kRollV : kSlideV, 0, 0);
            m_x0.push_back(at.x);
        }
    }
    double error(World& w, const Knobs& k, double, double) override {
        const double mu = combine(k.frictionRule, kFriction, kPlaneFriction);
        double worst = 0;
        for (size_t i = 0; i < w.bodies().size(); ++i) {
            const RBDynamics* d = w.bodies()[i]->getDynamics();
            const double e =
                m_roll ? std::abs(std::hypot(d->velocity.x, d->velocity.z) - rollingSpeed(kRollV))
                       : std::abs(d->position.x - m_x0[i] - stoppingDistance(kSlideV, mu, gravity(w)));
            worst = std::max(worst, e);
        }
        return worst;
    }

private:
    static constexpr int kCopies = 16;
    static constexpr float kFriction = 0.4f, kSlideV = 4.0f, kRollV = 5.0f;
    bool m_roll;
    std::vector<float> m_x0;
};

// Unit boxes at rest: 4 towers of 5 (stack) or one pyramid with a base of 8, 36 boxes. Error: the largest
// displacement of a top box from where it started (m); the truth is that nothing moves.
class Drift final : public TrialScene {
public:
    explicit Drift(bool pyramid) : m_pyramid(pyramid) {}
    void build(World& w, const Knobs&) override {
        w.ground();
        const Vector half(0.5f, 0.5f, 0.5f);
        if (m_pyramid) {
            for (int row = 0; row < 8; ++row)
                for (int i = 0; i < 8 - row; ++i)
                    w.box(Vector(-0.5f * (7 - row) + i, 0.5f + row, 0), half, 1.0f);
            m_tops.push_back(w.bodies().size() - 1);
        } else {
            for (int t = 0; t < 4; ++t) {
                for (int i = 0; i < 5; ++i) w.box(Vector(t * kContactSpacing, 0.5f + i, 0), half, 1.0f);
                m_tops.push_back(w.bodies().size() - 1);
            }
        }
        for (size_t i : m_tops) m_start.push_back(w.bodies()[i]->getDynamics()->position);
    }
    double error(World& w, const Knobs&, double, double) override {
        double worst = 0;
        for (size_t j = 0; j < m_tops.size(); ++j)
            worst = std::max(worst,
                             double((w.bodies()[m_tops[j]]->getDynamics()->position - m_start[j]).length()));
        return worst;
    }

private:
    bool m_pyramid;
    std::vector<size_t> m_tops;
    std::vector<Vector> m_start;
};

// 16 floating balls of radius 0.1 m at 150 m/s toward a fixed wall 0.1 m thick whose face is 3 m ahead.
// Error: how far a ball's front got past the wall's face, at worst over the run (m); 0 for a stop.
class Tunnel final : public TrialScene {
public:
    void build(World& w, const Knobs&) override {
        for (int i = 0; i < kCopies; ++i) {
            const float z = float(i) * kContactSpacing;
            w.fixedBox(Vector(kFace + 0.05f, 0, z), Vector(0.05f, 1.0f, 1.0f));
            RBDynamics* d = w.sphere(Vector(0, 0, z), kR, 1.0f)->getDynamics();
            d->physicsType = PHYS_Floating;
            d->velocity = Vector(150, 0, 0);
        }
        m_worst = 0;
    }
    void observe(World& w, double) override {
        for (iPhysicsFrame* f : w.bodies()) {
            const RBDynamics* d = f->getDynamics();
            if (d->physicsType == PHYS_FixedInSpace) continue;
            m_worst = std::max(m_worst, double(d->position.x) + kR - kFace);
        }
    }
    double error(World&, const Knobs&, double, double) override { return m_worst; }

private:
    static constexpr int kCopies = 16;
    static constexpr float kR = 0.1f, kFace = 3.0f;
    double m_worst = 0;
};

template <class T, class... A> std::unique_ptr<TrialScene> make(A... a) {
    return std::unique_ptr<TrialScene>(new T(a...));
}

} // namespace

std::vector<SceneInfo> contactScenes() {
    const Knobs base;
    return {
        {"rebound", "m", 2.0, base, [] { return make<Rebound>(); }},
        {"slide", "m", 4.5, base, [] { return make<Slide>(false); }},
        {"roll", "m/s", 1.5, base, [] { return make<Slide>(true); }},
        {"stack", "m", 5.0, base, [] { return make<Drift>(false); }},
        {"pyramid", "m", 5.0, base, [] { return make<Drift>(true); }},
        {"tunnel", "m", 0.3, base, [] { return make<Tunnel>(); }},
    };
}

} // namespace tradeoff
