// FuzzWorld.cpp - the random walk over the API (FuzzWorld.h).
//
// Legal uses only, as the interface headers state them: objects are used until their Delete() (or until the
// rigidBodyDestroyed watch says a scene took a body with it); a plain frame is deleted only after the bodies
// bound to it and the frames attached to it let go of it (a course framework's Frame keeps no list of them:
// README). Everything else goes: deletion in any order, from any callback; values the API refuses; update
// with any `now`. The hooks (one object that is a listener, a fixed updater and a force generator) act on
// the world from inside the callbacks, with a budget so that a sequence always ends.
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

namespace {

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

    void act(Where where) {
        ++m_stats.calls;
        const bool top = where == Where::Top;
        if (top) m_budget = 8;            // callbacks of this call may act this many times
        const bool full = objects() > 60; // keep sequences small: prefer deleting
        switch (pick(29)) {
        case 0:
            if (m_scenes.size() < 3) newScene();
            break;
        case 1:
            deleteScene();
            break;
        case 2:
        case 3:
            if (!full) newBody();
            break;
        case 4:
            deleteBody();
            break;
        case 5:
            if (!full)
                framesAndPhysicsFrames();
            else
                deleteFrame();
            break;
        case 6:
            deleteFrame();
            break;
        case 7:
            attachments();
            break;
        case 8:
        case 9:
            dynamics();
            break;
        case 10:
            sceneMembership();
            break;
        case 11:
        case 12:
        case 13:
        case 24:
        case 25:
        case 26:
            update(where);
            break;
        case 27:
        case 28:
            hooks();
            break;
        case 14:
            sceneSettings();
            break;
        case 15:
            spaces();
            break;
        case 16:
        case 17:
            if (!full) newGeometry();
            break;
        case 18:
            geometryEdits();
            break;
        case 19:
            hooks();
            break;
        case 20:
            if (!full) clones();
            break;
        case 21:
            queries();
            break;
        case 22:
            time();
            break;
        default:
            deleteGeometry();
            break;
        }
    }

    // A typical game's setup first (scene, space, bodies with shapes on a floor, callbacks), so that the
    // random calls meet contacts, steps and callbacks from the start.
    void stage() {
        newScene();
        m_spaces.push_back(CreateSimpleCollisionSpace(60));
        m_scenes.back()->setNewGlobalCollisionSpace(m_spaces.back());
        m_geoms.push_back(CreateCPlane(nullptr, Vector(0, 1, 0), -1.0f));
        for (int i = 0; i < 6; ++i) {
            iRigidBody* b = CreateRigidBody(nullptr);
            b->getDynamics().position = Vector(0.6f * float(i % 3), 0.5f + 0.9f * float(i), 0.3f * unit());
            m_bodies.push_back(b);
            m_geoms.push_back(i % 2 ? CreateCSphere(b, 0.5f) : CreateCOBB(b, Vector(0.4f, 0.4f, 0.4f)));
            b->attachListener(m_hooks[size_t(i) % m_hooks.size()].get());
            if (i % 3 == 0) hooksOf(m_scenes.back())->addForceGenerator(b, m_hooks[1].get());
        }
        hooksOf(m_scenes.back())->addFixedUpdater(m_hooks[0].get());
    }

    void newScene() {
        iPhysicsScene* s = CreatePhysicsScene(nullptr);
        m_scenes.push_back(s);
        settingsOf(s)->setMaxStepsPerUpdate(1 + pick(6));
        if (pick(2) && !m_spaces.empty()) s->setNewGlobalCollisionSpace(any(m_spaces));
    }
    void deleteScene() {
        iPhysicsScene* s = any(m_scenes);
        if (!s) return;
        m_stats.steps += (unsigned long)statsOf(s)->getStepCount();
        erase(m_scenes, s);
        s->Delete(); // its bodies are reported dead (bodyDied) when they go, maybe at the end of a step
    }
    void newBody() {
        iRigidBody* b = CreateRigidBody(pick(3) == 0 ? anyFrame() : nullptr);
        m_bodies.push_back(b);
        if (pick(2)) b->getDynamics().position = Vector(unit(), unit(), unit()) * 5.0f;
    }
    void deleteBody() {
        if (pick(4) == 0 && !m_pframes.empty()) { // refused: a PhysicsFrame owns it
            any(m_pframes)->getRB()->Delete();
            return;
        }
        iRigidBody* b = any(m_bodies);
        if (!b) return;
        erase(m_bodies, b);
        b->Delete();
    }
    void framesAndPhysicsFrames() {
        if (pick(2)) {
            Frame* f = static_cast<Frame*>(CreateFrame());
            f->translate(unit() * 5, unit() * 5, unit() * 5);
            if (iFrame* p = anyFrame(); p && pick(2)) f->attachTo(p);
            m_frames.push_back(f);
        } else {
            iPhysicsFrame* pf = CreatePhysicsFrame();
            pf->translate(unit() * 5, unit() * 5, unit() * 5);
            m_pframes.push_back(pf);
        }
    }
    void deleteFrame() {
        if (pick(2) && !m_pframes.empty()) { // deletion in any order: children, bound bodies and all
            deletePhysicsFrame(any(m_pframes));
            return;
        }
        iFrame* f = any(m_frames);
        if (!f) return;
        // The documented rule for a framework Frame: whoever points at it lets go first.
        for (iRigidBody* b : m_bodies)
            if (b->getFrame() == f) b->attach(nullptr);
        for (iPhysicsFrame* pf : m_pframes) {
            if (pf->getRB()->getFrame() == f) pf->getRB()->attach(nullptr);
            if (pf->parent() == f) pf->attachTo(nullptr);
        }
        for (iFrame* g : m_frames)
            if (g->parent() == f) g->attachTo(nullptr);
        erase(m_frames, f);
        f->Delete();
    }
    // A PhysicsFrame re-roots the PhysicsFrames attached to it and unbinds bodies itself; plain frames
    // attached to it are the game's to detach (README).
    void deletePhysicsFrame(iPhysicsFrame* pf) {
        if (!pf) return;
        for (iFrame* g : m_frames)
            if (g->parent() == pf) g->attachTo(nullptr);
        erase(m_pframes, pf);
        pf->Delete();
    }
    void attachments() {
        switch (pick(5)) {
        case 0:
            if (iRigidBody* b = anyBody()) b->attach(pick(3) ? anyFrame() : nullptr);
            break;
        case 1: // the bodies' own chains
            if (iRigidBody* b = anyBody()) {
                iRigidBody* p = pick(4) ? anyBody() : nullptr;
                b->getDynamics().attachTo(p ? &p->getDynamics() : nullptr);
            }
            break;
        case 2:
            if (iPhysicsFrame* pf = any(m_pframes)) pf->attachTo(pick(4) ? anyFrame() : nullptr);
            break;
        case 3:
            if (iFrame* f = any(m_frames)) f->attachTo(pick(3) ? anyFrame() : nullptr);
            break;
        default:
            if (iFrame* f = anyFrame()) {
                f->translate(value(), unit(), unit());
                f->rotatey(unit());
            }
            break;
        }
    }
    void dynamics() {
        iRigidBody* b = anyBody();
        if (!b) return;
        RBDynamics& d = b->getDynamics();
        switch (pick(20)) {
        case 0:
            d.position = vec();
            break;
        case 1:
            d.velocity = vec();
            break;
        case 2:
            d.acceleration = vec();
            break;
        case 3:
            d.force = vec();
            break;
        case 4:
            d.temporalForce = vec();
            break;
        case 5:
            d.mass = value();
            break;
        case 6:
            d.dragCoefficient = value();
            break;
        case 7:
            d.restitution = value();
            break;
        case 8:
            d.friction = value();
            break;
        case 9:
            d.com = vec();
            break;
        case 10:
            d.physicsType = PhysicsType(pick(5) - 1);
            break; // -1 and 3 are not types: refused
        case 11:
            d.orientation = rotation();
            break;
        case 12:
            d.angularVelocity = vec();
            break;
        case 13:
            d.angularMomentum = vec();
            break;
        case 14:
            d.torque = vec();
            break;
        case 15:
            d.temporalTorque = vec();
            break;
        case 16: {
            Matrix t = pick(2) ? getBoxInertiaTensor(std::fabs(value()), vec()) : Matrix(value());
            if (pick(2))
                d.setInertiaTensor(t);
            else if (pick(2))
                d.setInverseInertiaTensor(pick(4) ? t : Matrix(0));
            else
                d.getInertiaTensor() = t; // written through the reference: validated before a step
            break;
        }
        case 17:
            d.useShapeInertia();
            break;
        case 18:
            d.ApplyImpulse(vec(), vec());
            break;
        default: {
            RBDynamics copy(d);
            copy.mass = value();
            copy.position = vec();
            b->setDynamics(copy);
            break;
        }
        }
    }
    void sceneMembership() {
        iPhysicsScene* s = any(m_scenes);
        iRigidBody* b = anyBody();
        if (!s || !b) return;
        if (pick(2))
            s->add(b);
        else
            s->remove(b);
    }
    void update(Where where) {
        iPhysicsScene* s = any(m_scenes);
        if (!s) return;
        if (where != Where::Top) { // refused when a scene is mid-update
            s->update(now());
            return;
        }
        const int r = pick(40);
        if (r == 0)
            m_now -= pick(1000); // the clock went back: re-based
        else if (r == 1)
            m_now += 100000 + pick(1000000); // a long stall: capped
        else if (r == 2)
            m_now = pick(2) ? INT_MAX : INT_MIN; // the ends of `now`
        else if (m_now > INT_MAX / 2)
            m_now = 0; // back from the end: a re-base, then time flows again
        else
            m_now += pick(100);
        s->update(now());
    }
    int now() {
        m_now = std::min<long long>(INT_MAX, std::max<long long>(INT_MIN, m_now));
        return int(m_now);
    }
    void time() {
        iPhysicsScene* s = any(m_scenes);
        if (!s) return;
        switch (pick(3)) {
        case 0:
            s->suspend();
            break;
        case 1:
            s->restore(now());
            break;
        default:
            s->reset(now());
            break;
        }
    }
    void sceneSettings() {
        iPhysicsScene* s = any(m_scenes);
        if (!s) return;
        iPhysicsSceneSettings* set = settingsOf(s);
        switch (pick(8)) {
        case 0:
            set->setGravity(vec());
            break;
        case 1:
            set->setStepRate(pick(4) ? 30 + pick(300) : pick(2) ? 0 : 20000);
            break;
        case 2:
            set->setMaxStepsPerUpdate(pick(5));
            break;
        case 3:
            set->setIntegrator(Integrator(pick(7) - 1));
            break;
        case 4:
            set->setSolverIterations(pick(3) ? 1 + pick(20) : -3);
            break;
        case 5:
            set->setFrictionRule(CombineRule(pick(6) - 1));
            break;
        case 6:
            set->setRestitutionRule(CombineRule(pick(6) - 1));
            break;
        default:
            set->setSleepingEnabled(pick(2));
            break;
        }
    }
    void spaces() {
        switch (pick(4)) {
        case 0:
            if (m_spaces.size() < 3) m_spaces.push_back(CreateSimpleCollisionSpace(size_t(pick(3) * 60)));
            break;
        case 1: // deleted in any order: before the scenes colliding in it, before its geometries
            deleteSpace(any(m_spaces));
            break;
        case 2:
            if (iPhysicsScene* s = any(m_scenes))
                s->setNewGlobalCollisionSpace(pick(4) ? any(m_spaces) : nullptr);
            break;
        default:
            if (iCollisionSpace* cs = any(m_spaces)) {
                if (iCollisionGeometry* g = any(m_geoms)) {
                    if (pick(2))
                        cs->add(g);
                    else
                        cs->remove(g);
                }
            }
            break;
        }
    }
    // Refused (error()) while the space notifies listeners: then it stays in the pool.
    void deleteSpace(iCollisionSpace* cs) {
        if (!cs) return;
        const unsigned long before = errorCount();
        cs->Delete();
        if (errorCount() == before) erase(m_spaces, cs);
    }
    void newGeometry() {
        iRigidBody* b = pick(5) ? anyBody() : nullptr;
        iCollisionGeometry* g = nullptr;
        switch (pick(4)) {
        case 0:
            g = CreateCSphere(b, pick(6) ? 0.2f + std::fabs(unit()) : value());
            break;
        case 1:
            g = CreateCOBB(b, pick(6) ? Vector(0.5f, 0.3f, 0.4f) : vec());
            break;
        case 2:
            g = CreateCPlane(b, pick(5) ? Vector(0, 1, 0) : vec(), unit() * 3);
            break;
        default: {
            g = CreateCCompound(b);
            auto* c = static_cast<iCCompound*>(g);
            for (int i = pick(3); i > 0; --i) {
                if (pick(2))
                    c->addSphere(vec(), 0.3f + std::fabs(unit()));
                else
                    c->addBox(vec(), rotation(), Vector(0.2f, 0.3f, 0.4f));
            }
            break;
        }
        }
        if (g) m_geoms.push_back(g); // nullptr: a refused size
    }
    void deleteGeometry() {
        iCollisionGeometry* g = any(m_geoms);
        if (!g) return;
        erase(m_geoms, g);
        g->Delete();
    }
    void geometryEdits() {
        iCollisionGeometry* g = any(m_geoms);
        if (!g) return;
        switch (g->getCollisionType()) {
        case CT_SPHERE:
            if (pick(2)) static_cast<iCSphere*>(g)->setRadius(value());
            break;
        case CT_OBB:
            if (pick(2)) static_cast<iCOBB*>(g)->setRadius(vec());
            break;
        case CT_PLANE:
            if (pick(2)) static_cast<iCPlane*>(g)->setPlane(vec(), value());
            break;
        default:
            if (pick(3) == 0) static_cast<iCCompound*>(g)->clearChildren();
            break;
        }
        if (pick(2)) g->attach(pick(4) ? anyBody() : nullptr);
        float lo, hi;
        g->getProjectionBounds(vec(), lo, hi);
    }
    void hooks() {
        Hook* h = m_hooks[size_t(pick(int(m_hooks.size())))].get();
        iRigidBody* b = anyBody();
        iPhysicsScene* s = any(m_scenes);
        switch (pick(6)) {
        case 0:
            if (b) b->attachListener(h);
            break;
        case 1:
            if (b) b->detachListener(h);
            break;
        case 2:
            if (s) hooksOf(s)->addFixedUpdater(h);
            break;
        case 3:
            if (s) hooksOf(s)->removeFixedUpdater(h);
            break;
        case 4:
            if (s && b) hooksOf(s)->addForceGenerator(b, h);
            break;
        default:
            if (s && b) hooksOf(s)->removeForceGenerator(b, h);
            break;
        }
    }
    void clones() {
        if (pick(2)) {
            if (iRigidBody* b = anyBody()) m_bodies.push_back(b->clone());
        } else if (iPhysicsFrame* pf = any(m_pframes)) {
            m_pframes.push_back(pf->clone());
        } else if (iCollisionGeometry* g = any(m_geoms)) {
            if (iCollisionGeometry* c = g->clone()) m_geoms.push_back(c);
        }
    }
    void queries() {
        iCollisionSpace* cs = any(m_spaces);
        if (!cs) return;
        if (pick(2)) cs->populateContactList(pick(2) ? 1.0f / 60 : value());
        if (iCollisionQueries* q = queriesOf(cs)) {
            RayHit hit;
            q->rayCast(vec(), vec(), value(), hit);
            std::vector<iCollisionGeometry*> out;
            q->overlapSphere(vec(), std::fabs(unit()) * 5, out);
        }
    }

    // Everything left goes, in a random order that keeps the documented rule for plain frames.
    void teardown() {
        m_budget = 0; // callbacks of the last updates do nothing more
        while (!m_scenes.empty() || !m_bodies.empty() || !m_pframes.empty() || !m_frames.empty() ||
               !m_spaces.empty() || !m_geoms.empty()) {
            switch (pick(6)) {
            case 0:
                deleteScene();
                break;
            case 1:
                if (iRigidBody* b = any(m_bodies)) {
                    erase(m_bodies, b);
                    b->Delete();
                }
                break;
            case 2:
                deleteFrame();
                break;
            case 3:
                deletePhysicsFrame(any(m_pframes));
                break;
            case 4:
                deleteSpace(any(m_spaces));
                break;
            default:
                deleteGeometry();
                break;
            }
        }
    }
};

void Hook::HitWall(iRigidBody*, Vector, Vector) { world->callback(Where::Listener); }
void Hook::fixedUpdate(iPhysicsScene*, float) { world->callback(Where::Updater); }
void Hook::addForces(const iRigidBody*, const RigidBodyState& s, Vector& force, Vector& torque) {
    force += Vector(0, 1, 0) * 0.1f;
    torque += s.angularVelocity * -0.01f;
    world->callback(Where::Generator);
}

} // namespace

SequenceStats runSequence(std::uint64_t seed, int calls) {
    World w(seed);
    return w.run(calls);
}

} // namespace fuzz
