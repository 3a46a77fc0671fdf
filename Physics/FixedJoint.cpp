// FixedJoint.cpp - a weld: B keeps its pose relative to A (iFixedJoint.h).
//
// Rows (JointRows.h): the orientation block (C = the rotation vector from A's frame to B's, Cdot = wB - wA)
// and the point block, solved together as one 6x6 block. The point block holds the lighter body's centre of
// mass where B's frame, put on A's, carries it (prepare): at the anchors (C = pB - pA) it is the same
// constraint, but not in float when an arm is long against its body's size.
#include "Joint.h"
#include "JointRowsInline.h"

#include "iFixedJoint.h"

namespace physics {

namespace {

class FixedJoint final : public JointObject<iFixedJoint> {
public:
    FixedJoint(RigidBody* a, RigidBody* b, const JointFrame& fa, const JointFrame& fb)
        : JointObject(JOINT_Fixed, a, b, fa, fb) {
        m_usesPoint = m_usesOrientation = true;
    }

    void prepare(const SolverBody& a, const SolverBody& b, Real) override {
        const Vec3 pA = worldPoint(a, m_frameA), pB = worldPoint(b, m_frameB);
        const Quat basisA = worldBasis(a, m_frameA), basisB = worldBasis(b, m_frameB);
        m_rotationError = rotationError(basisA, basisB);
        // The point rows act at the lighter body's centre of mass, not at the anchor: the same constraint
        // (with the orientation rows), but that body's rows no longer turn it. At the anchor, a small body
        // welded far from it took two torques of about L times the force that all but cancelled: a 4 cm box
        // welded 100 m from a heavy one flew apart. The target of that point: where B's frame, put back on
        // A's, would carry it (the anchors' offset plus the point's turn by the rotation error).
        // (The point block's own 3x3 mass is not used: the weld solves its six rows as one block.)
        m_pointShift = bIsLighter(a, b) ? Vec3(pB - b.com) : Vec3(pA - a.com);
        m_point.rA = pA - a.com - m_pointShift;
        m_point.rB = pB - b.com - m_pointShift;
        m_pointError = Vec3(pB - pA) + Vec3((basisA * basisB.conjugate()) * m_pointShift - m_pointShift);
        // K = [P C; C^T R]: the point block, the coupling and the orientation block.
        const Mat3 sA = cross(m_point.rA), sB = cross(m_point.rB);
        const Mat3 c = -(sA * a.invInertia + sB * b.invInertia);
        const Mat3 r = a.invInertia + b.invInertia;
        m_movable = invertBlocks(a, b, m_point.rA - m_point.rB, c, r, m_mass); // else both immovable
    }

    // The six rows as one block (K is 6x6): one block after the other, the point and the orientation fought
    // wherever the anchor is far from the centre of mass against the body's size (a 2 kg box welded 1 m to
    // the side sagged 1.1 cm and its reaction read 0.96 m g: FixedCantilever).
    void solve(SolverBody& a, SolverBody& b, Real, JointPass pass, const JointSoftness& soft) override {
        if (!m_movable) return;
        const bool push = pass == JointPass::PushOut;
        Vec6 speed, impulse; // filled by halves (a comma initializer trips g++ 12's -Warray-bounds at -O3)
        speed.head<3>() = m_point.speed(a, b);
        speed.tail<3>() = b.w - a.w;
        if (push) {
            speed.head<3>() += soft.biasRate * m_pointError;
            speed.tail<3>() += soft.biasRate * m_rotationError;
        }
        impulse.head<3>() = m_point.impulse;
        impulse.tail<3>() = m_orientation.impulse;
        const Real massScale = push ? soft.massScale : 1, impulseScale = push ? soft.impulseScale : 0;
        const Vec6 change = -massScale * Vec6(m_mass * speed) - impulseScale * impulse;
        m_point.apply(a, b, change.head<3>());
        m_orientation.apply(a, b, change.tail<3>());
        m_point.impulse += change.head<3>();
        m_orientation.impulse += change.tail<3>();
    }

private:
    using Vec6 = Eigen::Matrix<Real, 6, 1>;
    using Mat6 = Eigen::Matrix<Real, 6, 6>;

    // The inverse of the symmetric K = [P C; C^T R] through the Schur complement of R, S = P - C R^-1 C^T:
    //   K^-1 = [S^-1, -S^-1 C R^-1; -R^-1 C^T S^-1, R^-1 + R^-1 C^T S^-1 C R^-1].
    // K is singular exactly when R or S is (det K = det R det S); R = IA^-1 + IB^-1 is singular when neither
    // body can turn about some axis, and then neither can the weld's orientation rows. False when singular.
    // (Two closed-form 3x3 inverses: Eigen's 6x6 LU was a tenth of a drop-in package's compile time.)
    static bool invertBlocks(const SolverBody& a, const SolverBody& b, const Vec3& arm, const Mat3& c,
                             const Mat3& r, Mat6& out) {
        if (r.determinant() == 0) return false;
        const Mat3 rInv = r.inverse();
        const Mat3 cr = c * rInv; // C R^-1 (and its transpose R^-1 C^T: R is symmetric)
        // S = P - C R^-1 C^T is formed directly, not by the subtraction: with IA^-1 = a, IB^-1 = b it is
        // (1/mA + 1/mB) 1 + [d]x Q [d]x^T, Q = a (a + b)^-1 b = (IA + IB)^-1, d = rA - rB. Subtracted, P's
        // L^2 I^-1 terms cancel: a 4 cm box welded 100 m from its anchor lost S to rounding (zero; the weld
        // did nothing), where S is 1/m.
        const Mat3 q = a.invInertia * rInv * b.invInertia, d = cross(arm);
        const Mat3 s =
            (a.invMass + b.invMass) * Mat3::Identity() + d * (0.5f * (q + q.transpose())) * d.transpose();
        if (s.determinant() == 0) return false;
        const Mat3 sInv = s.inverse();
        const Mat3 upperRight = -sInv * cr;
        out.topLeftCorner<3, 3>() = sInv;
        out.topRightCorner<3, 3>() = upperRight;
        out.bottomLeftCorner<3, 3>() = upperRight.transpose();
        out.bottomRightCorner<3, 3>() = rInv - cr.transpose() * upperRight;
        return true;
    }

    Mat6 m_mass = Mat6::Zero();
    bool m_movable = false;
};

} // namespace

} // namespace physics

extern "C" iFixedJoint* CreateFixedJoint(iRigidBody* a, iRigidBody* b, const Vector& anchor) {
    physics::RigidBody *ra, *rb;
    physics::JointFrame fa, fb;
    if (!physics::jointFrames(L"CreateFixedJoint", a, b, anchor, anchor, Vector(1, 0, 0), ra, rb, fa, fb))
        return nullptr;
    return new physics::FixedJoint(ra, rb, fa, fb);
}
