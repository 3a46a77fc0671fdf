// iBallJoint.h - a ball and socket: the anchors stay together and the bodies turn freely about them, within
// an optional swing cone and twist range (a shoulder, a ragdoll's hip).
//
// The twist axis is given in world axes at creation and kept in each body's frame. Swing is the angle
// between A's and B's twist axes; twist is B's turn about the twist axis relative to A, zero at creation.
#pragma once

#include "iJoint.h"

class iBallJoint : public iJoint {
public:
    // Swing at most angle radians (0 < angle <= pi); pi or more: no cone. Refused (error(), false) otherwise.
    virtual bool setConeLimit(float angle) = 0;
    virtual float getConeLimit() const = 0;
    // Twist within [lower, upper] radians (-pi <= lower <= upper <= pi); (-pi, pi): no limit.
    virtual bool setTwistLimits(float lower, float upper) = 0;
    virtual float getSwingAngle() const = 0; // now, radians
    virtual float getTwistAngle() const = 0;

protected:
    ~iBallJoint() override = default;
};

// a joined to b (nullptr: the world) at the world point anchor; twistAxis (world, normalised here) is the
// axis the cone and the twist are measured about. nullptr on bad input, with error().
extern "C" iBallJoint* CreateBallJoint(iRigidBody* a, iRigidBody* b, const Vector& anchor,
                                       const Vector& twistAxis = Vector(0, -1, 0));
