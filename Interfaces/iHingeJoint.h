// iHingeJoint.h - a hinge: the anchors stay together and B turns relative to A about one axis only (a door,
// a wheel, a chain link), within optional limits, driven by an optional motor.
#pragma once

#include "iJoint.h"

class iHingeJoint : public iJoint {
public:
    // The hinge angle stays in [lower, upper] radians (-pi < lower <= upper < pi); the limit holds against
    // the motor. setLimitsEnabled(false) (the default) lets it turn freely. Refused with error() otherwise.
    virtual bool setLimits(float lower, float upper) = 0;
    virtual void setLimitsEnabled(bool on) = 0;
    // The motor turns B relative to A at speed rad/s about the axis, with at most maxTorque N m (0: off, the
    // default). A negative or non-finite torque, or a non-finite speed, is refused.
    virtual bool setMotor(float speed, float maxTorque) = 0;
    virtual float getAngle() const = 0; // radians, B relative to A about the axis, 0 at creation
    virtual float getSpeed() const = 0; // rad/s

protected:
    ~iHingeJoint() override = default;
};

// a joined to b (nullptr: the world) at the world point anchor, turning about axis (world, normalised here).
// nullptr on bad input, with error().
extern "C" iHingeJoint* CreateHingeJoint(iRigidBody* a, iRigidBody* b, const Vector& anchor,
                                         const Vector& axis = Vector(0, 0, 1));
