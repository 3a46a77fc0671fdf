// iDistanceJoint.h - keeps two anchors between a minimum and a maximum distance: a rod when they are equal
// (the default, the distance at creation), a rope segment or a chain link with minimum 0 (it goes slack but
// does not stretch). A rope is a chain of these (iRope).
#pragma once

#include "iJoint.h"

class iDistanceJoint : public iJoint {
public:
    // 0 <= minLength <= maxLength, finite; refused with error() and false otherwise.
    virtual bool setLimits(float minLength, float maxLength) = 0;
    virtual float getMinLength() const = 0;
    virtual float getMaxLength() const = 0;
    virtual float getLength() const = 0; // the anchors' distance now

protected:
    ~iDistanceJoint() override = default;
};

// The world points anchorA on a and anchorB on b (nullptr: the world) kept at their distance now.
// nullptr on bad input, with error().
extern "C" iDistanceJoint* CreateDistanceJoint(iRigidBody* a, iRigidBody* b, const Vector& anchorA,
                                               const Vector& anchorB);
