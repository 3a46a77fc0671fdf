// SceneDebugDraw.cpp - the physics scene drawing itself through a game's iDebugDraw (iDebugDrawable.h):
// its space's drawing (shapes, bounds, contacts: the scene has no geometry of its own, so with no space or
// a space that cannot draw, the sim-only package still shows bodies), then each body's centre of mass and
// axes, "zz" at sleeping bodies, and islands of bodies touching through the space's current contacts.
//
// Drawing only reads; it may allocate (it is not part of a step).
#include "PhysicsScene.h"
#include "RigidBody.h"
#include "iCollisionGeometry.h"
#include "iCollisionSpace.h"

#include <algorithm>
#include <unordered_map>
#include <vector>

namespace physics {

namespace {

constexpr float kDrawAxisLength = 0.5f;  // m: each body axis drawn
constexpr float kDrawCentreSize = 0.1f;  // m: the cross at a body's centre of mass
const char* const kDrawSleepMark = "zz"; // drawn at a sleeping body's centre

int sceneDrawFind(std::vector<int>& parent, int i) {
    while (parent[size_t(i)] != i) i = parent[size_t(i)] = parent[size_t(parent[size_t(i)])];
    return i;
}

} // namespace

void PhysicsScene::debugDraw(iDebugDraw& out, unsigned flags) const {
    if (const iDebugDrawable* space = debugDrawOf(m_space)) space->debugDraw(out, flags);

    for (const RigidBody* b : bodies()) {
        if (b->dying()) continue;
        const RBDynamics& d = b->getDynamics();
        const Vector c = d.getWorldPosition();
        const Matrix r = d.getWorldOrientation();
        if (!c.isFinite() || !r.isFinite()) continue; // restored at the next step; nothing sensible to draw
        if (flags & DEBUGDRAW_BodyAxes) {
            out.drawPoint(c, kDrawCentreSize, debugcolour::kShape);
            out.drawLine(c, c + r.direction('x') * kDrawAxisLength, debugcolour::kAxisX);
            out.drawLine(c, c + r.direction('y') * kDrawAxisLength, debugcolour::kAxisY);
            out.drawLine(c, c + r.direction('z') * kDrawAxisLength, debugcolour::kAxisZ);
        }
        if ((flags & DEBUGDRAW_Sleeping) && d.attachmentRoot()->sleeping)
            out.drawText(c, kDrawSleepMark, debugcolour::kSleeping);
    }

    // Islands as the contact list links them now (the step's sleeping logic builds its own): moving roots
    // joined through contacts, each member linked to its island's first body. Pairs of two sleeping bodies
    // are not in the contact list, so a sleeping pile shows no links.
    if (!(flags & DEBUGDRAW_Islands) || !m_space) return;
    std::vector<const RigidBody*> roots;
    std::vector<int> parent;
    std::unordered_map<const RigidBody*, int> index;
    for (const RigidBody* b : bodies()) {
        const RBDynamics& d = b->getDynamics();
        if (b->dying() || d.attachedTo() || d.physicsType == PHYS_FixedInSpace) continue;
        index.emplace(b, int(roots.size()));
        parent.push_back(int(roots.size()));
        roots.push_back(b);
    }
    auto islandOf = [&](const iCollisionGeometry* g) -> int {
        const iRigidBody* rb = g ? g->getRigidBody() : nullptr;
        const RigidBody* body = rb ? bodyOf(rb->getDynamics().attachmentRoot()) : nullptr;
        auto it = body ? index.find(body) : index.end();
        return it == index.end() ? -1 : it->second;
    };
    const CollisionContact* contacts = m_space->getContactList();
    for (size_t i = 0; contacts && i < m_space->getNumContacts(); ++i) {
        int a = islandOf(contacts[i].g1), b = islandOf(contacts[i].g2);
        if (a < 0 || b < 0) continue;
        a = sceneDrawFind(parent, a);
        b = sceneDrawFind(parent, b);
        if (a != b) parent[size_t(std::max(a, b))] = std::min(a, b); // the first body leads
    }
    for (size_t i = 0; i < roots.size(); ++i) {
        const int first = sceneDrawFind(parent, int(i));
        if (first == int(i)) continue;
        out.drawLine(roots[size_t(first)]->getDynamics().getWorldPosition(),
                     roots[i]->getDynamics().getWorldPosition(), debugcolour::kIsland);
    }
}

} // namespace physics
