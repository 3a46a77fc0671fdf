// iSliderJoint.h - a slider (prismatic joint): B keeps its orientation relative to A and moves relative to
// it along one axis only (a piston, a lift, a drawer), within optional limits, driven by an optional motor.
#pragma once

#include "iJoint.h"

class iSliderJoint : public iJoint {
public:
    // The travel along the axis stays in [lower, upper] (length units; lower <= upper); off by default.
    virtual bool setLimits(float lower, float upper) = 0;
    virtual void setLimitsEnabled(bool on) = 0;
    // The motor moves B along the axis at speed (units/s) with at most maxForce N (0: off, the default).
    virtual bool setMotor(float speed, float maxForce) = 0;
    virtual float getPosition() const = 0; // travel along the axis since creation
    virtual float getSpeed() const = 0;

protected:
    ~iSliderJoint() override = default;
};

// a joined to b (nullptr: the world) at the world point anchor, sliding along axis (world, normalised here).
// nullptr on bad input, with error().
extern "C" iSliderJoint* CreateSliderJoint(iRigidBody* a, iRigidBody* b, const Vector& anchor,
                                           const Vector& axis = Vector(1, 0, 0));
