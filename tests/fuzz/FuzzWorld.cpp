// FuzzWorld.cpp - the random walk over the API (FuzzWorld.h): which call comes next, the opening stage and
// the teardown. The calls themselves are in FuzzObjects.cpp and FuzzCalls.cpp; the state in World.h.
//
// Legal uses only, as the interface headers state them: objects are used until their Delete() (or until the
// rigidBodyDestroyed watch says a scene took a body with it); a plain frame is deleted only after the bodies
// bound to it and the frames attached to it let go of it (a course framework's Frame keeps no list of them:
// README). Everything else goes: deletion in any order, from any callback; values the API refuses; update
// with any `now`. The hooks (one object that is a listener, a fixed updater and a force generator) act on
// the world from inside the callbacks, with a budget so that a sequence always ends.
#include "World.h"

namespace fuzz {

void World::act(Where where) {
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

void World::stage() {
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

void World::teardown() {
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

void Hook::HitWall(iRigidBody*, Vector, Vector) { world->callback(Where::Listener); }
void Hook::fixedUpdate(iPhysicsScene*, float) { world->callback(Where::Updater); }
void Hook::addForces(const iRigidBody*, const RigidBodyState& s, Vector& force, Vector& torque) {
    force += Vector(0, 1, 0) * 0.1f;
    torque += s.angularVelocity * -0.01f;
    world->callback(Where::Generator);
}

SequenceStats runSequence(std::uint64_t seed, int calls) {
    World w(seed);
    return w.run(calls);
}

} // namespace fuzz
