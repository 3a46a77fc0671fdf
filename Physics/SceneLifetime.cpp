// SceneLifetime.cpp - how scenes come and go: the registry of live scenes (the active one), the one update
// running at a time, deletions deferred while it steps, and forgetting a collision space that is deleted.
//
// Why deletions wait for the end of a step: a callback (fixed updater, force generator, listener) may delete
// a body or a scene while the step is walking bodies, composites or contacts, and a composite may hold
// bodies of another scene (attachment chains cross scenes). So while any scene steps, every body deletion
// (whatever its scene) is queued on the stepping scene and done at the end of the step, and every scene
// deletion at the end of the update. An update() from inside a callback is refused: it would walk the same
// lists.
#include "PhysicsScene.h"

#include "Joint.h"
#include "RigidBody.h"
#include "iCollisionSpace.h"
#include "iUtilities.h"

#include <algorithm>

namespace physics {

namespace {
// Scenes alive and not being deleted, in creation order: the last one is the active scene.
std::vector<PhysicsScene*>& scenes() {
    static std::vector<PhysicsScene*> all;
    return all;
}
PhysicsScene* s_updating = nullptr;
} // namespace

PhysicsScene* PhysicsScene::active() { return scenes().empty() ? nullptr : scenes().back(); }
PhysicsScene* PhysicsScene::updating() { return s_updating; }

PhysicsScene::PhysicsScene() {
    scenes().push_back(this);
    watchCollisionSpaces(&PhysicsScene::onSpaceDestroyed, this);
}

void PhysicsScene::leaveRegistry() {
    scenes().erase(std::remove(scenes().begin(), scenes().end(), this), scenes().end());
}

PhysicsScene::~PhysicsScene() {
    unwatchCollisionSpaces(&PhysicsScene::onSpaceDestroyed, this);
    leaveRegistry();
    // Every body leaves the scene first, so that none calls back into it while being deleted. Bodies owned
    // by a PhysicsFrame, and bodies being removed, survive: their owners delete them.
    std::vector<RigidBody*> leaving;
    leaving.swap(bodies());
    m_byDynamics.clear();
    for (RigidBody* b : leaving) {
        b->setScene(nullptr);
        b->sceneSlot = -1;
    }
    for (RigidBody* b : leaving) {
        if (b->dying() || (!b->owner() && !b->pendingRemoval))
            b->destroy();
        else
            b->pendingRemoval = false;
    }
}

void PhysicsScene::Delete() const {
    auto* self = const_cast<PhysicsScene*>(this);
    if (m_deleteRequested) return; // already going
    PhysicsScene* stepping = updating();
    if (!stepping) {
        delete this;
        return;
    }
    // From a callback: deleted when the update ends. Until then it is no longer the active scene, takes no
    // bodies, and the bodies it will delete let go of their frames now: the game may delete those frames
    // right after this call, and the step must not write them.
    m_deleteRequested = true;
    self->leaveRegistry();
    for (RigidBody* b : bodies())
        if (b->dying() || (!b->owner() && !b->pendingRemoval)) b->markDying();
    if (stepping != this) stepping->m_deferredScenes.push_back(self);
}

void PhysicsScene::beginSteps() {
    m_busy = true;
    s_updating = this;
}

void PhysicsScene::endSteps() {
    m_busy = false;
    s_updating = nullptr;
    std::vector<PhysicsScene*> doomed;
    doomed.swap(m_deferredScenes);
    for (PhysicsScene* s : doomed) delete s;
    Joint::deleteDeferred(); // joints deleted from callbacks
}

void PhysicsScene::forget(RigidBody* b) {
    b->setAsleep(false); // out of the scene, nobody would wake it
    ++m_membership;
    const size_t slot = size_t(b->sceneSlot);
    if (b->sceneSlot >= 0 && slot < m_bodies.size() && m_bodies[slot] == b) {
        m_bodies[slot] = nullptr; // the list closes up at its next read (bodies())
        b->sceneSlot = -1;
        ++m_bodyHoles;
    }
    m_byDynamics.erase(&b->getDynamics());
    m_leaving.erase(std::remove_if(m_leaving.begin(), m_leaving.end(),
                                   [b](const std::pair<RigidBody*, Leave>& e) { return e.first == b; }),
                    m_leaving.end());
}

void PhysicsScene::closeUpBodies() {
    size_t kept = 0;
    for (RigidBody* b : m_bodies)
        if (b) {
            b->sceneSlot = int(kept);
            m_bodies[kept++] = b;
        }
    m_bodies.resize(kept);
    m_bodyHoles = 0;
}

void PhysicsScene::deferRemove(RigidBody* b) {
    if (b->pendingRemoval) return;
    b->pendingRemoval = true;
    m_leaving.push_back({b, Leave::Remove});
}

// Last queued first, so that a body killed and then deleted in one step is deleted (its forget() drops the
// removal still queued). A removal that add() took back since (pendingRemoval cleared) is skipped.
void PhysicsScene::flushDeferred() {
    while (!m_leaving.empty()) {
        const std::pair<RigidBody*, Leave> next = m_leaving.back();
        m_leaving.pop_back(); // a body of another scene: its forget() does not touch this list
        RigidBody* b = next.first;
        if (next.second == Leave::Delete) {
            b->destroy();
        } else if (b->pendingRemoval && b->scene() == this) {
            b->pendingRemoval = false;
            forget(b);
            b->setScene(nullptr);
            if (!b->isAlive()) letJointsGo(b); // killed: its joints let go (seed 000's spring)
        }
    }
    m_updaters.erase(std::remove(m_updaters.begin(), m_updaters.end(), nullptr), m_updaters.end());
}

void PhysicsScene::onSpaceDestroyed(const iCollisionSpace* dying, void* self) {
    auto* scene = static_cast<PhysicsScene*>(self);
    if (scene->m_space != dying) return;
    scene->setSpace(nullptr); // as if setNewGlobalCollisionSpace(nullptr): the bodies stop colliding
}

} // namespace physics
