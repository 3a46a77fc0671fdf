// iSpring.h - a damped spring between two anchors (seed 000's Spring: rest length, tightness, damping) that
// does not blow up when stiff.
//
// It is solved as a soft constraint (implicit in time: Catto, "Soft Constraints", GDC 2011), inside the
// solver's sub-steps: for any stiffness and step it stays bounded and never gains energy; where the step
// resolves it (omega h small) it oscillates at sqrt(k / m). Give it as stiffness and damping, or as a
// frequency and damping ratio (then the stiffness follows the bodies' masses: k = m w^2). An optional force
// limit (the post mortem's fix) caps what it pulls or pushes with.
#pragma once

#include "iJoint.h"

class iSpring : public iJoint {
public:
    virtual bool setRestLength(float length) = 0; // >= 0
    virtual float getRestLength() const = 0;
    // Tightness k (N per length unit) and damping c (N s per length unit), both >= 0 and finite.
    virtual bool setStiffness(float k) = 0;
    virtual bool setDamping(float c) = 0;
    virtual float getStiffness() const = 0; // what the last step used (k = m w^2 when set as a frequency)
    virtual float getDamping() const = 0;
    // As a frequency (Hz, > 0) and damping ratio (>= 0; 1: critical), whatever the masses.
    virtual bool setFrequency(float hertz, float dampingRatio) = 0;
    // At most this force, N (> 0; infinite, the default: no limit).
    virtual bool setMaxForce(float newtons) = 0;
    virtual float getLength() const = 0; // the anchors' distance now

protected:
    ~iSpring() override = default;
};

// A spring from the world point anchorA on a to anchorB on b (nullptr: the world), at rest at restLength, of
// stiffness k and damping c. nullptr on bad input, with error().
extern "C" iSpring* CreateSpring(iRigidBody* a, iRigidBody* b, const Vector& anchorA, const Vector& anchorB,
                                 float restLength, float stiffness, float damping = 0.0f);
