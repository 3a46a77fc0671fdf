// World.h - the state of one fuzz sequence (FuzzWorld.h) and the random choices it draws from, shared by
// FuzzWorld.cpp (the walk), FuzzObjects.cpp (objects made, attached and deleted) and FuzzCalls.cpp (calls on
// live objects). Private to tests/fuzz.
#pragma once

#include "FuzzWorld.h"

#include "Frame.h"
#include "RBDynamics.h"
#include "iCCompound.h"
#include "iCOBB.h"
#include "iCPlane.h"
#include "iCSphere.h"
#include "iCollisionListener.h"
#include "iCollisionQueries.h"
#include "iCollisionSpace.h"
#include "iFixedUpdater.h"
#include "iForceGenerator.h"
#include "iPhysicsFrame.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneHooks.h"
#include "iPhysicsSceneSettings.h"
#include "iPhysicsSceneStats.h"
#include "iRigidBody.h"
#include "iSimpleCollisionSpace.h"
#include "iUtilities.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <vector>

namespace fuzz {

enum class Where { Top, Listener, Updater, Generator };

class World;

struct Hook final : iCollisionListener, iFixedUpdater, iForceGenerator {
    World* world;
    explicit Hook(World* w) : world(w) {}
    void HitWall(iRigidBody*, Vector, Vector) override;
    void fixedUpdate(iPhysicsScene*, float) override;
    void addForces(const iRigidBody*, const RigidBodyState&, Vector& force, Vector& torque) override;
};

template <class T> void erase(std::vector<T*>& v, const T* x) {
    v.erase(std::remove(v.begin(), v.end(), x), v.end());
}

class World {
public:
    explicit World(std::uint64_t seed) : m_rng(seed) {
        watchRigidBodies(&World::bodyDied, this);
        m_previous = setErrorHandler(&World::quiet);
        m_errorStart = errorCount();
        for (int i = 0; i < 3; ++i) m_hooks.push_back(std::make_unique<Hook>(this));
    }
    ~World() {
        unwatchRigidBodies(&World::bodyDied, this);
        setErrorHandler(m_previous);
    }
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    SequenceStats run(int calls) {
        stage();
        for (int i = 0; i < calls; ++i) act(Where::Top);
        teardown();
        m_stats.errors = errorCount() - m_errorStart;
        return m_stats;
    }

    void callback(Where where) {
        ++m_stats.callbacks;
        if (m_depth > 2 || m_budget <= 0 || pick(4) != 0) return; // most callbacks do nothing
        --m_budget;
        ++m_depth;
        act(where);
        --m_depth;
    }

private:
    std::mt19937_64 m_rng;
    ErrorHandler m_previous;
    unsigned long m_errorStart;
    SequenceStats m_stats;
    int m_depth = 0, m_budget = 0;
    long long m_now = 0; // kept within int: `now` is an int, and its ends are part of the walk
    std::vector<iPhysicsScene*> m_scenes;
    std::vector<iRigidBody*> m_bodies; // CreateRigidBody and clones (a PhysicsFrame's body is reached via it)
    std::vector<iFrame*> m_frames;     // plain frames
    std::vector<iPhysicsFrame*> m_pframes;
    std::vector<iCollisionSpace*> m_spaces;
    std::vector<iCollisionGeometry*> m_geoms;
    std::vector<std::unique_ptr<Hook>> m_hooks;

    static void quiet(const wchar_t*) {}
    static void bodyDied(const iRigidBody* b, void* self) { erase(static_cast<World*>(self)->m_bodies, b); }

    int pick(int n) { return n <= 1 ? 0 : int(m_rng() % unsigned(n)); }
    template <class T> T* any(const std::vector<T*>& v) {
        return v.empty() ? nullptr : v[size_t(pick(int(v.size())))];
    }
    float unit() { return float(m_rng() % 20001) / 10000.0f - 1.0f; }
    float value() {
        static const float special[] = {0.0f,
                                        -0.0f,
                                        1.0f,
                                        -1.0f,
                                        0.5f,
                                        1e30f,
                                        -1e30f,
                                        1e-39f,
                                        3e38f,
                                        std::numeric_limits<float>::infinity(),
                                        -std::numeric_limits<float>::infinity(),
                                        std::numeric_limits<float>::quiet_NaN(),
                                        1e6f,
                                        INFINITE_MASS};
        if (pick(3) == 0) return special[pick(int(sizeof special / sizeof special[0]))];
        return unit() * (pick(2) ? 10.0f : 1000.0f);
    }
    Vector vec() {
        return pick(3) == 0 ? Vector(value(), value(), value()) : Vector(unit(), unit(), unit()) * 20.0f;
    }
    Matrix rotation() {
        Matrix m(1);
        m.rotatex(unit() * 3.0f);
        m.rotatey(unit() * 3.0f);
        if (pick(8) == 0) m.scale(value(), 1.0f, 1.0f); // scaled or worse: refused by the simulator
        return m;
    }
    // Any body the game may touch: its own, or a PhysicsFrame's.
    iRigidBody* anyBody() {
        if (!m_pframes.empty() && pick(3) == 0) return any(m_pframes)->getRB();
        return any(m_bodies);
    }
    iFrame* anyFrame() {
        if (!m_pframes.empty() && pick(2) == 0) return any(m_pframes);
        return any(m_frames);
    }
    size_t objects() const { return m_bodies.size() + m_frames.size() + m_pframes.size() + m_geoms.size(); }

    // FuzzWorld.cpp: the walk itself.
    void act(Where where);
    // A typical game's setup first (scene, space, bodies with shapes on a floor, callbacks), so that the
    // random calls meet contacts, steps and callbacks from the start.
    void stage();
    // Everything left goes, in a random order that keeps the documented rule for plain frames.
    void teardown();

    // FuzzObjects.cpp: creation, deletion and attachment of every kind of object.
    void newScene();
    void deleteScene();
    void newBody();
    void deleteBody();
    void framesAndPhysicsFrames();
    void deleteFrame();
    // A PhysicsFrame re-roots the PhysicsFrames attached to it and unbinds bodies itself; plain frames
    // attached to it are the game's to detach (README).
    void deletePhysicsFrame(iPhysicsFrame* pf);
    void attachments();
    void spaces();
    // Refused (error()) while the space notifies listeners: then it stays in the pool.
    void deleteSpace(iCollisionSpace* cs);
    void newGeometry();
    void deleteGeometry();
    void clones();

    // FuzzCalls.cpp: what is done to live objects.
    void dynamics();
    void sceneMembership();
    void update(Where where);
    int now();
    void time();
    void sceneSettings();
    void geometryEdits();
    void hooks();
    void queries();
};

} // namespace fuzz
