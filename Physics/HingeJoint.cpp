// HingeJoint.cpp - B turns relative to A about the hinge axis only (iHingeJoint.h).
//
// Rows (JointRows.h): the anchors together (point block, C = pB - pA); the axes aligned, two angular rows
// across A's axis (C_i = (aA x aB) . p_i, Cdot_i = (wB - wA) . p_i); the limits, one-sided rows on the angle
// theta (the twist of B's frame in A's, Cdot = (wB - wA) . aA); the motor, Cdot = speed with |lambda| <=
// maxTorque h. Solved motor and limits first, the point last (what matters most ends the sweep exact).
// This file prepares the rows; Joint::solve solves them.
#include "Joint.h"

#include "RigidBody.h"
#include "iHingeJoint.h"
#include "iUtilities.h"

#include <cmath>

namespace physics {

namespace {

Vec3 hingeBodySpin(const RigidBody* body) {
    return body ? toEigen(body->getDynamics().attachmentRoot()->angularVelocity) : Vec3::Zero();
}

class HingeJoint final : public JointObject<iHingeJoint> {
    enum Row { Motor, Lower, Upper, AcrossY, AcrossZ }; // solved in this order, the point last

public:
    HingeJoint(RigidBody* a, RigidBody* b, const JointFrame& fa, const JointFrame& fb)
        : JointObject(JOINT_Hinge, a, b, fa, fb) {
        m_usesPoint = true;
        m_rowCount = 5;
    }

    bool setLimits(float lower, float upper) override {
        const float pi = 3.14159265f;
        if (!(lower > -pi && lower <= upper && upper < pi)) {
            error(L"iHingeJoint::setLimits: needs -pi < lower <= upper < pi; refused");
            return false;
        }
        change(m_lower, lower);
        change(m_upper, upper);
        change(m_limitsOn, true);
        return true;
    }
    void setLimitsEnabled(bool on) override { change(m_limitsOn, on); }
    bool setMotor(float speed, float maxTorque) override {
        if (!std::isfinite(speed) || !(maxTorque >= 0) || !std::isfinite(maxTorque)) {
            error(L"iHingeJoint::setMotor: needs a finite speed and a finite torque >= 0; refused");
            return false;
        }
        change(m_speed, speed);
        change(m_maxTorque, maxTorque);
        return true;
    }
    float getAngle() const override {
        JointFrame a, b;
        worldFrames(a, b);
        return float(twistAngle(a.basis, b.basis));
    }
    float getSpeed() const override {
        JointFrame a, b;
        worldFrames(a, b);
        return float((hingeBodySpin(bodyB()) - hingeBodySpin(bodyA())).dot(a.basis * Vec3::UnitX()));
    }

    void prepare(const SolverBody& a, const SolverBody& b, Real h) override {
        const Quat qA = worldBasis(a, m_frameA), qB = worldBasis(b, m_frameB);
        const Vec3 axis = qA * Vec3::UnitX();
        if (m_maxTorque > 0) {
            m_rows[Motor].setAngular(a, b, axis);
            makeMotor(m_rows[Motor], m_speed, m_maxTorque * h);
        } else {
            m_rows[Motor].off();
        }
        if (m_limitsOn) {
            const Real angle = twistAngle(qA, qB);
            m_rows[Lower].setAngular(a, b, axis);
            makeLimit(m_rows[Lower], angle - m_lower);
            m_rows[Upper].setAngular(a, b, -axis);
            makeLimit(m_rows[Upper], m_upper - angle);
        } else {
            m_rows[Lower].off();
            m_rows[Upper].off();
        }
        const Vec3 error = axis.cross(qB * Vec3::UnitX());
        for (int i = AcrossY; i <= AcrossZ; ++i) {
            const Vec3 across = qA * (i == AcrossY ? Vec3::UnitY() : Vec3::UnitZ());
            m_rows[i].setAngular(a, b, across);
            makeEqual(m_rows[i], error.dot(across));
        }
        preparePoint(a, b);
    }

private:
    bool m_limitsOn = false;
    Real m_lower = 0, m_upper = 0, m_speed = 0, m_maxTorque = 0;
};

} // namespace

} // namespace physics

extern "C" iHingeJoint* CreateHingeJoint(iRigidBody* a, iRigidBody* b, const Vector& anchor,
                                         const Vector& axis) {
    physics::RigidBody *ra, *rb;
    physics::JointFrame fa, fb;
    if (!physics::jointFrames(L"CreateHingeJoint", a, b, anchor, anchor, axis, ra, rb, fa, fb))
        return nullptr;
    return new physics::HingeJoint(ra, rb, fa, fb);
}
