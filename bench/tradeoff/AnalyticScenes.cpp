// AnalyticScenes.cpp - the bench_tradeoff scenes without contacts, each with a closed-form truth (Truth.h):
// projectile, fall with quadratic drag, circular orbit (inverse-square force generator), undamped spring
// (force generator), torque-free asymmetric top, and a projectile under a slow game (frames of 50 ms: what
// the max-steps cap drops). Every scene is 64 copies 10 m apart, so a run is long enough to time.
#include "TrialScene.h"
#include "Truth.h"

#include "RBDynamics.h"
#include "World.h"
#include "iForceGenerator.h"
#include "iPhysicsFrame.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneHooks.h"
#include "iPhysicsSceneSettings.h"
#include "iRigidBody.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace tradeoff {
namespace {

constexpr int kAnalyticCopies = 64;
constexpr float kAnalyticSpacing = 10.0f;

Vec3d toD(const Vector& v) { return {v.x, v.y, v.z}; }
Vector start(int i) { return Vector(gridX(i, kAnalyticSpacing), 0, gridZ(i, kAnalyticSpacing)); }

// A projectile thrown at (3, 8, 1) m/s; error: the largest |x - (x0 + v0 t + g t^2 / 2)| (m) over the
// copies after the run. With truthAtEngineTime the truth is taken at the game's clock, not the steps
// taken: a step dropped by the max-steps cap is time the body never moved.
class Projectile final : public TrialScene {
public:
    explicit Projectile(bool truthAtEngineTime) : m_engineTime(truthAtEngineTime) {}
    void build(World& w, const Knobs&) override {
        for (int i = 0; i < kAnalyticCopies; ++i)
            w.sphere(start(i), 0.1f, 1.0f)->getDynamics()->velocity = m_v0;
    }
    double error(World& w, const Knobs&, double simTime, double engineTime) override {
        const double t = m_engineTime ? engineTime : simTime;
        const Vec3d g = toD(settingsOf(w.scene())->getGravity());
        double worst = 0;
        for (size_t i = 0; i < w.bodies().size(); ++i) {
            const Vec3d truth = projectileAt(toD(start(int(i))), toD(m_v0), g, t);
            worst = std::max(worst, distance(toD(w.bodies()[i]->getDynamics()->position), truth));
        }
        return worst;
    }

private:
    bool m_engineTime;
    Vector m_v0 = Vector(3, 8, 1);
};

// Dropped from rest with the drag coefficient of the knobs (m = 1 kg, a sphere of 1 m^2 cross-section);
// error: the largest |fallen - vt^2 / g ln cosh(g t / vt)| (m).
class DragFall final : public TrialScene {
public:
    static constexpr double kRadius = 0.5641896; // pi r^2 = 1 m^2
    void build(World& w, const Knobs&) override {
        for (int i = 0; i < kAnalyticCopies; ++i) w.sphere(start(i), float(kRadius), 1.0f);
    }
    double error(World& w, const Knobs& k, double t, double) override {
        const double g = -settingsOf(w.scene())->getGravity().y;
        const double truth = dragFallDistance(1.0, k.drag, kPi * kRadius * kRadius, g, t);
        double worst = 0;
        for (iPhysicsFrame* f : w.bodies())
            worst = std::max(worst, std::abs(-f->getDynamics()->position.y - truth));
        return worst;
    }
};

// A force generator pulling toward a centre: inverse-square (orbit) or linear (spring).
class CentralForce final : public iForceGenerator {
public:
    CentralForce(const Vector& c, double strength, bool inverseSquare)
        : m_c(c), m_k(strength), m_inverseSquare(inverseSquare) {}
    void addForces(const iRigidBody* body, const RigidBodyState& s, Vector& force, Vector&) override {
        const double m = body->getDynamics().mass;
        const double dx = s.position.x - m_c.x, dy = s.position.y - m_c.y, dz = s.position.z - m_c.z;
        double f; // force per metre of offset, toward the centre
        if (m_inverseSquare) {
            const double d = std::sqrt(dx * dx + dy * dy + dz * dz);
            f = m_k * m / (d * d * d); // GM m / d^2 along -d/|d|
        } else {
            f = m_k; // spring stiffness
        }
        force -= Vector(float(f * dx), float(f * dy), float(f * dz));
    }

private:
    Vector m_c;
    double m_k;
    bool m_inverseSquare;
};

// Floating bodies held by a CentralForce each. Orbit: radius 0.5 m, period 1 s, 2 periods; spring: k = 4
// pi^2 N/m, m = 1 kg (period 1 s), released 0.5 m from its anchor, 4 periods. Error: the largest distance
// from the closed-form position at the end (m).
class Central final : public TrialScene {
public:
    explicit Central(bool orbit) : m_orbit(orbit) {}
    void build(World& w, const Knobs&) override {
        for (int i = 0; i < kAnalyticCopies; ++i) {
            iPhysicsFrame* f = w.sphere(start(i) + Vector(kRadius, 0, 0), 0.05f, 1.0f);
            RBDynamics* d = f->getDynamics();
            d->physicsType = PHYS_Floating;
            if (m_orbit) d->velocity = Vector(0, float(2 * kPi * kRadius / kPeriod), 0);
            m_forces.push_back(std::make_unique<CentralForce>(
                start(i), m_orbit ? orbitGM(kRadius, kPeriod) : 4 * kPi * kPi / (kPeriod * kPeriod),
                m_orbit));
            hooksOf(w.scene())->addForceGenerator(f->getRB(), m_forces.back().get());
        }
    }
    double error(World& w, const Knobs&, double t, double) override {
        double worst = 0;
        for (size_t i = 0; i < w.bodies().size(); ++i) {
            const Vec3d c = toD(start(int(i)));
            Vec3d truth = orbitAt(c, kRadius, kPeriod, t);
            if (!m_orbit) truth = {c.x + springAt(kRadius, 4 * kPi * kPi, 1.0, t), c.y, c.z};
            worst = std::max(worst, distance(toD(w.bodies()[i]->getDynamics()->position), truth));
        }
        return worst;
    }

private:
    static constexpr double kPeriod = 1.0;
    static constexpr float kRadius = 0.5f;
    bool m_orbit;
    std::vector<std::unique_ptr<CentralForce>> m_forces;
};

// A floating 1 kg box of half extents (0.5, 0.3, 0.1) m spun mostly about its intermediate axis (the
// unstable one: it tumbles), torque-free for 3 s. Error: the largest relative error of its rotational
// energy against 1/2 w.I w computed from the box formula at the start (|L| is the integrated state, so
// the engine keeps it exactly: README).
class Top final : public TrialScene {
public:
    void build(World& w, const Knobs&) override {
        for (int i = 0; i < kAnalyticCopies; ++i) {
            RBDynamics* d = w.box(start(i), Vector(kH[0], kH[1], kH[2]), 1.0f)->getDynamics();
            d->physicsType = PHYS_Floating;
            d->angularVelocity = Vector(float(kW.x), float(kW.y), float(kW.z));
        }
    }
    double error(World& w, const Knobs&, double, double) override {
        const double truth = boxSpinEnergy(1.0, kH[0], kH[1], kH[2], kW);
        double worst = 0;
        for (iPhysicsFrame* f : w.bodies()) {
            const RBDynamics* d = f->getDynamics();
            const double e = 0.5 * (double(d->angularVelocity.x) * d->angularMomentum.x +
                                    double(d->angularVelocity.y) * d->angularMomentum.y +
                                    double(d->angularVelocity.z) * d->angularMomentum.z);
            worst = std::max(worst, std::abs(e - truth) / truth);
        }
        return worst;
    }

private:
    static constexpr float kH[3] = {0.5f, 0.3f, 0.1f};
    static constexpr Vec3d kW = {0.05, 6.0, 0.05};
};

} // namespace

std::vector<SceneInfo> analyticScenes() {
    std::vector<SceneInfo> s;
    Knobs base;
    s.push_back(
        {"projectile", "m", 2.0, base, [] { return std::unique_ptr<TrialScene>(new Projectile(false)); }});
    Knobs drag = base;
    drag.drag = 0.5f; // terminal speed 5.7 m/s
    s.push_back({"drag_fall", "m", 2.0, drag, [] { return std::unique_ptr<TrialScene>(new DragFall()); }});
    s.push_back({"orbit", "m", 2.0, base, [] { return std::unique_ptr<TrialScene>(new Central(true)); }});
    s.push_back({"spring", "m", 4.0, base, [] { return std::unique_ptr<TrialScene>(new Central(false)); }});
    s.push_back({"top", "relative energy", 3.0, base, [] { return std::unique_ptr<TrialScene>(new Top()); }});
    Knobs slow = base;
    slow.frameMs = 50; // a 20 fps game: 3 steps an update at 60 Hz
    s.push_back({"slow_game", "m at engine time", 3.0, slow,
                 [] { return std::unique_ptr<TrialScene>(new Projectile(true)); }});
    return s;
}

} // namespace tradeoff
