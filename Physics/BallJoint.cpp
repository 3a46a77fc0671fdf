// BallJoint.cpp - the anchors together, the bodies turning freely about them within an optional swing cone
// and twist range (iBallJoint.h).
//
// Rows (JointRows.h): the point block (C = pB - pA); the cone, a one-sided row on the swing angle theta
// between the twist axes tA and tB, gap = cone - theta, Cdot = -(wB - wA) . (tA x tB)/|tA x tB|; the twist
// limits, one-sided rows on B's twist about the axis in A's frame (swing-twist split), Cdot = (wB - wA) . t
// with t the mean of the two axes. The twist first; in the velocity passes the cone and the point as one
// block (solvePointAndCone), in the push out one after the other.
#include "Joint.h"
#include "JointRowsInline.h"

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
    enum Row { TwistLower, TwistUpper, Cone }; // solved in this order, the point last

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
        change(m_cone, std::min(Real(angle), kBallPi));
        return true;
    }
    float getConeLimit() const override { return float(m_cone); }
    bool setTwistLimits(float lower, float upper) override {
        if (!(lower >= -kBallPi && lower <= upper && upper <= kBallPi)) {
            error(L"iBallJoint::setTwistLimits: needs -pi <= lower <= upper <= pi; refused");
            return false;
        }
        change(m_twistLower, lower);
        change(m_twistUpper, upper);
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
        if (m_cone < kBallPi && length > Real(1e-6)) { // aligned axes are far from any cone
            m_rows[Cone].setAngular(a, b, -n / length);
            makeLimit(m_rows[Cone], m_cone - ballSwingAngle(qA, qB));
            prepareConeBlock(a, b);
        } else {
            m_rows[Cone].off();
        }
    }

    // The twist limits, then (velocity and relax passes) the cone and the point as one block; the push out
    // corrects them one after the other.
    void solve(SolverBody& a, SolverBody& b, Real h, JointPass pass, const JointSoftness& soft) override {
        if (pass == JointPass::PushOut || m_rows[Cone].kind == RowKind::Off) {
            Joint::solve(a, b, h, pass, soft);
            return;
        }
        for (int i : {TwistLower, TwistUpper})
            if (m_rows[i].kind == RowKind::Limit) m_rows[i].solveLimit(a, b, m_rows[i].error, h, false, soft);
        const Real gap = m_rows[Cone].error;
        solvePointAndCone(a, b, gap > 0 ? gap / h : 0);
    }

private:
    using Vec4r = Eigen::Matrix<Real, 4, 1>;
    using Mat4r = Eigen::Matrix<Real, 4, 4>;

    // The point's three rows and the cone's as one block (K is 4x4), the cone's impulse kept >= 0 (a
    // limit): one after the other, the point undid most of what the cone did wherever the body's own inertia
    // is small against m r^2 about the anchor (a 0.1 m ball on a 1 m arm knocked at 10 m/s swung to 0.77 rad
    // past a 0.5 rad cone: BallCone).
    void prepareConeBlock(const SolverBody& a, const SolverBody& b) {
        const Vec3 u = m_rows[Cone].armB;
        const Mat3 sA = cross(m_point.rA), sB = cross(m_point.rB);
        const Mat3 kp =
            (a.invMass + b.invMass) * Mat3::Identity() - sA * a.invInertia * sA - sB * b.invInertia * sB;
        m_coupling = -(sB * b.invInertia + sA * a.invInertia) * u; // the point's speed per cone impulse
        // K = [P c; c^T k] inverted through the Schur complement of P, s = k - c^T P^-1 c:
        //   K^-1 = [P^-1 + w w^T / s, -w / s; -w^T / s, 1 / s], w = P^-1 c.
        // (Eigen's 4x4 inverse by cofactors lost K to float rounding where a body is far from the joint
        // against its size: a 0.4 m box 50 m out took non-finite steps.)
        m_blockOk = kp.determinant() != 0;
        if (!m_blockOk) return;
        const Mat3 pInv = kp.inverse();
        const Vec3 w = pInv * m_coupling;
        const Real schur = u.dot((a.invInertia + b.invInertia) * u) - m_coupling.dot(w);
        m_blockOk = schur > 0 && std::isfinite(schur);
        if (!m_blockOk) return;
        m_blockMass.topLeftCorner<3, 3>() = pInv + w * w.transpose() / schur;
        m_blockMass.topRightCorner<3, 1>() = -w / schur;
        m_blockMass.bottomLeftCorner<1, 3>() = -w.transpose() / schur;
        m_blockMass(3, 3) = 1 / schur;
    }

    void solvePointAndCone(SolverBody& a, SolverBody& b, Real bias) {
        JointRow& cone = m_rows[Cone];
        const Vec3 pointSpeed = m_point.speed(a, b);
        // Element by element: the comma initializer's packet copy into a block of a Vec4 tripped g++ 12's
        // -Warray-bounds in optimised builds.
        const Vec4r speed(pointSpeed.x(), pointSpeed.y(), pointSpeed.z(), cone.speed(a, b) + bias);
        const Vec4r old(m_point.impulse.x(), m_point.impulse.y(), m_point.impulse.z(), cone.impulse);
        Vec4r now = old;
        if (m_blockOk) now = old - Vec4r(m_blockMass * speed);
        if (!m_blockOk || now(3) < 0) { // the cone does not push: its impulse goes, the point alone holds
            now(3) = 0;
            now.head<3>() = old.head<3>() - m_point.mass * (pointSpeed + m_coupling * (now(3) - old(3)));
        }
        m_point.apply(a, b, now.head<3>() - old.head<3>());
        cone.apply(a, b, now(3) - old(3));
        m_point.impulse = now.head<3>();
        cone.impulse = now(3);
    }

    Mat4r m_blockMass = Mat4r::Zero();
    Vec3 m_coupling = Vec3::Zero();
    bool m_blockOk = false;

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
