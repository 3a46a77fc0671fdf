// SliderJoint.cpp - B keeps its orientation relative to A and moves along A's axis only (iSliderJoint.h).
//
// Rows (JointRows.h), with d = pB - pA and the axis x and the across directions p_i of A's frame: the
// orientation block (C = the rotation from A's frame to B's); two linear rows across the axis, C_i = d . p_i
// with A's arm reaching B's anchor (rA + d); the limits, one-sided rows on the travel d . x; the motor,
// Cdot = speed along x with |lambda| <= maxForce h. The linear rows act at the lighter body's centre of mass
// (prepare), which with the orientation held is the same constraint.
#include "Joint.h"
#include "JointRowsInline.h"

#include "RigidBody.h"
#include "iSliderJoint.h"
#include "iUtilities.h"

#include <cmath>

namespace physics {

namespace {

Vec3 sliderPointVelocity(const RigidBody* body, const Vec3& point) {
    if (!body) return Vec3::Zero();
    const RBDynamics& root = *body->getDynamics().attachmentRoot();
    return toEigen(root.velocity) + toEigen(root.angularVelocity).cross(point - toEigen(root.position));
}

class SliderJoint final : public JointObject<iSliderJoint> {
    enum Row { Motor, Lower, Upper, AcrossY, AcrossZ }; // solved in this order, then the orientation

public:
    SliderJoint(RigidBody* a, RigidBody* b, const JointFrame& fa, const JointFrame& fb)
        : JointObject(JOINT_Slider, a, b, fa, fb) {
        m_usesOrientation = true;
        m_rowCount = 5;
    }

    bool setLimits(float lower, float upper) override {
        if (!(lower <= upper) || !std::isfinite(lower) || !std::isfinite(upper)) {
            error(L"iSliderJoint::setLimits: needs finite lower <= upper; refused");
            return false;
        }
        change(m_lower, lower);
        change(m_upper, upper);
        change(m_limitsOn, true);
        return true;
    }
    void setLimitsEnabled(bool on) override { change(m_limitsOn, on); }
    bool setMotor(float speed, float maxForce) override {
        if (!std::isfinite(speed) || !(maxForce >= 0) || !std::isfinite(maxForce)) {
            error(L"iSliderJoint::setMotor: needs a finite speed and a finite force >= 0; refused");
            return false;
        }
        change(m_speed, speed);
        change(m_maxForce, maxForce);
        return true;
    }
    float getPosition() const override {
        JointFrame a, b;
        worldFrames(a, b);
        return float((b.point - a.point).dot(a.basis * Vec3::UnitX()));
    }
    float getSpeed() const override {
        JointFrame a, b;
        worldFrames(a, b);
        const Vec3 v = sliderPointVelocity(bodyB(), b.point) - sliderPointVelocity(bodyA(), b.point);
        return float(v.dot(a.basis * Vec3::UnitX()));
    }

    void prepare(const SolverBody& a, const SolverBody& b, Real h) override {
        const Quat qA = worldBasis(a, m_frameA);
        const Vec3 axis = qA * Vec3::UnitX();
        const Vec3 pA = worldPoint(a, m_frameA), pB = worldPoint(b, m_frameB);
        const Quat qB = worldBasis(b, m_frameB);
        // The linear rows act at the lighter body's centre of mass, as the weld's do (FixedJoint.cpp): with
        // the orientation held, the same constraint, but that body's linear rows no longer turn it against
        // its orientation rows (a 0.4 m box on a 10 m slider from a spinning 1 t box strayed 0.4 m off the
        // axis). d is B's anchor from A's, moved with the point.
        Vec3 rA = pB - a.com, rB = pB - b.com;
        m_pointShift = bIsLighter(a, b) ? rB : rA;
        rA -= m_pointShift;
        rB -= m_pointShift;
        const Vec3 d = pB - pA + (qA * qB.conjugate()) * m_pointShift - m_pointShift;
        if (m_maxForce > 0) {
            m_rows[Motor].setLinear(a, b, axis, rA, rB);
            makeMotor(m_rows[Motor], m_speed, m_maxForce * h);
        } else {
            m_rows[Motor].off();
        }
        if (m_limitsOn) {
            const Real travel = d.dot(axis);
            m_rows[Lower].setLinear(a, b, axis, rA, rB);
            makeLimit(m_rows[Lower], travel - m_lower);
            m_rows[Upper].setLinear(a, b, -axis, rA, rB);
            makeLimit(m_rows[Upper], m_upper - travel);
        } else {
            m_rows[Lower].off();
            m_rows[Upper].off();
        }
        for (int i = AcrossY; i <= AcrossZ; ++i) {
            const Vec3 across = qA * (i == AcrossY ? Vec3::UnitY() : Vec3::UnitZ());
            m_rows[i].setLinear(a, b, across, rA, rB);
            makeEqual(m_rows[i], d.dot(across));
        }
        m_orientation.setMass(a, b);
        m_rotationError = rotationError(qA, qB);
    }

private:
    bool m_limitsOn = false;
    Real m_lower = 0, m_upper = 0, m_speed = 0, m_maxForce = 0;
};

} // namespace

} // namespace physics

extern "C" iSliderJoint* CreateSliderJoint(iRigidBody* a, iRigidBody* b, const Vector& anchor,
                                           const Vector& axis) {
    physics::RigidBody *ra, *rb;
    physics::JointFrame fa, fb;
    if (!physics::jointFrames(L"CreateSliderJoint", a, b, anchor, anchor, axis, ra, rb, fa, fb))
        return nullptr;
    return new physics::SliderJoint(ra, rb, fa, fb);
}
