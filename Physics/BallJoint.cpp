// BallJoint.cpp - the anchors together, the bodies turning freely about them within an optional swing cone
// and twist range (iBallJoint.h).
//
// Rows (JointRows.h): the point block (C = pB - pA); the cone, a one-sided row on the swing angle theta
// between the twist axes tA and tB, gap = cone - theta, Cdot = -(wB - wA) . (tA x tB)/|tA x tB|; the twist
// limits, one-sided rows on B's twist about the axis in A's frame (swing-twist split), Cdot = (wB - wA) . t
// with t the mean of the two axes. The twist first; in the velocity passes the cone and the point as one
// block (solvePointAndCone), in the push out one after the other.
#include "Joint.h"

#include "iBallJoint.h"
#include "iUtilities.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

    void solve(SolverBody& a, SolverBody& b, Real h, JointPass pass, const JointSoftness& soft) override {
        const bool push = pass == JointPass::PushOut;
        const Quat qA = worldBasis(a, m_frameA), qB = worldBasis(b, m_frameB);
        const Vec3 tA = qA * Vec3::UnitX(), tB = qB * Vec3::UnitX();
        if (m_twistLower > -kBallPi || m_twistUpper < kBallPi) {
            const Real twist = twistAngle(qA, qB);
            const Vec3 t = (tA + tB).normalized();
            m_rows[TwistLower].setAngular(a, b, t);
            m_rows[TwistLower].solveLimit(a, b, twist - m_twistLower, h, push, soft);
            m_rows[TwistUpper].setAngular(a, b, -t);
            m_rows[TwistUpper].solveLimit(a, b, m_twistUpper - twist, h, push, soft);
        } else {
            m_rows[TwistLower].impulse = m_rows[TwistUpper].impulse = 0;
        }
        const Vec3 pA = worldPoint(a, m_frameA), pB = worldPoint(b, m_frameB);
        m_point.setArms(a, b, pA - a.com, pB - b.com);
        bool coneActive = false;
        if (m_cone < kBallPi) {
            const Vec3 n = tA.cross(tB);
            const Real length = n.norm();
            if (length > Real(1e-6)) {
                m_rows[Cone].setAngular(a, b, -n / length);
                coneActive = true;
            }
        }
        if (!coneActive) m_rows[Cone].impulse = 0; // no cone, or the axes aligned: far from any cone
        const Real gap = coneActive ? m_cone - ballSwingAngle(qA, qB) : 0;
        if (push) {
            if (coneActive) m_rows[Cone].solveLimit(a, b, gap, h, true, soft);
            m_point.solve(a, b, soft.biasRate * (pB - pA), soft);
        } else if (coneActive) {
            solvePointAndCone(a, b, gap > 0 ? gap / h : 0);
        } else {
            m_point.solve(a, b, Vec3::Zero());
        }
    }

private:
    // The point's three rows and the cone's as one block (K is 4x4), the cone's impulse kept >= 0 (a limit):
    // one after the other, the point undid most of what the cone did wherever the body's own inertia is
    // small against m r^2 about the anchor (a 0.1 m ball on a 1 m arm knocked at 10 m/s swung to 0.77 rad
    // past a 0.5 rad cone: BallCone). Velocity passes only (the push out corrects the swing on its own).
    void solvePointAndCone(SolverBody& a, SolverBody& b, Real bias) {
        using Vec4r = Eigen::Matrix<Real, 4, 1>;
        using Mat4r = Eigen::Matrix<Real, 4, 4>;
        JointRow& cone = m_rows[Cone];
        cone.lower = 0;
        cone.upper = std::numeric_limits<Real>::infinity();
        const Vec3 u = cone.armB;
        const Mat3 sA = cross(m_point.rA), sB = cross(m_point.rB);
        const Mat3 kp =
            (a.invMass + b.invMass) * Mat3::Identity() - sA * a.invInertia * sA - sB * b.invInertia * sB;
        const Vec3 c = -(sB * b.invInertia + sA * a.invInertia) * u; // the point's speed per cone impulse
        Mat4r k;
        k.topLeftCorner<3, 3>() = kp;
        k.topRightCorner<3, 1>() = c;
        k.bottomLeftCorner<1, 3>() = c.transpose();
        k(3, 3) = u.dot((a.invInertia + b.invInertia) * u);
        const Vec3 pointSpeed = m_point.speed(a, b);
        Vec4r speed;
        speed << pointSpeed, cone.speed(a, b) + bias;
        Vec4r old;
        old << m_point.impulse, cone.impulse;
        Vec4r now = old;
        if (k.determinant() != 0) now = old - Vec4r(k.inverse() * speed);
        if (!(k.determinant() != 0) || now(3) < 0) {
            // the cone does not push: its impulse goes and the point alone holds
            now(3) = 0;
            now.head<3>() = old.head<3>() - m_point.mass * (pointSpeed + c * (now(3) - old(3)));
        }
        m_point.apply(a, b, now.head<3>() - old.head<3>());
        cone.apply(a, b, now(3) - old(3));
        m_point.impulse = now.head<3>();
        cone.impulse = now(3);
    }

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
