// WorldPoseCache.cpp - world poses of attached bodies in O(1) each while the scene walks all its bodies.
//
// Why: an attached body stores its pose relative to its parent, so its world pose costs O(depth) to compute
// (RBDynamics::getWorldPosition), and a step reads every body's world pose several times: a 1,000-deep chain
// cost O(depth^2) a step. Inside a PoseCache each body computes its world pose once, from its parent's
// cached one (the same products in the same order as RBDynamics', so the same bits). The cache is only
// trusted between the scene's PoseCache scopes, which run no game code; any pose the engine itself changes
// meanwhile (a frame adopted, a state restored) invalidates it.
#include "PhysicsScene.h"
#include "RigidBody.h"

#include <vector>

namespace physics {

namespace {
unsigned long long s_round = 1;
bool s_caching = false;
} // namespace

RigidBody::PoseCache::PoseCache() {
    ++s_round;
    s_caching = true;
}
RigidBody::PoseCache::~PoseCache() {
    s_caching = false;
    ++s_round;
}

void RigidBody::invalidatePoses() { ++s_round; }

Vector RigidBody::worldPosition() const {
    if (!s_caching) return m_dyn.getWorldPosition();
    cacheWorldPose();
    return m_worldPos;
}

Matrix RigidBody::worldOrientation() const {
    if (!s_caching) return m_dyn.getWorldOrientation();
    cacheWorldPose();
    return m_worldRot;
}

void RigidBody::cacheWorldPose() const {
    if (m_poseRound == s_round) return;
    if (!m_dyn.attachedTo()) { // most bodies: their own pose, no walk
        m_worldPos = m_dyn.position;
        m_worldRot = m_dyn.orientation;
        m_poseRound = s_round;
        return;
    }
    // Up to the nearest ancestor already cached (or the root, or a parent outside this scene), then down.
    auto parentBody = [](const RigidBody* b) -> const RigidBody* {
        const RBDynamics* p = b->m_dyn.attachedTo();
        return p && b->m_scene ? b->m_scene->bodyOf(p) : nullptr;
    };
    thread_local std::vector<const RigidBody*> path;
    path.clear();
    for (const RigidBody* b = this; b; b = parentBody(b)) {
        path.push_back(b);
        const RigidBody* p = parentBody(b);
        if (p && p->m_poseRound == s_round) break;
    }
    for (size_t i = path.size(); i-- > 0;) {
        const RigidBody* b = path[i];
        const RBDynamics& d = b->m_dyn;
        const RigidBody* p = parentBody(b);
        if (!d.attachedTo()) {
            b->m_worldPos = d.position;
            b->m_worldRot = d.orientation;
        } else if (p && p->m_poseRound == s_round) {
            b->m_worldPos = d.position * p->m_worldRot + p->m_worldPos;
            b->m_worldRot = d.orientation * p->m_worldRot;
        } else { // the parent is not a body of this scene: computed the long way
            b->m_worldPos = d.getWorldPosition();
            b->m_worldRot = d.getWorldOrientation();
        }
        b->m_poseRound = s_round;
    }
}

} // namespace physics
