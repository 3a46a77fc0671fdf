// BallJoint.cpp - the anchors together, the bodies turning freely about them within an optional swing cone
// and twist range (iBallJoint.h).
//
// Rows (JointRows.h): the point block (C = pB - pA); the cone, a one-sided row on the swing angle theta
// between the twist axes tA and tB, gap = cone - theta, Cdot = -(wB - wA) . (tA x tB)/|tA x tB|; the twist
// limits, one-sided rows on B's twist about the axis in A's frame (swing-twist split), Cdot = (wB - wA) . t
// with t the mean of the two axes.
#include "Joint.h"

#include "iBallJoint.h"
#include "iUtilities.h"

#include <algorithm>
#include <cmath>

namespace physics {

namespace {

constexpr Real kBallPi = Real(3.14159265358979);

Real ballSwingAngle(const Quat& qA, const Quat& qB) {
    const Real c = (qA * Vec3::UnitX()).dot(qB * Vec3::UnitX());
    return std::acos(std::clamp(c, Real(-1), Real(1)));
}

class BallJoint final : public JointObject<iBallJoint> {
    enum Row { Cone, TwistLower, TwistUpper };

public:
    BallJoint(RigidBody* a, RigidBody* b, const JointFrame& fa, const JointFrame& fb)
        : JointObject(JOINT_Ball, a, b, fa, fb) {
        m_usesPoint = true;
        m_rowCount = 3;
    }

    bool setConeLimit(float angle) override {
        if (!(angle > 0) || std::isnan(angle)) {
            error(L"iBallJoint::setConeLimit: the angle must be positive (pi or more: no cone); refused");
            return false;
        }
        m_cone = std::min(Real(angle), kBallPi);
        return true;
    }
    float getConeLimit() const override { return float(m_cone); }
    bool setTwistLimits(float lower, float upper) override {
        if (!(lower >= -kBallPi && lower <= upper && upper <= kBallPi)) {
            error(L"iBallJoint::setTwistLimits: needs -pi <= lower <= upper <= pi; refused");
            return false;
        }
        m_twistLower = lower;
        m_twistUpper = upper;
        return true;
    }
    float getSwingAngle() const override {
        JointFrame a, b;
        worldFrames(a, b);
        return float(ballSwingAngle(a.basis, b.basis));
    }
    float getTwistAngle() const override {
        JointFrame a, b;
        worldFrames(a, b);
        return float(twistAngle(a.basis, b.basis));
    }

    void prepare(const SolverBody& a, const SolverBody& b, Real) override {
        const Quat qA = worldBasis(a, m_frameA), qB = worldBasis(b, m_frameB);
        const Vec3 tA = qA * Vec3::UnitX(), tB = qB * Vec3::UnitX();
        const Vec3 n = tA.cross(tB);
        const Real length = n.norm();
        if (m_cone < kBallPi && length > Real(1e-6)) { // aligned axes are far from any cone
            m_rows[Cone].setAngular(a, b, -n / length);
            makeLimit(m_rows[Cone], m_cone - ballSwingAngle(qA, qB));
        } else {
            m_rows[Cone].off();
        }
        if (m_twistLower > -kBallPi || m_twistUpper < kBallPi) {
            const Real twist = twistAngle(qA, qB);
            const Vec3 t = (tA + tB).normalized();
            m_rows[TwistLower].setAngular(a, b, t);
            makeLimit(m_rows[TwistLower], twist - m_twistLower);
            m_rows[TwistUpper].setAngular(a, b, -t);
            makeLimit(m_rows[TwistUpper], m_twistUpper - twist);
        } else {
            m_rows[TwistLower].off();
            m_rows[TwistUpper].off();
        }
        preparePoint(a, b);
    }

private:
    Real m_cone = kBallPi, m_twistLower = -kBallPi, m_twistUpper = kBallPi;
};

} // namespace

} // namespace physics

extern "C" iBallJoint* CreateBallJoint(iRigidBody* a, iRigidBody* b, const Vector& anchor,
                                       const Vector& twistAxis) {
    physics::RigidBody *ra, *rb;
    physics::JointFrame fa, fb;
    if (!physics::jointFrames(L"CreateBallJoint", a, b, anchor, anchor, twistAxis, ra, rb, fa, fb))
        return nullptr;
    return new physics::BallJoint(ra, rb, fa, fb);
}
