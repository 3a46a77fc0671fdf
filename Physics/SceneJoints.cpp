// SceneJoints.cpp - the scene's side of joints: which joints this step solves, their bodies as one island,
// their reactions and breaks after the solve, and letting go of a killed body.
//
// A joint is this scene's while its body A is one of the scene's bodies taking part in the step and B is
// the world or another such body; it is found through body A's joint list, so a scene with no joints pays
// one empty-list check a body.
#include "Joint.h"
#include "PhysicsScene.h"
#include "RigidBody.h"

namespace physics {

namespace {
bool takesPartInStep(const RigidBody* b, const PhysicsScene* scene) {
    return b->scene() == scene && !b->dying() && !b->pendingRemoval;
}
} // namespace

void PhysicsScene::gatherJoints() {
    m_joints.clear();
    for (RigidBody* b : bodies()) {
        if (b->joints.empty() || !takesPartInStep(b, this)) continue;
        for (Joint* j : b->joints)
            if (j->bodyA() == b && j->acting() && (!j->bodyB() || takesPartInStep(j->bodyB(), this)))
                m_joints.push_back(j);
    }
}

void PhysicsScene::joinJointIslands() {
    for (const Joint* j : m_joints) {
        const RigidBody* a = bodyOf(j->bodyA()->getDynamics().attachmentRoot());
        const RigidBody* b = j->bodyB() ? bodyOf(j->bodyB()->getDynamics().attachmentRoot()) : nullptr;
        m_islands.join(a, b);
    }
}

void PhysicsScene::finishJoints() {
    const Real h = m_solver.substepLength();
    for (Joint* j : m_solver.joints())
        if (j->finish(h)) m_brokenJoints.push_back(j);
}

// At the end of the step (before its removals): a listener may delete the joint, kill or delete bodies.
void PhysicsScene::deliverJointBreaks() {
    for (size_t i = 0; i < m_brokenJoints.size(); ++i) {
        Joint* j = m_brokenJoints[i];
        if (!j->deleted() && j->listener) j->listener->jointBroken(j->object());
    }
    m_brokenJoints.clear();
}

void PhysicsScene::letJointsGo(RigidBody* b) {
    while (!b->joints.empty()) b->joints.back()->letGo(b);
}

} // namespace physics
