// Composite.cpp - mass properties of an attachment chain, gathered once per step before integrating it.
#include "Composite.h"

#include "MathEigen.h"
#include "RigidBody.h"

#include <cmath>

namespace physics {

namespace {
// Air density of the drag law (RBDynamics.h), 1.2 kg/m^3: in a world of L length units per metre it is
// 1.2 / L^3 kg/unit^3, so that a body falls through the air alike at every scale.
constexpr float AIR_DENSITY = 1.2f;

// The drag law's reference area: the cross-section pi r^2 of the sphere with the body's volume (the solid of
// its collision geometry; a body with none is the sphere of radius 1 its inertia assumes), so that drag
// follows the body's size and dragCoefficient is a true Cd (the seed: 0.25-0.45 a car).
float dragArea(const RBDynamics& d) {
    const float volume = d.getShapeMass().volume;
    const float r = volume > 0.0f ? std::cbrt(volume * (3.0f / (4.0f * 3.14159265f))) : 1.0f;
    return 3.14159265f * r * r;
}

// d's forces and drag as a part of out at offset from its centre of mass, turned by rotation from the root;
// locked becomes true when body's rotation is locked.
void addPart(Composite& out, RigidBody* body, RBDynamics& d, const Vec3& offset, const Mat3& rotation,
             float lengthUnit, bool& locked) {
    if (body && !body->generators().empty()) out.hasGenerators = true;
    locked = locked || (body && body->isRotationLocked());
    // Written in place: a part put together on the stack and copied was read back before its fields'
    // stores had left (a stall on every body, every step).
    CompositePart& part = out.parts.emplace_back();
    part.body = body;
    part.dyn = &d;
    part.offset = offset;
    part.relRot = rotation;
    part.constForce = toEigen(d.force + d.temporalForce);
    if (d.mass < INFINITE_MASS) part.constForce += d.mass * toEigen(d.acceleration);
    part.constTorque = toEigen(d.torque + d.temporalTorque);
    part.dragK =
        out.drag && d.dragCoefficient > 0.0f
            ? 0.5f * AIR_DENSITY / (lengthUnit * lengthUnit * lengthUnit) * dragArea(d) * d.dragCoefficient
            : 0.0f;
}

struct Placed {
    RBDynamics* dyn;
    Vec3 position; // part COM relative to the root COM, root axes
    Mat3 rotation; // relative to the root
};
} // namespace

bool isKinematicChain(const RBDynamics& root) {
    if (!(root.mass < INFINITE_MASS)) return true;
    for (const RBDynamics* c = root.firstAttached(); c; c = c->nextAttached())
        if (isKinematicChain(*c)) return true;
    return false;
}

void buildComposite(RigidBody* rootBody, const FlatMap<const RBDynamics*, RigidBody*>& bodies,
                    const Vec3& gravity, float lengthUnit, bool drag, Composite& out) {
    RBDynamics* root = &rootBody->getDynamics();
    out.root = root;
    out.parts.clear();
    out.kinematic = false;
    out.hasGenerators = false;
    out.drag = drag;
    out.gravity =
        root->physicsType == PHYS_Falling ? Vec3(gravity * rootBody->getGravityScale()) : Vec3::Zero();
    out.angularDrag = root->angularDrag;

    if (!root->firstAttached()) { // an unattached body: itself, its own tensors (what follows gives the same)
        out.kinematic = !(root->mass < INFINITE_MASS);
        out.mass = out.kinematic ? INFINITE_MASS : root->mass;
        out.invMass = out.kinematic ? Real(0) : Real(1.0 / double(root->mass));
        out.rootOffset = -Vec3::Zero();
        out.inertia = tensor(root->getInertiaTensor());
        out.invInertia = tensor(root->getInverseInertiaTensor());
        bool locked = false;
        addPart(out, rootBody, *root, Vec3::Zero(), Mat3::Identity(), lengthUnit, locked);
        if (locked) out.inertia = out.invInertia = Mat3::Zero();
        out.rotationLocked = out.invInertia.isZero(0.0f);
        return;
    }

    // Place every part relative to the root: a child stores its pose relative to its parent's COM and
    // orientation, p_world = R_parent p + P_parent (column form), so the same recursion holds in root axes.
    thread_local std::vector<Placed> stack, placed;
    stack.clear();
    placed.clear();
    stack.push_back({root, Vec3::Zero(), Mat3::Identity()});
    while (!stack.empty()) {
        Placed p = stack.back();
        stack.pop_back();
        placed.push_back(p);
        for (RBDynamics* c = p.dyn->firstAttached(); c; c = c->nextAttached())
            stack.push_back(
                {c, p.rotation * toEigen(c->position) + p.position, p.rotation * toRotation(c->orientation)});
    }

    double mass = 0;
    Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
    for (const Placed& p : placed) {
        if (!(p.dyn->mass < INFINITE_MASS)) out.kinematic = true;
        mass += p.dyn->mass;
        weighted += double(p.dyn->mass) * p.position.cast<double>();
    }
    Vec3 centre = out.kinematic ? Vec3::Zero() : Vec3((weighted / mass).cast<Real>());
    out.mass = out.kinematic ? INFINITE_MASS : Real(mass);
    out.invMass = out.kinematic ? Real(0) : Real(1.0 / mass);
    out.rootOffset = -centre;

    if (placed.size() == 1) { // an unattached body: its own tensors, no parallel-axis sum
        out.inertia = tensor(root->getInertiaTensor());
        out.invInertia = tensor(root->getInverseInertiaTensor());
    } else {
        Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
        for (const Placed& p : placed) {
            Mat3 own = p.rotation * tensor(p.dyn->getInertiaTensor()) * p.rotation.transpose();
            Eigen::Vector3d d = (p.position - centre).cast<double>();
            inertia += own.cast<double>();
            if (!out.kinematic)
                inertia +=
                    double(p.dyn->mass) * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
        }
        out.inertia = inertia.cast<Real>();
        bool locked = false; // a part with a zero inverse tensor locks the composite's rotation
        for (const Placed& p : placed) locked = locked || isRotationLock(p.dyn->getInverseInertiaTensor());
        out.invInertia = locked ? Mat3(Mat3::Zero()) : Mat3(inertia.inverse().cast<Real>());
    }

    bool locked = false; // rotation locked by a part's switch
    for (const Placed& p : placed) {
        RigidBody* body = rootBody;
        if (p.dyn != root) {
            RigidBody* const* found = bodies.find(p.dyn);
            body = found ? *found : nullptr;
        }
        addPart(out, body, *p.dyn, p.position - centre, p.rotation, lengthUnit, locked);
    }
    if (locked) out.inertia = out.invInertia = Mat3::Zero(); // as a zero inverse tensor: never turns
    out.rotationLocked = out.invInertia.isZero(0.0f);
}

} // namespace physics
