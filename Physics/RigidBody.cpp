// RigidBody.cpp - the simulator's rigid body: frame binding, listeners, lifetime, validation, interpolation.
#include "RigidBody.h"

#include "BodyValidation.h"
#include "FrameDriver.h"
#include "Joint.h"
#include "PhysicsScene.h"
#include "iFrame.h"
#include "iUtilities.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

namespace physics {

namespace {
// Which bodies are bound to which frame (only looked up when a PhysicsFrame is deleted).
std::unordered_multimap<const iFrame*, RigidBody*>& bindings() {
    static std::unordered_multimap<const iFrame*, RigidBody*> all;
    return all;
}
} // namespace

void RigidBody::bindFrame(iFrame* o) {
    if (m_frame == o) return;
    if (m_frame) {
        auto range = bindings().equal_range(m_frame);
        for (auto it = range.first; it != range.second; ++it)
            if (it->second == this) {
                bindings().erase(it);
                break;
            }
    }
    m_frame = o;
    if (o) bindings().emplace(o, this);
}

void RigidBody::frameDeleted(const iFrame* f) {
    std::vector<RigidBody*> bound;
    auto range = bindings().equal_range(f);
    for (auto it = range.first; it != range.second; ++it) bound.push_back(it->second);
    for (RigidBody* b : bound) b->bindFrame(nullptr);
}

RigidBody::RigidBody(iFrame* frame) {
    // A new body starts where its frame is (the game usually positions the frame first).
    bindFrame(frame);
    if (frame) {
        m_dyn.orientation = frameWorldRotation(frame);
        m_dyn.position = frame->position() + m_dyn.orientation.direction(m_dyn.com);
        m_writtenWorld = frame->world();
    }
    snapshotValid();
    recordPreviousPose();
    recordStepPose();
}

RigidBody::~RigidBody() {
    bindFrame(nullptr);
    while (!joints.empty()) joints.back()->letGo(this); // each leaves the list
    // Collision spaces unbind their geometries from this body before it goes (iRigidBody.h).
    rigidBodyDestroyed(this);
    // m_dyn's destructor then releases any bodies attached to this one (they keep their world pose).
}

iRigidBody* RigidBody::clone() const {
    // The copy has the same dynamics (unattached: RBDynamics copies never copy links), listeners and force
    // generators, no frame (two bodies driving one frame would fight), and joins this body's scene.
    RigidBody* copy = new RigidBody(nullptr);
    copy->m_dyn = m_dyn;
    copy->m_listeners = m_listeners;
    copy->m_generators = m_generators;
    copy->m_switches = m_switches;
    copy->inheritLastValid(*this);
    copy->recordPreviousPose();
    copy->recordStepPose();
    if (m_scene && !m_dying) m_scene->add(copy);
    return copy;
}

void RigidBody::attach(iFrame* o) {
    if (m_dying) return;
    // The frame follows this body from now on: it is moved to the body's pose at once.
    bindFrame(o);
    if (o) {
        m_writtenWorld = o->world(); // not a game edit to adopt: the body's pose wins
        recordPreviousPose();
        writeFrame(1.0f);
    }
}

void RigidBody::attachListener(iCollisionListener* l) {
    if (!l) {
        error(L"RigidBody::attachListener: nullptr refused");
        return;
    }
    if (std::find(m_listeners.begin(), m_listeners.end(), l) == m_listeners.end()) m_listeners.push_back(l);
}

void RigidBody::detachListener(const iCollisionListener* l) {
    m_listeners.erase(std::remove(m_listeners.begin(), m_listeners.end(), l), m_listeners.end());
}

bool RigidBody::setGravityScale(float scale) {
    if (!std::isfinite(scale)) {
        error(L"iRigidBodySwitches::setGravityScale: non-finite scale refused");
        return false;
    }
    if (scale != m_switches.gravityScale) wake(); // asleep under the old weight, it would hang
    m_switches.gravityScale = scale;
    return true;
}

void RigidBody::setDynamics(const RBDynamics& d) {
    RBDynamics candidate(d);
    if (const wchar_t* why = checkDynamics(candidate, Matrix(), Matrix())) {
        std::wstring msg = std::wstring(L"RigidBody::setDynamics: refused, ") + why;
        error(msg.c_str());
        return;
    }
    m_dyn = candidate; // keeps this body's place in its attachment chain
}

void RigidBody::Delete() const {
    RigidBody* self = const_cast<RigidBody*>(this);
    if (m_dying) return; // already queued
    if (m_owner) {
        error(L"RigidBody::Delete: this body belongs to a PhysicsFrame; delete the PhysicsFrame instead");
        return;
    }
    if (PhysicsScene* stepping = PhysicsScene::updating()) {
        // Inside a step (a fixed updater, a force generator, a listener): the step still walks its bodies,
        // and its composites may hold this body even when it is in another scene or none. So only mark it;
        // the stepping scene deletes it when the step ends.
        self->markDying();
        stepping->deferDelete(self);
        return;
    }
    self->destroy();
}

void RigidBody::kill() {
    if (m_dying) return; // being deleted: it leaves anyway
    m_alive = false;
    if (m_scene) m_scene->deferRemove(this);
}

void RigidBody::destroy() {
    if (m_scene) m_scene->forget(this);
    delete this;
}

namespace {
// Bit for bit (a frame holding the same NaN as last time is not a new edit: NaN != NaN).
template <class T> bool sameBits(const T& a, const T& b) { return std::memcmp(&a, &b, sizeof(T)) == 0; }
} // namespace

void RigidBody::adoptFrameEdits() {
    if (!m_frame || m_dyn.attachedTo()) return;
    Matrix w = m_frame->world();
    if (w == m_writtenWorld || sameBits(w, m_writtenWorld)) return;
    if (!w.isFinite()) {
        // Refused once: the body keeps its state, and the frame is put back where the body is (through
        // iFrame's members a NaN in the rotation is replaced; one in T's translation row survives
        // translate(), and then the same NaN is not reported again).
        error(
            L"RigidBody: the bound frame's transform is not finite; refused, the frame is moved back to the "
            L"body's pose");
        setFrameWorldPose(m_frame, m_dyn.getWorldOrientation(), m_dyn.getWorldOrigin());
        m_writtenWorld = m_frame->world();
        return;
    }
    m_dyn.orientation = frameWorldRotation(m_frame);
    m_dyn.position = w.position() + m_dyn.orientation.direction(m_dyn.com);
    invalidatePoses(); // bodies attached to this one moved too
    m_writtenWorld = w;
    recordPreviousPose(); // a teleport: nothing to interpolate across
}

bool RigidBody::validate(const char* when, bool motionOnly) {
    // Orientations known to be rotations: the last one accepted, the last one the engine wrote (from a unit
    // quaternion, or a locked body's accepted matrix).
    const Matrix* clean[2] = {&m_checkedOrientation, &writtenOrientation};
    const wchar_t* why = motionOnly ? checkMotion(m_dyn, clean)
                                    : checkDynamics(m_dyn, m_lastValid.getInertiaTensor(),
                                                    m_lastValid.getInverseInertiaTensor(), clean);
    if (!why) {
        m_checkedOrientation = m_dyn.orientation;
        return true;
    }
    std::wstring msg = L"PhysicsScene: invalid rigid body state ";
    for (const char* c = when; *c; ++c) msg += wchar_t(*c);
    msg += L" (";
    msg += why;
    msg += L"); the body is restored to its last valid state";
    error(msg.c_str());
    m_dyn = m_lastValid; // operator= keeps the attachment links
    invalidatePoses();
    return false;
}

namespace {
// Whether d holds, bit for bit, what RBDynamics::operator= copied into v, in two parts: the settings, which a
// step never writes, and the motion, which it does (BodyValidation.h, checkMotion). Where both are v's,
// checkDynamics (given v's tensors and orientation as the known ones) finds d as it found v.
bool sameSettings(const RBDynamics& d, const RBDynamics& v) {
    return sameBits(d.mass, v.mass) && sameBits(d.com, v.com) && sameBits(d.acceleration, v.acceleration) &&
           sameBits(d.force, v.force) && sameBits(d.torque, v.torque) &&
           sameBits(d.dragCoefficient, v.dragCoefficient) && sameBits(d.angularDrag, v.angularDrag) &&
           sameBits(d.restitution, v.restitution) && sameBits(d.friction, v.friction) &&
           d.physicsType == v.physicsType && d.isInertiaSetByGame() == v.isInertiaSetByGame() &&
           sameBits(d.getInertiaTensor(), v.getInertiaTensor()) &&
           sameBits(d.getInverseInertiaTensor(), v.getInverseInertiaTensor());
}

bool sameMotion(const RBDynamics& d, const RBDynamics& v) {
    return sameBits(d.position, v.position) && sameBits(d.orientation, v.orientation) &&
           sameBits(d.velocity, v.velocity) && sameBits(d.angularVelocity, v.angularVelocity) &&
           sameBits(d.angularMomentum, v.angularMomentum) && sameBits(d.lastVelocity, v.lastVelocity) &&
           sameBits(d.temporalForce, v.temporalForce) && sameBits(d.temporalTorque, v.temporalTorque);
}

// The motion fields of operator=, copied: with the same settings, to like effect.
void copyMotion(RBDynamics& to, const RBDynamics& from) {
    to.position = from.position;
    to.orientation = from.orientation;
    to.velocity = from.velocity;
    to.angularVelocity = from.angularVelocity;
    to.angularMomentum = from.angularMomentum;
    to.lastVelocity = from.lastVelocity;
    to.temporalForce = from.temporalForce;
    to.temporalTorque = from.temporalTorque;
}
} // namespace

// A step changes only the motion, and so does a game that only moves a body: with the settings as last
// accepted, only the motion is checked and copied (checking and copying the whole state after every step
// was 8 % of the instructions of 1,000 spheres raining into a pile; a third of that went).
bool RigidBody::acceptState(const char* when) {
    if (m_lastValidChecked && sameSettings(m_dyn, m_lastValid)) {
        if (sameMotion(m_dyn, m_lastValid)) return true;
        if (!validate(when, true)) return false;
        copyMotion(m_lastValid, m_dyn);
        return true;
    }
    if (!validate(when, false)) return false;
    snapshotValid();
    m_lastValidChecked = true;
    return true;
}

void RigidBody::recordPreviousPose() {
    m_prevPosition = worldPosition();
    m_prevRotation = toQuat(worldOrientation());
    // A root starts the step from its own Real pose (the same numbers in a float build, whose start
    // rotation stays the float matrix's, as the determinism hashes were recorded with).
    const bool root = !m_dyn.attachedTo();
    m_startPosition = root ? statePosition() : toEigen(m_prevPosition);
    if (GUARDIAN_REAL_IS_DOUBLE && root) m_prevRotation = ownRotation();
    projectedBy = Vector();
}

void RigidBody::recordStepPose() {
    m_stepPosition = worldPosition();
    m_stepOrientation = worldOrientation();
}

bool RigidBody::editedWhileAsleep() const {
    const Vector zero;
    const RBDynamics& d = m_dyn;
    return d.velocity != zero || d.angularVelocity != zero || d.angularMomentum != zero || d.force != zero ||
           d.temporalForce != zero || d.acceleration != zero || d.torque != zero ||
           d.temporalTorque != zero || movedByGame();
}

bool RigidBody::movedByGame() const {
    return worldPosition() != m_stepPosition || worldOrientation() != m_stepOrientation;
}

void RigidBody::writeFrame(float alpha) {
    if (!m_frame) return;
    adoptFrameEdits();
    // The game moved the body (its dynamics) since the last step: show it there, do not smear towards it.
    if (movedByGame()) {
        m_dyn.markTeleported(); // the next step will not see the edit: say it here
        recordPreviousPose();
        recordStepPose();
    }
    // Drawn pose = previous step's pose blended towards the current one: position lerp, orientation slerp;
    // alpha 1 (interpolation off) is the current pose itself, with no blend computed.
    Vector p = worldPosition();
    Matrix r = worldOrientation();
    if (alpha < 1.0f) {
        p = m_prevPosition + (p - m_prevPosition) * alpha;
        const Quat now = m_dyn.attachedTo() ? toQuat(r) : ownRotation(); // a root's world rotation is its own
        r = toOrientation(m_prevRotation.slerp(alpha, now).normalized());
    }
    setFrameWorldPose(m_frame, r, p - r.direction(m_dyn.com));
    m_writtenWorld = m_frame->world();
}

unsigned long long RigidBody::newFrameRound() {
    static unsigned long long round = 0;
    return ++round;
}

void RigidBody::writeFrameAfterParent(float alpha, unsigned long long round) {
    if (m_frameRound == round) return;
    m_frameRound = round;
    if (!m_frame) return;
    // Frames attached to each other through PhysicsFrame::attachTo have attached bodies too, so the body
    // chain gives the frame order; a course framework's iFrame does not tell its parent.
    for (const RBDynamics* a = m_dyn.attachedTo(); a && m_scene; a = a->attachedTo()) {
        RigidBody* p = m_scene->bodyOf(a);
        if (!p || !p->m_frame) continue;
        if (!p->m_dying && !p->pendingRemoval) p->writeFrameAfterParent(alpha, round);
        break; // that body wrote its own ancestors first
    }
    writeFrame(alpha);
}

} // namespace physics

extern "C" iRigidBody* CreateRigidBody(iFrame* o) {
    physics::RigidBody* body = new physics::RigidBody(o);
    if (physics::PhysicsScene* scene = physics::PhysicsScene::active())
        scene->add(body);
    else // the seed's order is scene first: say so now, not when the body silently never moves
        error(L"CreateRigidBody: no physics scene exists yet, so this body is not simulated; add() it to a "
              L"scene once there is one");
    return body;
}
