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

    void prepare(const SolverBody& a, const SolverBody& b, Real) override {
        m_orientation.setMass(a, b);
        m_rotationError = rotationError(worldBasis(a, m_frameA), worldBasis(b, m_frameB));
        preparePoint(a, b);
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
