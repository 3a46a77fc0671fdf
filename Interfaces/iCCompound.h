// iCCompound.h - compound collision geometry: several spheres and boxes carried by one body.
//
// Each child sits at an offset from the body frame's origin and (boxes) turns by a local rotation on top of
// the body's orientation. Contacts name the compound itself as g1 or g2; getContactFeatureIds() tells the
// children apart. A compound with no children never collides. For its body's inertia the children are one
// solid of uniform density (each child's mass share is its volume share; overlaps count twice), about
// their common centroid.
#pragma once

#include <cstddef>

#include "iCollisionGeometry.h"

class iRigidBody;

class iCCompound : public iCollisionGeometry {
public:
    // A radius that is not finite and positive, or a non-finite offset, is refused with error() (false).
    virtual bool addSphere(const Vector& offset, float radius) = 0;
    // rotation: row-vector rotation (child local -> body local); must be a proper rotation. Half extents
    // must be finite and positive. Refused with error() (false) otherwise.
    virtual bool addBox(const Vector& offset, const Matrix& rotation, const Vector& halfExtents) = 0;
    virtual size_t getNumChildren() const = 0;
    virtual void clearChildren() = 0;

protected:
    ~iCCompound() = default;
};

extern "C" iCollisionGeometry* CreateCCompound(iRigidBody* rb = NULL);
