// iCOBB.h - a body-oriented bounding box: three half extents ("radius"), turning with its body.
#pragma once

#include "iCollisionGeometry.h"

class iRigidBody;

class iCOBB : public iCollisionGeometry {
public:
    virtual Vector getRadius() const = 0; // half extents along the body's local x, y, z
    // Half extents that are not all finite and positive are refused with error().
    virtual void setRadius(const Vector& radius) = 0;

protected:
    ~iCOBB() = default;
};

extern "C" iCollisionGeometry* CreateCOBB(iRigidBody* rb = NULL, const Vector& radius = Vector(10, 10, 10));
