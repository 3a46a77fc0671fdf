// FixedJoint.cpp - a weld: B keeps its pose relative to A (iFixedJoint.h).
//
// Rows (JointRows.h): the orientation block (C = the rotation vector from A's frame to B's, Cdot = wB - wA)
// and the point block (C = pB - pA), the point last.
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

    void solve(SolverBody& a, SolverBody& b, Real, JointPass pass, const JointSoftness& soft) override {
        const bool push = pass == JointPass::PushOut;
        m_orientation.setMass(a, b);
        if (push)
            m_orientation.solve(
                a, b, soft.biasRate * rotationError(worldBasis(a, m_frameA), worldBasis(b, m_frameB)), soft);
        else
            m_orientation.solve(a, b, Vec3::Zero());
        const Vec3 pA = worldPoint(a, m_frameA), pB = worldPoint(b, m_frameB);
        m_point.setArms(a, b, pA - a.com, pB - b.com);
        if (push)
            m_point.solve(a, b, soft.biasRate * (pB - pA), soft);
        else
            m_point.solve(a, b, Vec3::Zero());
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
