// iCollisionGeometry.h - the interface to a collision shape carried by a rigid body.
//
// A geometry takes its pose and velocity from its body's getDynamics(): it is centred on the body frame's
// origin (getWorldOrigin(), i.e. the COM minus the com offset) and turns with getWorldOrientation().
// On creation it joins the default collision space (setDefaultCollisionSpace); Delete() leaves its space.
#pragma once

#include "MathDeclarations.h"

class iRigidBody;
class iCollisionSpace;

enum CollisionType {
    CT_SPHERE = 1,
    CT_OBB = 2,
};

class iCollisionGeometry {
public:
    virtual iCollisionGeometry* clone() const = 0;
    // Binds this geometry to a body (nullptr unbinds: an unbound geometry never collides).
    virtual void attach(iRigidBody* rb) = 0;
    virtual iRigidBody* getRigidBody() = 0;
    virtual const iRigidBody* getRigidBody() const = 0;
    virtual int getCollisionType() const = 0;
    // Radius of a sphere about the geometry's centre that contains it.
    virtual float getBoundingRadius() const = 0;
    // The interval the geometry covers along a unit axis, at its current pose.
    virtual void getProjectionBounds(const Vector& axis, float& min, float& max) const = 0;
    // The space this geometry is in, or nullptr.
    virtual iCollisionSpace* getSpace() const = 0;
    // termination functions
    virtual void suspend() const = 0;
    virtual void release() const = 0;
    virtual void Delete() const = 0;
};
