// ContactResolution.cpp - scene bodies in and out of the contact solver.
#include "ContactResolution.h"

#include "JointClosing.h"

#include "Integrators.h"
#include "MathEigen.h"
#include "RigidBody.h"

namespace physics {

RigidBody* SceneBodyAccess::bodyOf(const RBDynamics* root) const {
    RigidBody* const* body = m_bodies.find(root);
    return body ? *body : nullptr;
}

SolverBody SceneBodyAccess::enter(RBDynamics* root, int slot) const {
    if (!root) return SolverBodyAccess::enter(nullptr, slot); // the static world
    SolverBody b;
    b.root = root;
    b.slot = slot;
    RigidBody* body = bodyOf(root);
    // The contacts were found at the step's starting poses: anchors are measured there.
    b.startOrigin = body ? body->startPosition() : toEigen(root->position);
    b.startRotation = body ? body->previousRotation() : toQuat(root->orientation);
    const bool moves = body && !body->asleep() && !body->dying() && !body->pendingRemoval &&
                       root->physicsType != PHYS_FixedInSpace && !isKinematicChain(*root);
    if (!moves) { // not ours to move, or at rest
        refresh(b);
        return b;
    }
    body->solverSlot = slot;
    b.origin = b.startOrigin;
    b.rotation = b.startRotation;
    return b;
}

void SceneBodyAccess::refresh(SolverBody& b) const {
    const RBDynamics& d = *b.root;
    RigidBody* body = bodyOf(b.root);
    b.com = b.origin = body ? body->statePosition() : toEigen(d.position);
    b.rotation = toQuat(d.orientation);
    const bool still = body && body->asleep();
    b.v = still ? Vec3::Zero() : body ? body->stateVelocity() : toEigen(d.velocity);
    b.w = still ? Vec3::Zero() : toEigen(d.angularVelocity);
}

bool SceneBodyAccess::resting(const RBDynamics* root) const {
    if (!root || root->physicsType == PHYS_FixedInSpace) return true;
    RigidBody* body = bodyOf(root);
    return body && body->asleep();
}

void SceneBodyAccess::setMotion(SolverBody& b, RigidBody* body, const Composite& c, const Vec3& v,
                                const Vec3& w, const Vec3& dv, const Vec3& dw) const {
    // The contacts were found at the step's starting pose, so lever arms are measured from the centre of
    // mass there (measuring from the integrated pose skews every torque by v dt and pumps energy into
    // rocking stacks).
    const Quat& q0 = b.startRotation;
    b.com = b.startOrigin - q0 * c.rootOffset;
    b.v = v;
    b.w = w;
    b.dv = dv;
    b.dw = dw;
    b.invMass = c.invMass;
    b.invInertia = worldInverseInertia(c, q0);
    if (size_t(b.slot) >= m_mass.size()) m_mass.resize(size_t(b.slot) + 1);
    m_mass[size_t(b.slot)] = Mass{body, c.rootOffset, c.inertia};
}

bool SceneBodyAccess::alive(const RBDynamics* root) const {
    if (!root) return true;
    RigidBody* body = bodyOf(root);
    return body && !body->dying() && !body->pendingRemoval;
}

void SceneBodyAccess::storeVelocity(const SolverBody& b) const {
    if (!b.root || b.invMass == 0.0f) return;
    const Mass& m = m_mass[size_t(b.slot)]; // setMotion recorded every movable body
    Mat3 r = b.rotation.toRotationMatrix();
    Vec3 arm = r * m.rootOffset;
    const Vec3 momentum = r * m.inertia * r.transpose() * b.w;
    b.root->angularVelocity = toVector(b.w);
    m.body->writeVelocity(b.v + b.w.cross(arm));
    b.root->angularMomentum = toVector(momentum);
    m.body->own.omega = b.w;
    m.body->own.momentum = momentum;
}

void SceneBodyAccess::prefetch(const SolverBody& b) const {
    if (b.invMass == 0.0f) return;
    // storeVelocity and storePose write the dynamics' state and the body's own; acceptWrites reads and writes
    // the same.
    m_mass[size_t(b.slot)].body->prefetchSolverState();
    SolverBodyAccess::prefetch(b);
}

void SceneBodyAccess::storePose(const SolverBody& b) const {
    SolverBodyAccess::storePose(b);
    if (b.invMass != 0.0f) m_mass[size_t(b.slot)].body->writePosition(b.origin);
}

void SceneBodyAccess::acceptWrites(const std::vector<SolverBody>& bodies, JointClosing& closing) const {
    constexpr size_t kAhead = 4;
    for (size_t i = 0; i < bodies.size(); ++i) {
        if (i + kAhead < bodies.size()) prefetch(bodies[i + kAhead]);
        const SolverBody& b = bodies[i];
        if (!b.root) continue;
        if (b.invMass == 0.0f) {
            if (RigidBody* entered = bodyOf(b.root)) entered->solverSlot = -1; // entered, never completed
            continue;
        }
        RigidBody* body = m_mass[size_t(b.slot)].body;
        body->solverSlot = -1;
        body->writtenOmega = b.root->angularVelocity;
        body->writtenMomentum = b.root->angularMomentum;
        body->writtenOrientation = b.root->orientation;
        body->rotation = b.rotation;
        body->projectedBy = toVector(b.projection);
        if (b.projection != Vec3::Zero()) closing.add(body, false); // moved alone: its joints follow
    }
}

} // namespace physics
