// GuardianScenes.cpp - bench_compare's adapter for our engine: builds a SceneDesc through the public API only
// (Interfaces/ and ReferenceGame's World helper, as the other benchmarks do), steps it with
// iPhysicsScene::update at 60 Hz, reads poses back, and times a collision space's populateContactList for the
// broadphase row: the whole call (with the narrow phase), and the candidate-pair stage alone (an internal
// call of the space, SimpleCollisionSpace::findCandidatePairs, as Bullet's and ODE's broadphases are timed).
#include "Scene.h"

#include "MathDeclarations.h"
#include "RBDynamics.h"
#include "SimpleCollisionSpace.h"
#include "World.h"
#include "iCollisionSpace.h"
#include "iContactSettings.h"
#include "iOctreeCollisionSpace.h"
#include "iPhysicsFrame.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneSettings.h"

#include <cmath>

namespace compare {

namespace {

Vector vectorOf(const double p[3]) { return Vector(float(p[0]), float(p[1]), float(p[2])); }

// Guardian's orientation is a row-vector transform (world = local * M): M is R transposed.
Matrix matrixOf(const double R[9]) {
    auto f = [&](int i) { return float(R[i]); };
    return Matrix(f(0), f(3), f(6), 0, f(1), f(4), f(7), 0, f(2), f(5), f(8), 0, 0, 0, 0, 1);
}

Pose poseOf(const RBDynamics& d) {
    Pose pose;
    pose.p[0] = d.position.x;
    pose.p[1] = d.position.y;
    pose.p[2] = d.position.z;
    const float* m = d.orientation.data();
    for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k) pose.R[3 * r + k] = m[4 * k + r];
    return pose;
}

// A physics scene with a World (simple collision space) holding the scene's bodies.
class GuardianWorld {
public:
    GuardianWorld(const SceneDesc& s, const SimOptions& o, bool octree = false)
        : m_scene(CreatePhysicsScene(nullptr)) {
        iPhysicsSceneSettings* settings = settingsOf(m_scene);
        settings->setSleepingEnabled(o.sleeping);
        settings->setContinuousCollisionEnabled(o.continuous);
        if (o.iterations > 0) settings->setSolverIterations(o.iterations);
        // Restitution 0 everywhere: the bodiless ground plane has the default material (0.5), so combine by
        // the smaller value. Friction: the default 0.25 a body, summed (the seed's rule), is 0.5.
        settings->setRestitutionRule(COMBINE_Min);
        m_scene->update(0);
        m_world = new World(m_scene, octree ? CreateOctreeCollisionSpace() : nullptr);
        if (s.ground) m_world->ground();
        for (const BodyDesc& b : s.bodies) {
            const float h = float(b.size);
            iPhysicsFrame* f = b.shape == Shape::Box ? m_world->box(vectorOf(b.pose.p), Vector(h, h, h),
                                                                    float(b.mass), matrixOf(b.pose.R))
                                                     : m_world->sphere(vectorOf(b.pose.p), h, float(b.mass));
            RBDynamics* d = f->getDynamics();
            d->restitution = 0.0f;
            d->friction = float(kFriction / 2);
            m_bodies.push_back(d);
        }
    }
    ~GuardianWorld() {
        delete m_world;
        m_scene->Delete();
    }
    GuardianWorld(const GuardianWorld&) = delete;
    GuardianWorld& operator=(const GuardianWorld&) = delete;

protected:
    iPhysicsScene* m_scene;
    World* m_world = nullptr;
    std::vector<RBDynamics*> m_bodies;
};

class GuardianSim : public Sim, private GuardianWorld {
public:
    GuardianSim(const SceneDesc& s, const SimOptions& o) : GuardianWorld(s, o) {}
    void step() override {
        // Engine time in whole milliseconds, as the game loop gives it: one fixed step per call on average.
        ++m_steps;
        m_scene->update(int(std::ceil(m_steps * 1000.0 / 60.0)));
    }
    BodyState state(size_t i) const override {
        BodyState s;
        s.pose = poseOf(*m_bodies[i]);
        s.v[0] = m_bodies[i]->velocity.x;
        s.v[1] = m_bodies[i]->velocity.y;
        s.v[2] = m_bodies[i]->velocity.z;
        return s;
    }
    size_t bodyCount() const override { return m_bodies.size(); }

private:
    long long m_steps = 0;
};

class GuardianPairs : public PairFinder, private GuardianWorld {
public:
    GuardianPairs(const SceneDesc& s, bool octree, bool candidatesOnly = false)
        : GuardianWorld(s, SimOptions{}, octree),
          m_candidates(candidatesOnly ? dynamic_cast<SimpleCollisionSpace*>(m_world->space()) : nullptr) {}
    void place(const std::vector<Pose>& poses) override {
        for (size_t i = 0; i < poses.size() && i < m_bodies.size(); ++i) {
            m_bodies[i]->position = vectorOf(poses[i].p);
            m_bodies[i]->orientation = matrixOf(poses[i].R);
        }
    }
    size_t findPairs() override {
        if (m_candidates) return m_candidates->findCandidatePairs();
        m_world->space()->populateContactList(float(kDt));
        return m_world->space()->getNumContacts();
    }

private:
    SimpleCollisionSpace* m_candidates;
};

} // namespace

EngineInfo guardianInfo() {
    EngineInfo info;
    info.name = "Guardian";
    info.precision = "float";
    info.defaults = "4 solver iterations (sub-steps), simple collision space, continuous collision on";
    info.knob = "setSolverIterations";
    info.pairsNote = "iCollisionSpace::populateContactList (broad + narrow phase; counts contacts)";
    info.ladder = {1, 2, 3, 4, 6, 8, 12, 16};
    return info;
}

std::unique_ptr<Sim> makeGuardianSim(const SceneDesc& scene, const SimOptions& options) {
    return std::make_unique<GuardianSim>(scene, options);
}

std::unique_ptr<PairFinder> makeGuardianPairs(const SceneDesc& scene) {
    return std::make_unique<GuardianPairs>(scene, false);
}

std::unique_ptr<PairFinder> makeGuardianOctreePairs(const SceneDesc& scene) {
    return std::make_unique<GuardianPairs>(scene, true);
}

std::unique_ptr<PairFinder> makeGuardianCandidatePairs(const SceneDesc& scene, bool octree) {
    return std::make_unique<GuardianPairs>(scene, octree, true);
}

} // namespace compare
