// HingeJoint.cpp - B turns relative to A about the hinge axis only (iHingeJoint.h).
//
// Rows (JointRows.h): the anchors together (point block, C = pB - pA, acting at the lighter body's centre of
// mass: prepare); the axes aligned, two angular rows across A's axis (C_i = (aA x aB) . p_i, Cdot_i =
// (wB - wA) . p_i); the limits, one-sided rows on the angle theta (the twist of B's frame in A's, Cdot =
// (wB - wA) . aA); the motor, Cdot = speed with |lambda| <= maxTorque h. Solved motor and limits first, the
// point last (what matters most ends the sweep exact). This file prepares the rows; Joint::solve solves them.
#include "Joint.h"
#include "JointRowsInline.h"

#include "RigidBody.h"
#include "iHingeJoint.h"
#include "iUtilities.h"

#include <cmath>
#include <limits>

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
        const Vec3 misaligned = axis.cross(qB * Vec3::UnitX());
        for (int i = AcrossY; i <= AcrossZ; ++i) {
            const Vec3 across = qA * (i == AcrossY ? Vec3::UnitY() : Vec3::UnitZ());
            m_rows[i].setAngular(a, b, across);
            makeEqual(m_rows[i], misaligned.dot(across));
        }
        // The point acts at the lighter body's centre of mass, as the weld's and slider's do, with that
        // body's turn about the axis (the swing) in its rows: the turn across the axis is then the angular
        // rows' alone and no longer fought over (a 0.4 m box hinged 10 m out from a spinning 1 t box tilted
        // its axis 23 mrad and left its place by 0.23 m). Its target: the anchors' offset, less what the
        // axes' misalignment moves it by.
        const Vec3 pA = worldPoint(a, m_frameA), pB = worldPoint(b, m_frameB);
        const bool lightIsB = bIsLighter(a, b);
        m_pointShift = lightIsB ? Vec3(pB - b.com) : Vec3(pA - a.com);
        m_point.setSwingArms(a, b, lightIsB,
                             lightIsB ? Vec3(pA - a.com - m_pointShift) : Vec3(pB - b.com - m_pointShift),
                             axis.cross(m_pointShift), axis);
        m_pointError = pB - pA - misaligned.cross(m_pointShift);
        if (m_point.swingCondition > kFloatSwingLimit && !m_reportedFar) {
            m_reportedFar = true;
            error(L"iHingeJoint: a body this small this far from its hinge is beyond float precision "
                  L"(README, joints): its place may drift (reported once a joint)");
        }
    }

private:
    // PointBlock::swingCondition: about 10^7 in float
    static constexpr Real kFloatSwingLimit = Real(1.2) / std::numeric_limits<Real>::epsilon();
    bool m_limitsOn = false, m_reportedFar = false;
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
