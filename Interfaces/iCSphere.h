// iCSphere.h - a collision sphere: one radius, centred on its body frame's origin.
#pragma once

#include "iCollisionGeometry.h"

class iRigidBody;

class iCSphere : public iCollisionGeometry {
public:
    virtual float getRadius() const = 0;
    // A radius that is not finite and positive is refused with error().
    virtual void setRadius(float radius) = 0;

protected:
    ~iCSphere() = default;
};

extern "C" iCollisionGeometry* CreateCSphere(iRigidBody* rb = NULL, float radius = 10.0f);
