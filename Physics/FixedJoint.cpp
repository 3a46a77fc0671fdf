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

    // The six rows as one block (K is 6x6): one at a time, the point's rows and the orientation's fight
    // each other wherever the anchor is far from the centre of mass compared with the body's size (a 2 kg
    // box welded 1 m to the side sagged 1.1 cm and its reaction read 0.96 m g: FixedCantilever).
    void solve(SolverBody& a, SolverBody& b, Real, JointPass pass, const JointSoftness& soft) override {
        using Vec6 = Eigen::Matrix<Real, 6, 1>;
        using Mat6 = Eigen::Matrix<Real, 6, 6>;
        const bool push = pass == JointPass::PushOut;
        const Vec3 pA = worldPoint(a, m_frameA), pB = worldPoint(b, m_frameB);
        m_point.setArms(a, b, pA - a.com, pB - b.com);
        const Mat3 sA = cross(m_point.rA), sB = cross(m_point.rB);
        Mat6 k;
        k.topLeftCorner<3, 3>() =
            (a.invMass + b.invMass) * Mat3::Identity() - sA * a.invInertia * sA - sB * b.invInertia * sB;
        k.topRightCorner<3, 3>() = -(sA * a.invInertia + sB * b.invInertia);
        k.bottomLeftCorner<3, 3>() = a.invInertia * sA + b.invInertia * sB;
        k.bottomRightCorner<3, 3>() = a.invInertia + b.invInertia;
        if (!(k.determinant() != 0)) return; // nothing can move: both immovable
        Vec6 speed;
        speed << m_point.speed(a, b), b.w - a.w;
        if (push)
            speed << speed.head<3>() + soft.biasRate * (pB - pA),
                speed.tail<3>() +
                    soft.biasRate * rotationError(worldBasis(a, m_frameA), worldBasis(b, m_frameB));
        Vec6 impulse;
        impulse << m_point.impulse, m_orientation.impulse;
        const Vec6 change = -soft.massScale * Vec6(k.inverse() * speed) - soft.impulseScale * impulse;
        m_point.apply(a, b, change.head<3>());
        m_orientation.apply(a, b, change.tail<3>());
        m_point.impulse += change.head<3>();
        m_orientation.impulse += change.tail<3>();
    }
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
