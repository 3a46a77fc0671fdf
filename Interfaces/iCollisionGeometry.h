// iCollisionGeometry.h - the interface to a collision shape carried by a rigid body.
//
// A geometry takes its pose and velocity from its body's getDynamics(): it is centred on the body frame's
// origin (getWorldOrigin(), i.e. the COM minus the com offset) and turns with getWorldOrientation().
// Detection itself uses poses only (a space remembers each geometry's previous pose for continuous
// sampling); velocities are for whoever resolves the contacts (getVelocityAtWorldPoint).
// On creation it joins the default collision space (setDefaultCollisionSpace; with none set, error() says it
// joins no space: add it with iCollisionSpace::add). Delete() leaves its space.
// A geometry is in at most one space: adding it to a second space moves it there. A geometry bound to a body
// that is destroyed (rigidBodyDestroyed) is unbound and stops colliding.
#pragma once

#include "MathDeclarations.h"

class iRigidBody;
class iCollisionSpace;

enum CollisionType : int {
    CT_SPHERE = 1,
    CT_OBB = 2,
    CT_PLANE = 3,    // iCPlane: one-sided, infinite, static
    CT_COMPOUND = 4, // iCCompound: several spheres and boxes on one body
};

class iCollisionGeometry {
public:
    virtual iCollisionGeometry* clone() const = 0;
    // Binds this geometry to a body (nullptr unbinds: an unbound geometry never collides). The body's
    // inertia follows its geometries (as one uniform solid) until the game sets a tensor: RBDynamics.h.
    virtual void attach(iRigidBody* rb) = 0;
    virtual iRigidBody* getRigidBody() = 0;
    virtual const iRigidBody* getRigidBody() const = 0;
    virtual int getCollisionType() const = 0;
    // Radius of a sphere about the geometry's centre that contains it (a plane: infinity).
    virtual float getBoundingRadius() const = 0;
    // The interval the geometry covers along a unit axis, at its current pose.
    virtual void getProjectionBounds(const Vector& axis, float& min, float& max) const = 0;
    // The space this geometry is in, or nullptr.
    virtual iCollisionSpace* getSpace() const = 0;
    // termination functions
    virtual void suspend() const = 0;
    virtual void release() const = 0;
    virtual void Delete() const = 0;

protected:
    // Not deleted through the interface: call Delete().
    ~iCollisionGeometry() = default;
};
