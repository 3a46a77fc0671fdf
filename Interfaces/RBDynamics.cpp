// RBDynamics.cpp - RBDynamics' functions: inertia, impulses, and attachment chains (composite bodies).
//
// Compiled once per package (both the simulator and the collision detector read RBDynamics). Composite
// (attached) bodies: an attached body's world pose follows its parent chain, and impulses and
// getCompositeMass act on the whole composite (see RBDynamics.h). Eigen is used in here only.
#include "RBDynamics.h"

#include "MathEigen.h"
#include "iUtilities.h"

#include <Eigen/Eigenvalues>

#include <atomic>
#include <cmath>

namespace {
std::atomic<unsigned long long> g_attachmentEpoch{0};
} // namespace

unsigned long long RBDynamics::attachmentEpoch() { return g_attachmentEpoch.load(std::memory_order_relaxed); }

RBDynamics::RBDynamics() : m_inertia(getSphereInertiaTensor(1.0f, 1.0f)), m_inverseInertia(1) {
    m_inverseInertia = m_inertia.inverse();
    m_derivedInertia = m_inertia;
    m_derivedInverse = m_inverseInertia;
    updateInertia();
}

RBDynamics::RBDynamics(const RBDynamics& src) { *this = src; }

RBDynamics& RBDynamics::operator=(const RBDynamics& src) {
    if (this == &src) return *this;
    position = src.position;
    velocity = src.velocity;
    lastVelocity = src.lastVelocity;
    acceleration = src.acceleration;
    force = src.force;
    temporalForce = src.temporalForce;
    mass = src.mass;
    dragCoefficient = src.dragCoefficient;
    angularDrag = src.angularDrag;
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
    m_inertiaFromGame = src.m_inertiaFromGame;
    m_derivedInertia = src.m_derivedInertia;
    m_derivedInverse = src.m_derivedInverse;
    if (m_shapeParts.empty()) m_shape = src.m_shape; // a body with geometries keeps its own shape
    m_shapeDirty = true;                             // derived again at the next updateInertia()
    return *this;
}

RBDynamics::~RBDynamics() {
    while (m_firstChild) m_firstChild->attachTo(nullptr);
    unlinkFromParent();
}

Vector RBDynamics::getWorldCOM() const { return getWorldPosition(); }

Vector RBDynamics::getVelocityAtWorldPoint(const Vector& p) const {
    const RBDynamics* root = attachmentRoot();
    return root->velocity + cross(root->angularVelocity, p - root->position);
}

bool isValidInertiaTensor(const Matrix& i) {
    // In double: entries near the float limit square and subtract without overflowing here.
    Eigen::Matrix3d t = gmath::block3(i).cast<double>();
    if (!t.allFinite()) return false;
    if ((t - t.transpose()).cwiseAbs().maxCoeff() > 1e-4 * (1.0 + t.cwiseAbs().maxCoeff())) return false;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(t);
    return eig.eigenvalues().minCoeff() > 0.0;
}

bool isRotationLock(const Matrix& inverse) { return gmath::block3(inverse).isZero(0.0f); }

namespace {
// The inverse of a valid tensor, inverted in double (a float 3x3 inverse overflows its determinant from
// entries of about 1e13 on: a 1 km rock's 2.5e17 came out as zero). False when the inverse does not fit a
// float as a valid tensor (entries beyond the float range, or so small they flush to zero).
bool invertTensor(const Matrix& i, Matrix& inverse) {
    if (!isValidInertiaTensor(i)) return false;
    Eigen::Matrix3d inv = gmath::block3(i).cast<double>().inverse();
    Matrix out = gmath::fromBlock3(inv.cast<float>());
    if (!isValidInertiaTensor(out)) return false;
    inverse = out;
    return true;
}
} // namespace

void RBDynamics::setInertiaTensor(const Matrix& i) {
    Matrix inverse;
    if (!invertTensor(i, inverse)) {
        error(L"RBDynamics::setInertiaTensor: tensor is not finite, symmetric and positive definite (with an "
              L"inverse that is too, in float); refused");
        return;
    }
    m_inertia = gmath::fromBlock3(gmath::block3(i));
    m_inverseInertia = inverse;
    m_inertiaFromGame = true;
}

void RBDynamics::setInverseInertiaTensor(const Matrix& i) {
    if (isRotationLock(i)) { // zero: infinite inertia, the body never turns (the tensor reads zero)
        m_inverseInertia = Matrix(0);
        m_inertia = Matrix(0);
        m_inertiaFromGame = true;
        return;
    }
    Matrix inertia;
    if (!invertTensor(i, inertia)) {
        error(L"RBDynamics::setInverseInertiaTensor: tensor is not zero, or finite, symmetric and positive "
              L"definite (with an inverse that is too, in float); refused");
        return;
    }
    m_inverseInertia = gmath::fromBlock3(gmath::block3(i));
    m_inertia = inertia;
    m_inertiaFromGame = true;
}

// --- inertia from shape and mass ---
namespace {
// m (|d|^2 1 - d d^T): the parallel-axis term for an offset d.
Eigen::Matrix3d parallelAxis(double m, const Eigen::Vector3d& d) {
    return m * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
}
} // namespace

ShapeMass sphereShapeMass(float r, const Vector& centre) {
    ShapeMass s;
    s.volume = float(4.0 / 3.0 * 3.14159265358979 * double(r) * r * r);
    s.centroid = centre;
    s.unitInertia = getSphereInertiaTensor(1.0f, r);
    return s;
}

ShapeMass boxShapeMass(const Vector& h, const Vector& centre, const Matrix& rotation) {
    ShapeMass s;
    s.volume = 8.0f * h.x * h.y * h.z;
    s.centroid = centre;
    // Row vectors: w_box = w_body R^T, so the body-axes tensor is R^T I_box R.
    gmath::Mat3 r = gmath::block3(rotation);
    s.unitInertia = gmath::fromBlock3(r.transpose() * gmath::block3(getBoxInertiaTensor(1.0f, h)) * r);
    return s;
}

ShapeMass combineShapeMass(const ShapeMass* parts, size_t n) {
    ShapeMass out;
    double volume = 0;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (size_t i = 0; i < n; ++i) {
        if (!(parts[i].volume > 0.0f)) continue;
        volume += parts[i].volume;
        centre += double(parts[i].volume) * gmath::map(parts[i].centroid).cast<double>();
    }
    if (!(volume > 0)) return out;
    centre /= volume;
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
    for (size_t i = 0; i < n; ++i) {
        if (!(parts[i].volume > 0.0f)) continue;
        double share = parts[i].volume / volume;
        inertia += share * gmath::block3(parts[i].unitInertia).cast<double>();
        inertia += parallelAxis(share, gmath::map(parts[i].centroid).cast<double>() - centre);
    }
    out.volume = float(volume);
    out.centroid = Vector(float(centre.x()), float(centre.y()), float(centre.z()));
    out.unitInertia = gmath::fromBlock3(inertia.cast<float>());
    return out;
}

void RBDynamics::combineShapeParts() {
    std::vector<ShapeMass> shapes;
    shapes.reserve(m_shapeParts.size());
    for (const ShapePart& p : m_shapeParts) shapes.push_back(p.shape);
    m_shape = combineShapeMass(shapes.data(), shapes.size());
    m_shapeDirty = true;
    updateInertia();
}

void RBDynamics::setShapeMass(const void* owner, const ShapeMass& s) {
    if (!(s.volume > 0.0f) || !std::isfinite(s.volume) || !s.centroid.isFinite() ||
        !isValidInertiaTensor(s.unitInertia)) {
        removeShapeMass(owner);
        return;
    }
    for (ShapePart& p : m_shapeParts) {
        if (p.owner == owner) {
            p.shape = s;
            combineShapeParts();
            return;
        }
    }
    m_shapeParts.push_back({owner, s});
    combineShapeParts();
}

void RBDynamics::removeShapeMass(const void* owner) {
    for (size_t i = 0; i < m_shapeParts.size(); ++i) {
        if (m_shapeParts[i].owner == owner) {
            m_shapeParts.erase(m_shapeParts.begin() + std::ptrdiff_t(i));
            combineShapeParts();
            return;
        }
    }
}

void RBDynamics::useShapeInertia() {
    m_inertiaFromGame = false;
    m_derivedInertia = m_inertia; // what is there now is not a write through a reference
    m_derivedInverse = m_inverseInertia;
    m_shapeDirty = true;
    updateInertia();
}

bool RBDynamics::updateInertia() {
    if (m_inertiaFromGame) return false;
    if (m_inertia != m_derivedInertia || m_inverseInertia != m_derivedInverse) {
        m_inertiaFromGame = true; // the game wrote through getInertiaTensor() / getInverseInertiaTensor()
        return false;
    }
    // INFINITE_MASS (immovable) or an invalid mass or com (the simulator reports those): left as it is.
    if (!(mass > 0.0f) || !(mass < INFINITE_MASS) || !com.isFinite()) return false;
    if (!m_shapeDirty && mass == m_derivedMass && com == m_derivedCom) return false;
    Eigen::Matrix3d unit;
    if (m_shape.volume > 0.0f) {
        Eigen::Vector3d d = (gmath::map(m_shape.centroid) - gmath::map(com)).cast<double>();
        unit = gmath::block3(m_shape.unitInertia).cast<double>() + parallelAxis(1.0, d);
    } else {
        unit = 0.4 * Eigen::Matrix3d::Identity(); // no geometry: a solid sphere of radius 1 m
    }
    Eigen::Matrix3d inertia = double(mass) * unit;
    Matrix tensor = gmath::fromBlock3(inertia.cast<float>());
    if (!isValidInertiaTensor(tensor)) return false; // a mass so large or small that floats give out
    Matrix inverse = gmath::fromBlock3(inertia.inverse().cast<float>());
    if (!inverse.isFinite()) return false;
    m_derivedMass = mass;
    m_derivedCom = com;
    m_shapeDirty = false;
    bool changed = tensor != m_inertia || inverse != m_inverseInertia;
    m_inertia = m_derivedInertia = tensor;
    m_inverseInertia = m_derivedInverse = inverse;
    return changed;
}

Matrix& RBDynamics::getInertiaTensor() { return m_inertia; }
Matrix& RBDynamics::getInverseInertiaTensor() { return m_inverseInertia; }
const Matrix& RBDynamics::getInertiaTensor() const { return m_inertia; }
const Matrix& RBDynamics::getInverseInertiaTensor() const { return m_inverseInertia; }

Matrix RBDynamics::getWorldInverseInertiaTensor() const {
    Matrix r = getWorldOrientation();
    return r.transpose() * m_inverseInertia * r;
}

void RBDynamics::ApplyImpulse(const Vector& impulse, const Vector& point) {
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

void RBDynamics::ApplyForce(const Vector& force, const Vector& point) {
    if (!force.isFinite() || !point.isFinite()) {
        error(L"RBDynamics::ApplyForce: non-finite force or point refused");
        return;
    }
    // Through the part's own centre of mass plus the couple: the integrator adds (part - C) x F for a part
    // of a composite, so the total moment about C is (point - C) x F.
    temporalForce += force;
    temporalTorque += cross(point - getWorldPosition(), force);
}

RBDynamics::MassProperties RBDynamics::getCompositeMassProperties() const {
    // Every part's world pose first, in one walk down from the root (each from its parent's: O(parts), where
    // asking each part for its world pose was O(parts x depth), and detaching from a deep chain repeated
    // it). Then mass and centre, then inertia about that centre (parallel-axis theorem), each part's tensor
    // turned to world axes (R^T I R for row vectors), accumulated in double.
    const RBDynamics* root = attachmentRoot();
    struct Placed {
        const RBDynamics* n;
        Vector p;
        Matrix r;
    };
    std::vector<Placed> parts, stack;
    stack.push_back({root, root->position, root->orientation});
    while (!stack.empty()) {
        Placed x = stack.back();
        stack.pop_back();
        parts.push_back(x);
        for (const RBDynamics* c = x.n->m_firstChild; c; c = c->m_nextSibling)
            stack.push_back({c, c->position * x.r + x.p, c->orientation * x.r}); // as getWorldPosition does
    }
    MassProperties out{0.0f, Vector(), Matrix(1), Matrix()};
    double m = 0, cx = 0, cy = 0, cz = 0;
    bool infinite = false, locked = false;
    for (const Placed& x : parts) {
        if (!(x.n->mass < INFINITE_MASS)) infinite = true;
        if (isRotationLock(x.n->m_inverseInertia)) locked = true;
        m += x.n->mass;
        cx += double(x.n->mass) * x.p.x;
        cy += double(x.n->mass) * x.p.y;
        cz += double(x.n->mass) * x.p.z;
    }
    if (infinite || !(m > 0)) {
        out.mass = infinite ? INFINITE_MASS : float(m);
        out.centre = root->position;
        out.inertia = root->orientation.transpose() * root->m_inertia * root->orientation;
        out.inverseInertia = Matrix(0);
        return out;
    }
    out.mass = float(m);
    out.centre = Vector(float(cx / m), float(cy / m), float(cz / m));
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
    for (const Placed& x : parts) {
        gmath::Mat3 r = gmath::block3(x.r);
        inertia += (r.transpose() * gmath::block3(x.n->m_inertia) * r).cast<double>();
        Eigen::Vector3d d = gmath::map(x.p - out.centre).cast<double>();
        inertia += double(x.n->mass) * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
    }
    out.inertia = gmath::fromBlock3(inertia.cast<float>());
    // A part whose rotation is locked (zero inverse tensor) locks the whole composite's.
    out.inverseInertia = locked ? Matrix(0) : gmath::fromBlock3(inertia.inverse().cast<float>());
    return out;
}

// --- attachment chains ---

// World poses go from the root down the chain (p_world = p R_parent + P_parent, R_world = R R_parent), in
// one pass: O(depth). (Recursing for the position and the orientation separately was O(depth^2) per call.)
// The same products in the same order as that recursion, so the result is the same to the bit.
namespace {
template <class Visit> void downFromRoot(const RBDynamics* leaf, Visit visit) {
    thread_local std::vector<const RBDynamics*> path;
    size_t base = path.size(); // re-entrant: each call uses its own tail of the scratch
    for (const RBDynamics* n = leaf; n; n = n->attachedTo()) path.push_back(n);
    for (size_t i = path.size(); i-- > base;) visit(*path[i], i + 1 == path.size());
    path.resize(base);
}
} // namespace

Vector RBDynamics::getWorldPosition() const {
    if (!m_parent) return position;
    Vector p;
    Matrix r;
    downFromRoot(this, [&](const RBDynamics& n, bool root) {
        if (root) {
            p = n.position;
            r = n.orientation;
        } else {
            p = n.position * r + p;
            r = n.orientation * r;
        }
    });
    return p;
}

Matrix RBDynamics::getWorldOrientation() const {
    if (!m_parent) return orientation;
    Matrix r;
    downFromRoot(this, [&](const RBDynamics& n, bool root) { r = root ? n.orientation : n.orientation * r; });
    return r;
}

Vector RBDynamics::getWorldOrigin() const {
    return getWorldPosition() - getWorldOrientation().direction(com);
}

float RBDynamics::getMass() const { return attachmentRoot()->mass; }

float RBDynamics::getCompositeMass() const {
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

void RBDynamics::unlinkFromParent() {
    if (!m_parent) return;
    g_attachmentEpoch.fetch_add(1, std::memory_order_relaxed);
    RBDynamics** link = &m_parent->m_firstChild;
    while (*link && *link != this) link = &(*link)->m_nextSibling;
    if (*link) *link = m_nextSibling;
    m_parent = nullptr;
    m_nextSibling = nullptr;
}

void RBDynamics::attachTo(RBDynamics* p) {
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
        // Cleaned: the transpose is the inverse only of an exact rotation, and the float error of an
        // unclean one doubled with every level of a chain built by attaching (a 1,000-deep one overflowed).
        orientation = orthoNormalize(worldRot * parentRot.transpose());
        g_attachmentEpoch.fetch_add(1, std::memory_order_relaxed);
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
