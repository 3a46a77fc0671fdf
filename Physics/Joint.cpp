// Joint.cpp - what every joint shares: its bodies' joint lists, letting go, deferred deletion, the frames
// entering a step, the generic warm start, save/restore and reaction, breaking, and the factories' checks.
#include "Joint.h"
#include "JointRowsInline.h"

#include "MathEigen.h"
#include "PhysicsScene.h"
#include "RigidBody.h"
#include "iUtilities.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace physics {

namespace {
std::vector<Joint*>& deferredJointDeletes() {
    static std::vector<Joint*> all;
    return all;
}
void leaveJointList(RigidBody* body, Joint* joint) {
    if (!body) return;
    auto& list = body->joints;
    list.erase(std::remove(list.begin(), list.end(), joint), list.end());
}
} // namespace

Joint::Joint(JointType type, RigidBody* a, RigidBody* b, const JointFrame& localA, const JointFrame& localB)
    : m_localA(localA), m_localB(localB), m_type(type), m_a(a), m_b(b) {
    if (m_a) m_a->joints.push_back(this);
    if (m_b) m_b->joints.push_back(this);
}

Joint::~Joint() {
    leaveJointList(m_a, this);
    leaveJointList(m_b, this);
}

// A body the joint held wakes when the joint lets go of it or goes: asleep hanging from it, it would hang in
// the air.
void Joint::letGo(const RigidBody* body) {
    if (body != m_a && body != m_b) return;
    if (RigidBody* other = body == m_a ? m_b : m_a) other->wake();
    RigidBody*& held = body == m_a ? m_a : m_b;
    leaveJointList(held, this);
    held = nullptr;
    m_letGo = true;
}

void Joint::wakeBodies() {
    for (RigidBody* held : {m_a, m_b})
        if (held) held->wake();
}

void Joint::destroy() {
    if (m_deleted) return;
    wakeBodies();
    if (!PhysicsScene::updating()) {
        delete this;
        return;
    }
    // The step may hold it (its list of joints, a break event): out of the simulation now, freed later.
    m_deleted = true;
    leaveJointList(m_a, this);
    leaveJointList(m_b, this);
    m_a = m_b = nullptr;
    deferredJointDeletes().push_back(this);
}

void Joint::deleteDeferred() {
    std::vector<Joint*> doomed;
    doomed.swap(deferredJointDeletes());
    for (Joint* j : doomed) delete j;
}

iRigidBody* Joint::publicBodyA() const { return m_a; }
iRigidBody* Joint::publicBodyB() const { return m_b; }

bool Joint::setBreakForce(float newtons) {
    if (!(newtons > 0)) {
        error(L"iJoint::setBreakForce: the force must be positive (infinite: never breaks); refused");
        return false;
    }
    change(m_breakForce, newtons); // a sleeping load may break it now
    return true;
}

bool Joint::setBreakTorque(float newtonMetres) {
    if (!(newtonMetres > 0)) {
        error(L"iJoint::setBreakTorque: the torque must be positive (infinite: never breaks); refused");
        return false;
    }
    change(m_breakTorque, newtonMetres);
    return true;
}

// A body's frame (relative to its frame's origin, body axes) in its attachment root's frame (relative to the
// root's position, the solver body's origin), at the poses now: the step's start.
JointFrame Joint::rootFrame(const RigidBody* body, const JointFrame& local) const {
    if (!body) return local; // the world
    const RBDynamics& d = body->getDynamics();
    const RBDynamics* root = d.attachmentRoot();
    const Quat qBody = toQuat(d.getWorldOrientation()), qRoot = toQuat(root->orientation);
    const Vec3 origin = toEigen(d.getWorldOrigin()), rootPosition = toEigen(root->position);
    JointFrame f;
    f.point = qRoot.conjugate() * (origin + qBody * local.point - rootPosition);
    f.basis = (qRoot.conjugate() * qBody * local.basis).normalized();
    return f;
}

void Joint::worldFrames(JointFrame& a, JointFrame& b) const {
    auto world = [](const RigidBody* body, const JointFrame& local) {
        if (!body) return local;
        const RBDynamics& d = body->getDynamics();
        const Quat q = toQuat(d.getWorldOrientation());
        return JointFrame{toEigen(d.getWorldOrigin()) + q * local.point, (q * local.basis).normalized()};
    };
    a = world(m_a, m_localA);
    b = world(m_b, m_localB);
}

Real Joint::anchorDistance() const {
    JointFrame a, b;
    worldFrames(a, b);
    return (b.point - a.point).norm();
}

void Joint::enter(int a, int b) {
    slotA = a;
    slotB = b;
    m_carried = Vec3::Zero();
    m_frameA = rootFrame(m_a, m_localA);
    m_frameB = rootFrame(m_b, m_localB);
}

void Joint::preparePoint(const SolverBody& a, const SolverBody& b) {
    const Vec3 pA = worldPoint(a, m_frameA), pB = worldPoint(b, m_frameB);
    m_point.setArms(a, b, pA - a.com, pB - b.com);
    m_pointError = pB - pA;
}

// Every sub-step starts from the impulses the last one ended with (the first from last step's), along the
// rows prepared at the poses now.
void Joint::warmStart(SolverBody& a, SolverBody& b) {
    if (!m_warmStarts) {
        resetImpulses();
        return;
    }
    if (m_usesPoint) m_point.warmStart(a, b);
    if (m_usesOrientation) m_orientation.apply(a, b, m_orientation.impulse);
    for (int i = 0; i < m_rowCount; ++i)
        if (m_rows[i].kind != RowKind::Off && m_rows[i].impulse != 0)
            m_rows[i].apply(a, b, m_rows[i].impulse);
}

void Joint::solve(SolverBody& a, SolverBody& b, Real h, JointPass pass, const JointSoftness& soft) {
    const bool push = pass == JointPass::PushOut;
    const JointSoftness rigid;
    if (m_usesOrientation)
        m_orientation.solve(a, b, push ? Vec3(soft.biasRate * m_rotationError) : Vec3::Zero(),
                            push ? soft : rigid);
    for (int i = 0; i < m_rowCount; ++i) {
        JointRow& r = m_rows[i];
        switch (r.kind) {
        case RowKind::Off:
            break;
        case RowKind::Motor:
            if (!push) r.solve(a, b, -r.error);
            break;
        case RowKind::Limit:
            r.solveLimit(a, b, r.error, h, push, soft);
            break;
        case RowKind::Equal:
            r.solve(a, b, push ? soft.biasRate * r.error : 0, push ? soft : rigid);
            break;
        }
    }
    if (m_usesPoint)
        m_point.solve(a, b, push ? Vec3(soft.biasRate * m_pointError) : Vec3::Zero(), push ? soft : rigid);
}

void Joint::save() {
    m_point.saved = m_point.impulse;
    m_point.savedSwing = m_point.swingImpulse;
    m_orientation.saved = m_orientation.impulse;
    for (int i = 0; i < m_rowCount; ++i) m_rows[i].saved = m_rows[i].impulse;
}

void Joint::restore() {
    m_point.impulse = m_point.saved;
    m_point.swingImpulse = m_point.savedSwing;
    m_orientation.impulse = m_orientation.saved;
    for (int i = 0; i < m_rowCount; ++i) m_rows[i].impulse = m_rows[i].saved;
}

Real Joint::reach() const {
    const bool together = m_type == JOINT_Ball || m_type == JOINT_Hinge || m_type == JOINT_Fixed;
    return together ? Real(0) : std::numeric_limits<Real>::infinity();
}

bool Joint::finish(Real h) {
    Vec3 linear = m_usesPoint ? m_point.impulse : Vec3::Zero();
    Vec3 angular = m_usesOrientation ? m_orientation.impulse : Vec3::Zero();
    for (int i = 0; i < m_rowCount; ++i) {
        const JointRow& r = m_rows[i];
        if (r.kind == RowKind::Off) continue;
        if (r.n.squaredNorm() > 0)
            linear += r.impulse * r.n;
        else
            angular += r.impulse * r.armB;
    }
    // About the anchors (the part about a hinge's free axis was the hinge's own).
    const Vec3 moved = m_pointShift.cross(linear);
    angular -= m_point.swings ? Vec3(moved - m_point.swingAxis * m_point.swingAxis.dot(moved)) : moved;
    m_force = (linear + m_carried) / h; // (a tether's pull runs through the anchors: no torque about them)
    m_torque = angular / h;
    if (m_broken || !(m_force.norm() > m_breakForce || m_torque.norm() > m_breakTorque)) return false;
    m_broken = true;
    return true;
}

Joint::State Joint::state() const {
    State s{m_point, m_orientation, {}, m_broken, m_force, m_torque};
    for (int i = 0; i < kMaxRows; ++i) s.rows[i] = m_rows[i];
    return s;
}

void Joint::setState(const State& s) {
    m_point = s.point;
    m_orientation = s.orientation;
    for (int i = 0; i < kMaxRows; ++i) m_rows[i] = s.rows[i];
    m_broken = s.broken;
    m_force = s.force;
    m_torque = s.torque;
}

void Joint::resetImpulses() {
    m_point.impulse = m_orientation.impulse = Vec3::Zero();
    m_point.swingImpulse = 0;
    for (int i = 0; i < kMaxRows; ++i) m_rows[i].impulse = 0;
}

bool jointFrames(const wchar_t* factory, iRigidBody* a, iRigidBody* b, const Vector& anchorA,
                 const Vector& anchorB, const Vector& axis, RigidBody*& bodyA, RigidBody*& bodyB,
                 JointFrame& localA, JointFrame& localB) {
    auto refuse = [factory](const wchar_t* why) {
        error((std::wstring(factory) + L": " + why + L"; refused").c_str());
        return false;
    };
    bodyA = dynamic_cast<RigidBody*>(a);
    bodyB = dynamic_cast<RigidBody*>(b);
    if (!a) return refuse(L"body A is nullptr (the world may only be body B)");
    if (!bodyA || (b && !bodyB)) return refuse(L"only bodies made by CreateRigidBody or CreatePhysicsFrame");
    if (a == b) return refuse(L"a body cannot be joined to itself");
    if (bodyA->dying() || (bodyB && bodyB->dying())) return refuse(L"a body is being deleted");
    if (!anchorA.isFinite() || !anchorB.isFinite() || !axis.isFinite() || !(axis.length() > 1e-6f))
        return refuse(L"anchors and axis must be finite and the axis not zero");
    const Vec3 x = toEigen(axis).normalized();
    Vec3 across[2];
    tangentBasis(x, across); // (x, across[0], across[1]) right-handed
    Mat3 axes;
    axes << x, across[0], across[1];
    const Quat world = Quat(axes).normalized();
    auto local = [&](const RigidBody* body, const Vector& anchor) {
        if (!body) return JointFrame{toEigen(anchor), world};
        const RBDynamics& d = body->getDynamics();
        const Quat q = toQuat(d.getWorldOrientation());
        return JointFrame{q.conjugate() * (toEigen(anchor) - toEigen(d.getWorldOrigin())),
                          (q.conjugate() * world).normalized()};
    };
    localA = local(bodyA, anchorA);
    localB = local(bodyB, anchorB);
    return true;
}

} // namespace physics
