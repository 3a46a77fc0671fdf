// JointStage.cpp - the joints' part of the contact solve: their bodies entering, contacts between joined
// bodies dropped, and the joints' rows (and their tethers', JointTethers.cpp) in each pass of each sub-step
// beside the contacts' (Joint.h).
#include "ContactSolver.h"
#include "Joint.h"
#include "JointRowsInline.h"

#include "RigidBody.h"

#include <algorithm>

namespace physics {

namespace {
const RBDynamics* jointRoot(const RigidBody* body) {
    return body ? body->getDynamics().attachmentRoot() : nullptr;
}
std::pair<const RBDynamics*, const RBDynamics*> orderedRoots(const RBDynamics* a, const RBDynamics* b) {
    return std::less<const RBDynamics*>()(a, b) ? std::make_pair(a, b) : std::make_pair(b, a);
}
} // namespace

void ContactSolver::setJoints(const std::vector<Joint*>& joints) {
    m_joints = joints;
    m_noContact.clear();
    for (const Joint* j : m_joints)
        if (!j->collideConnected)
            m_noContact.push_back(orderedRoots(jointRoot(j->bodyA()), jointRoot(j->bodyB())));
    std::sort(m_noContact.begin(), m_noContact.end());
}

bool ContactSolver::joinedWithoutContact(const RBDynamics* a, const RBDynamics* b) const {
    return !m_noContact.empty() &&
           std::binary_search(m_noContact.begin(), m_noContact.end(), orderedRoots(a, b));
}

void ContactSolver::enterJoints(const SolverBodyAccess& access) {
    m_solvedJoints.clear();
    for (Joint* j : m_joints) {
        RBDynamics* a = j->bodyA()->getDynamics().attachmentRoot();
        RBDynamics* b = j->bodyB() ? j->bodyB()->getDynamics().attachmentRoot() : nullptr;
        if (a == b || (access.resting(a) && access.resting(b))) continue;
        const int slotA = bodyIndex(a, access), slotB = bodyIndex(b, access);
        j->enter(slotA, slotB);
        m_solvedJoints.push_back(j);
    }
}

void ContactSolver::prepareJoints(Real h) {
    for (Joint* j : m_solvedJoints) j->prepare(m_bodies[size_t(j->slotA)], m_bodies[size_t(j->slotB)], h);
    prepareTethers(h);
}

void ContactSolver::warmStartJoints() {
    for (Joint* j : m_solvedJoints) j->warmStart(m_bodies[size_t(j->slotA)], m_bodies[size_t(j->slotB)]);
    for (Tether& t : m_tethers)
        if (t.row.kind != RowKind::Off && t.row.impulse != 0)
            t.row.apply(m_bodies[size_t(t.root)], m_bodies[size_t(t.body)], t.row.impulse);
}

// The push out corrects drift at biasRate C, rigidly (massScale 1, impulseScale 0): a soft push, as the
// contacts', would give way under load (the load / (m w^2) of each joint added up a 20-link chain to 1 %).
// The velocity and relax passes sweep jointIterations times: a chain's load reaches its top link only
// through as many sweeps as there are links (one sweep let a 20-link chain sag 1.4 % as it started).
void ContactSolver::solveJoints(Real h, JointPass pass) {
    const JointSoftness soft{m_jointSoft.biasRate, 1, 0};
    const int sweeps = pass == JointPass::PushOut ? 1 : std::max(1, m_settings.jointIterations);
    for (int k = 0; k < sweeps; ++k) {
        for (Joint* j : m_solvedJoints)
            j->solve(m_bodies[size_t(j->slotA)], m_bodies[size_t(j->slotB)], h, pass, soft);
        solveTethers(h, pass, soft); // last: a chain pulled straight ends holding its load
    }
}

void ContactSolver::saveJoints() {
    for (Joint* j : m_solvedJoints) j->save();
    for (Tether& t : m_tethers) t.row.saved = t.row.impulse;
}

void ContactSolver::restoreJoints() {
    for (Joint* j : m_solvedJoints) j->restore();
    for (Tether& t : m_tethers) t.row.impulse = t.row.saved;
}

} // namespace physics
