// RBDynamicsDefinitions.h - inline definitions of RBDynamics' functions (included by RBDynamics.h).
//
// Header-only because both the simulator and the collision detector read RBDynamics and each package must
// carry it. Composite (attached) bodies: an attached body's world pose follows its parent chain, and
// impulses and getCompositeMass act on the whole composite (see RBDynamics.h).
#pragma once

#include "MathDefinitions.h"
#include "RBDynamics.h"
#include "iUtilities.h"

#include <cmath>

inline RBDynamics::RBDynamics() : m_inertia(getSphereInertiaTensor(1.0f, 1.0f)), m_inverseInertia(1) {
    m_inverseInertia = m_inertia.inverse();
}

inline RBDynamics::RBDynamics(const RBDynamics& src) { *this = src; }

inline RBDynamics& RBDynamics::operator=(const RBDynamics& src) {
    if (this == &src) return *this;
    position = src.position;
    velocity = src.velocity;
    lastVelocity = src.lastVelocity;
    acceleration = src.acceleration;
    force = src.force;
    temporalForce = src.temporalForce;
    mass = src.mass;
    dragCoefficient = src.dragCoefficient;
    restitution = src.restitution;
    friction = src.friction;
    com = src.com;
    physicsType = src.physicsType;
    orientation = src.orientation;
    angularVelocity = src.angularVelocity;
    angularMomentum = src.angularMomentum;
    torque = src.torque;
    temporalTorque = src.temporalTorque;
    m_inertia = src.m_inertia;
    m_inverseInertia = src.m_inverseInertia;
    return *this;
}

inline RBDynamics::~RBDynamics() {
    while (m_firstChild) m_firstChild->attachTo(nullptr);
    unlinkFromParent();
}

inline Vector RBDynamics::getWorldCOM() const { return getWorldPosition(); }

inline Vector RBDynamics::getVelocityAtWorldPoint(const Vector& p) const {
    const RBDynamics* root = attachmentRoot();
    return root->velocity + cross(root->angularVelocity, p - root->position);
}

namespace guardian_detail {
inline bool isValidInertia(const Matrix& i) {
    gmath::Mat3 t = gmath::block3(i);
    if (!t.allFinite()) return false;
    if ((t - t.transpose()).cwiseAbs().maxCoeff() > 1e-4f * (1.0f + t.cwiseAbs().maxCoeff())) return false;
    Eigen::SelfAdjointEigenSolver<gmath::Mat3> eig(t);
    return eig.eigenvalues().minCoeff() > 0.0f;
}
} // namespace guardian_detail

inline void RBDynamics::setInertiaTensor(const Matrix& i) {
    if (!guardian_detail::isValidInertia(i)) {
        error(
            L"RBDynamics::setInertiaTensor: tensor is not finite, symmetric and positive definite; refused");
        return;
    }
    m_inertia = gmath::fromBlock3(gmath::block3(i));
    m_inverseInertia = gmath::fromBlock3(gmath::block3(i).inverse());
}

inline void RBDynamics::setInverseInertiaTensor(const Matrix& i) {
    if (!guardian_detail::isValidInertia(i)) {
        error(L"RBDynamics::setInverseInertiaTensor: tensor is not finite, symmetric and positive definite; "
              L"refused");
        return;
    }
    m_inverseInertia = gmath::fromBlock3(gmath::block3(i));
    m_inertia = gmath::fromBlock3(gmath::block3(i).inverse());
}

inline Matrix& RBDynamics::getInertiaTensor() { return m_inertia; }
inline Matrix& RBDynamics::getInverseInertiaTensor() { return m_inverseInertia; }
inline const Matrix& RBDynamics::getInertiaTensor() const { return m_inertia; }
inline const Matrix& RBDynamics::getInverseInertiaTensor() const { return m_inverseInertia; }

inline Matrix RBDynamics::getWorldInverseInertiaTensor() const {
    Matrix r = getWorldOrientation();
    return r.transpose() * m_inverseInertia * r;
}

inline void RBDynamics::ApplyImpulse(const Vector& impulse, const Vector& point) {
    if (!impulse.isFinite() || !point.isFinite()) {
        error(L"RBDynamics::ApplyImpulse: non-finite impulse or point refused");
        return;
    }
    RBDynamics* root = attachmentRoot();
    if (root->physicsType == PHYS_FixedInSpace || !(root->mass < INFINITE_MASS)) return;
    MassProperties mp = getCompositeMassProperties();
    if (!(mp.mass < INFINITE_MASS)) return;
    // The whole composite responds: its centre of mass C gets dV = J/M, its momentum about C gets
    // dL = (p - C) x J, and w = I_world^-1 L. The root's velocity is that of the root's own centre of mass,
    // so it also picks up dw x (root - C).
    Vector dL = cross(point - mp.centre, impulse);
    Vector dOmega = dL * mp.inverseInertia;
    root->velocity += impulse * RECIP(mp.mass) + cross(dOmega, root->position - mp.centre);
    root->angularMomentum += dL;
    root->angularVelocity = root->angularMomentum * mp.inverseInertia;
}

inline RBDynamics::MassProperties RBDynamics::getCompositeMassProperties() const {
    // First pass: mass and centre; second pass: inertia about that centre (parallel-axis theorem), each
    // part's tensor turned to world axes (R^T I R for row vectors). Iterative depth-first walks, accumulated
    // in double.
    const RBDynamics* root = attachmentRoot();
    MassProperties out{0.0f, Vector(), Matrix(1), Matrix()};
    double m = 0, cx = 0, cy = 0, cz = 0;
    bool infinite = false;
    auto next = [root](const RBDynamics* n) -> const RBDynamics* {
        if (n->m_firstChild) return n->m_firstChild;
        while (n && n != root && !n->m_nextSibling) n = n->m_parent;
        return (n && n != root) ? n->m_nextSibling : nullptr;
    };
    for (const RBDynamics* n = root; n; n = next(n)) {
        if (!(n->mass < INFINITE_MASS)) infinite = true;
        Vector p = n->getWorldPosition();
        m += n->mass;
        cx += double(n->mass) * p.x;
        cy += double(n->mass) * p.y;
        cz += double(n->mass) * p.z;
    }
    if (infinite || !(m > 0)) {
        out.mass = infinite ? INFINITE_MASS : float(m);
        out.centre = root->position;
        out.inertia = root->getWorldOrientation().transpose() * root->m_inertia * root->getWorldOrientation();
        out.inverseInertia = Matrix(0);
        return out;
    }
    out.mass = float(m);
    out.centre = Vector(float(cx / m), float(cy / m), float(cz / m));
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
    for (const RBDynamics* n = root; n; n = next(n)) {
        gmath::Mat3 r = gmath::block3(n->getWorldOrientation());
        inertia += (r.transpose() * gmath::block3(n->m_inertia) * r).cast<double>();
        Eigen::Vector3d d = gmath::map(n->getWorldPosition() - out.centre).cast<double>();
        inertia += double(n->mass) * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
    }
    out.inertia = gmath::fromBlock3(inertia.cast<float>());
    out.inverseInertia = gmath::fromBlock3(inertia.inverse().cast<float>());
    return out;
}

// --- attachment chains ---
inline RBDynamics* RBDynamics::attachedTo() const { return m_parent; }

inline RBDynamics* RBDynamics::attachmentRoot() const {
    const RBDynamics* r = this;
    while (r->m_parent) r = r->m_parent;
    return const_cast<RBDynamics*>(r);
}

inline Vector RBDynamics::getWorldPosition() const {
    return m_parent ? position * m_parent->getWorldOrientation() + m_parent->getWorldPosition() : position;
}

inline Matrix RBDynamics::getWorldOrientation() const {
    return m_parent ? orientation * m_parent->getWorldOrientation() : orientation;
}

inline Vector RBDynamics::getWorldOrigin() const {
    return getWorldPosition() - getWorldOrientation().direction(com);
}

inline float RBDynamics::getMass() const { return attachmentRoot()->mass; }

inline float RBDynamics::getCompositeMass() const {
    // Sum over the tree rooted at the chain's root (iterative depth-first walk).
    const RBDynamics* root = attachmentRoot();
    float total = 0.0f;
    const RBDynamics* n = root;
    while (n) {
        total += n->mass;
        if (n->m_firstChild) {
            n = n->m_firstChild;
            continue;
        }
        while (n && n != root && !n->m_nextSibling) n = n->m_parent;
        n = (n && n != root) ? n->m_nextSibling : nullptr;
    }
    return total;
}

inline void RBDynamics::unlinkFromParent() {
    if (!m_parent) return;
    RBDynamics** link = &m_parent->m_firstChild;
    while (*link && *link != this) link = &(*link)->m_nextSibling;
    if (*link) *link = m_nextSibling;
    m_parent = nullptr;
    m_nextSibling = nullptr;
}

inline void RBDynamics::attachTo(RBDynamics* p) {
    for (const RBDynamics* a = p; a; a = a->m_parent) {
        if (a == this) {
            error(L"RBDynamics::attachTo: attaching a body to itself or to a descendant refused");
            return;
        }
    }
    if (!p && !m_parent) return; // already a root: detaching changes nothing (and must keep a composite's L)
    // World pose and velocity before the change, so that attaching and detaching are seamless.
    Vector worldPos = getWorldPosition();
    Matrix worldRot = getWorldOrientation();
    Vector worldVel = getVelocityAtWorldPoint(worldPos);
    Vector worldOmega = attachmentRoot()->angularVelocity;
    unlinkFromParent();
    if (p) {
        Matrix parentRot = p->getWorldOrientation();
        position = (worldPos - p->getWorldPosition()) * parentRot.transpose();
        orientation = worldRot * parentRot.transpose();
        m_parent = p;
        m_nextSibling = p->m_firstChild;
        p->m_firstChild = this;
    } else {
        position = worldPos;
        orientation = worldRot;
        velocity = worldVel;
        angularVelocity = worldOmega;
        angularMomentum = angularVelocity * getCompositeMassProperties().inertia; // its own subtree, if any
    }
}
