// DistanceJoint.cpp - the anchors kept between a minimum and a maximum distance (iDistanceJoint.h).
//
// One row along n = (pB - pA) / L (JointRows.h), Cdot = n . (vB + wB x rB - vA - wA x rA): an equality row,
// C = L - length, when the two are equal (a rod); otherwise one-sided rows, gap L - min (pushing apart) and
// max - L (pulling together), which a slack rope leaves at rest.
#include "Joint.h"
#include "JointRowsInline.h"

#include "iDistanceJoint.h"
#include "iUtilities.h"

#include <cmath>

namespace physics {

namespace {

class DistanceJoint final : public JointObject<iDistanceJoint> {
    enum Row { Equal, Lower, Upper };

public:
    DistanceJoint(RigidBody* a, RigidBody* b, const JointFrame& fa, const JointFrame& fb, Real length)
        : JointObject(JOINT_Distance, a, b, fa, fb), m_min(length), m_max(length) {
        m_rowCount = 3;
    }

    bool setLimits(float minLength, float maxLength) override {
        if (!(minLength >= 0 && minLength <= maxLength) || !std::isfinite(maxLength)) {
            error(L"iDistanceJoint::setLimits: needs finite 0 <= min <= max; refused");
            return false;
        }
        change(m_min, minLength);
        change(m_max, maxLength);
        return true;
    }
    float getMinLength() const override { return float(m_min); }
    float getMaxLength() const override { return float(m_max); }
    float getLength() const override { return float(anchorDistance()); }
    Real reach() const override { return m_max; }

    void prepare(const SolverBody& a, const SolverBody& b, Real) override {
        const Vec3 pA = worldPoint(a, m_frameA), pB = worldPoint(b, m_frameB);
        const Vec3 d = pB - pA, rA = pA - a.com, rB = pB - b.com;
        const Real length = d.norm();
        if (length > Real(1e-9)) m_direction = d / length; // else the last direction
        if (m_min == m_max) {
            m_rows[Lower].off();
            m_rows[Upper].off();
            m_rows[Equal].setLinear(a, b, m_direction, rA, rB);
            makeEqual(m_rows[Equal], length - m_min);
            return;
        }
        m_rows[Equal].off();
        if (m_min > 0) {
            m_rows[Lower].setLinear(a, b, m_direction, rA, rB);
            makeLimit(m_rows[Lower], length - m_min);
        } else {
            m_rows[Lower].off();
        }
        m_rows[Upper].setLinear(a, b, -m_direction, rA, rB);
        makeLimit(m_rows[Upper], m_max - length);
    }

private:
    Real m_min, m_max;
    Vec3 m_direction = Vec3::UnitY();
};

} // namespace

} // namespace physics

extern "C" iDistanceJoint* CreateDistanceJoint(iRigidBody* a, iRigidBody* b, const Vector& anchorA,
                                               const Vector& anchorB) {
    physics::RigidBody *ra, *rb;
    physics::JointFrame fa, fb;
    if (!physics::jointFrames(L"CreateDistanceJoint", a, b, anchorA, anchorB, Vector(1, 0, 0), ra, rb, fa,
                              fb))
        return nullptr;
    const physics::Real length = (physics::toEigen(anchorB) - physics::toEigen(anchorA)).norm();
    return new physics::DistanceJoint(ra, rb, fa, fb, length);
}
