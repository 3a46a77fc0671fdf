// iCPlane.h - a one-sided infinite plane: static collision geometry such as a floor or a wall.
//
// Everything behind the plane (dot(normal, p) < offset) is solid, so a shape that ends up wholly behind it
// still collides: a plane cannot be tunnelled through. The normal points into free space. Contacts with a
// plane have the plane's normal. Without a body the plane is in world space and counts as fixed; with a
// body, normal and offset are in the body frame and the plane moves with it. Two planes never collide.
#pragma once

#include "iCollisionGeometry.h"

class iRigidBody;

class iCPlane : public iCollisionGeometry {
public:
    virtual Vector getNormal() const = 0; // unit, body frame (world frame when there is no body)
    virtual float getOffset() const = 0;
    // A normal that is zero or not finite, or an offset that is not finite, is refused with error().
    virtual void setPlane(const Vector& normal, float offset) = 0;

protected:
    ~iCPlane() = default;
};

// Returns nullptr (after error()) when the normal is zero or not finite or the offset not finite. The
// normal is normalised.
extern "C" iCollisionGeometry* CreateCPlane(iRigidBody* rb = NULL, const Vector& normal = Vector(0, 1, 0),
                                            float offset = 0.0f);
