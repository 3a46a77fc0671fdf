// Composite.h - one integrable rigid body: an unattached body, or a whole attachment chain seen as one body
// (total mass, composite centre of mass, composite inertia by the parallel-axis theorem), plus the
// per-step force inputs of each of its parts and the motion state the integrators advance.
//
// Axes: everything "local" is in the root body's axes, about the composite centre of mass C. Column vectors
// (Eigen): a root rotation R maps local to world, R = M^T for the row-vector orientation M.
#pragma once

#include "FlatMap.h"
#include "MathBridge.h"
#include "RBDynamics.h"

#include <vector>

namespace physics {

class RigidBody;

struct CompositePart {
    RigidBody* body;  // the scene's body owning dyn (nullptr if none): its force generators are called
    RBDynamics* dyn;  // the part's own dynamics
    Vec3 offset;      // part centre of mass - C, root axes
    Mat3 relRot;      // part rotation relative to the root: R_part = R_root * relRot
    Vec3 constForce;  // force + temporalForce + mass * acceleration (world, through the part's COM)
    Vec3 constTorque; // torque + temporalTorque (world)
    Real dragK;       // 1/2 rho Cd A of the part's drag law
};

struct Composite {
    RBDynamics* root = nullptr;
    Real mass = 0, invMass = 0;
    Mat3 inertia = Mat3::Identity(), invInertia = Mat3::Identity(); // local, about C
    Vec3 rootOffset = Vec3::Zero();                                 // root's own COM - C, root axes
    Vec3 gravity = Vec3::Zero();                                    // zero unless the root is PHYS_Falling
    bool kinematic = false; // some part has INFINITE_MASS: forces do nothing, velocities are kept
    // Zero inverse inertia (a part's switch or a zero inverse tensor): the integrators skip the rotation.
    bool rotationLocked = false;
    bool drag = true; // the scene's drag switch
    bool hasGenerators = false;
    float angularDrag = 0; // the root's RBDynamics::angularDrag (1/s)
    std::vector<CompositePart> parts;
};

// The state an integrator advances: C's position and velocity, the root's rotation, L about C (world).
struct MotionState {
    Vec3 x, v, L;
    Quat q;
};

// Fills out (reusing its storage) for the chain rooted at rootBody's dynamics. bodies maps the dynamics of
// attached parts to the scene's bodies (looked up only for chains, not for a lone body). gravity is the
// scene's (zero when switched off), scaled by the root's gravity scale; lengthUnit: the world's length units
// per metre (the drag law's air density and reference area follow it); drag false leaves every part's drag
// out. A part whose body is rotation-locked (iRigidBodySwitches) gives the composite zero inertia tensors.
void buildComposite(RigidBody* rootBody, const FlatMap<const RBDynamics*, RigidBody*>& bodies,
                    const Vec3& gravity, float lengthUnit, bool drag, Composite& out);

// Whether some part of the chain rooted at root has INFINITE_MASS (forces cannot move it), without building
// it.
bool isKinematicChain(const RBDynamics& root);

// World inverse inertia R I^-1 R^T and angular velocity of a state.
inline Mat3 worldInverseInertia(const Composite& c, const Quat& q) {
    Mat3 r = q.toRotationMatrix();
    return r * c.invInertia * r.transpose();
}
inline Mat3 worldInertia(const Composite& c, const Quat& q) {
    Mat3 r = q.toRotationMatrix();
    return r * c.inertia * r.transpose();
}

} // namespace physics
