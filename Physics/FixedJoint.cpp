// FixedJoint.cpp - a weld: B keeps its pose relative to A (iFixedJoint.h).
//
// Rows (JointRows.h): the orientation block (C = the rotation vector from A's frame to B's, Cdot = wB - wA)
// and the point block (C = pB - pA), solved together as one 6x6 block.
#include "Joint.h"

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
        preparePoint(a, b);
        m_rotationError = rotationError(worldBasis(a, m_frameA), worldBasis(b, m_frameB));
        const Mat3 sA = cross(m_point.rA), sB = cross(m_point.rB);
        Mat6 k;
        k.topLeftCorner<3, 3>() =
            (a.invMass + b.invMass) * Mat3::Identity() - sA * a.invInertia * sA - sB * b.invInertia * sB;
        k.topRightCorner<3, 3>() = -(sA * a.invInertia + sB * b.invInertia);
        k.bottomLeftCorner<3, 3>() = a.invInertia * sA + b.invInertia * sB;
        k.bottomRightCorner<3, 3>() = a.invInertia + b.invInertia;
        m_movable = k.determinant() != 0; // else both immovable
        if (m_movable) m_mass = k.inverse();
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
