// SpringJoint.cpp - a damped spring between two anchors, solved as a soft constraint (iSpring.h).
//
// One row along n = (pB - pA) / L (JointRows.h), C = L - rest. A spring of stiffness k and damping c over a
// sub-step h is the constraint solved with (Catto, "Soft Constraints", GDC 2011; implicit Euler):
//   lambda = -(Cdot + (beta / h) C + gamma lambda_acc) / (K + gamma),  gamma = 1 / (h (c + h k)),
//   beta = h k / (c + h k),
// which for any k, c and h dissipates (the implicit step's eigenvalues lie inside the unit circle), and as
// h w -> 0 oscillates at w = sqrt(k K). It is solved in the velocity pass only (the force acts once per
// sub-step), its accumulated impulse within +-maxForce h. Given as a frequency f and ratio z, k = m w^2 and
// c = 2 m z w with m = 1 / K, the row's effective mass (Box2D's b2LinearStiffness).
#include "Joint.h"

#include "iSpring.h"
#include "iUtilities.h"

#include <cmath>
#include <limits>
#include <string>

namespace physics {

namespace {

class SpringJoint final : public JointObject<iSpring> {
public:
    SpringJoint(RigidBody* a, RigidBody* b, const JointFrame& fa, const JointFrame& fb, Real rest, Real k,
                Real c)
        : JointObject(JOINT_Spring, a, b, fa, fb), m_rest(rest), m_k(k), m_c(c) {
        m_rowCount = 1;
    }

    bool setRestLength(float length) override {
        if (!(length >= 0) || !std::isfinite(length))
            return refuse(L"iSpring::setRestLength: needs a finite length >= 0");
        m_rest = length;
        return true;
    }
    float getRestLength() const override { return float(m_rest); }
    bool setStiffness(float k) override {
        if (!(k >= 0) || !std::isfinite(k)) return refuse(L"iSpring::setStiffness: needs a finite k >= 0");
        m_k = k;
        m_byFrequency = false;
        return true;
    }
    bool setDamping(float c) override {
        if (!(c >= 0) || !std::isfinite(c)) return refuse(L"iSpring::setDamping: needs a finite c >= 0");
        m_c = c;
        m_byFrequency = false;
        return true;
    }
    float getStiffness() const override { return float(m_k); }
    float getDamping() const override { return float(m_c); }
    bool setFrequency(float hertz, float dampingRatio) override {
        if (!(hertz > 0) || !std::isfinite(hertz) || !(dampingRatio >= 0) || !std::isfinite(dampingRatio))
            return refuse(L"iSpring::setFrequency: needs finite hertz > 0 and ratio >= 0");
        m_hertz = hertz;
        m_ratio = dampingRatio;
        m_byFrequency = true;
        return true;
    }
    bool setMaxForce(float newtons) override {
        if (!(newtons > 0)) return refuse(L"iSpring::setMaxForce: needs a force > 0 (infinite: no limit)");
        m_maxForce = newtons;
        return true;
    }
    float getLength() const override {
        JointFrame a, b;
        worldFrames(a, b);
        return float((b.point - a.point).norm());
    }

    void solve(SolverBody& a, SolverBody& b, Real h, JointPass pass, const JointSoftness&) override {
        if (pass != JointPass::Velocity) return;
        const Vec3 pA = worldPoint(a, m_frameA), pB = worldPoint(b, m_frameB);
        const Vec3 d = pB - pA;
        const Real length = d.norm();
        if (length > Real(1e-9)) m_direction = d / length;
        JointRow& row = m_rows[0];
        row.setLinear(a, b, m_direction, pA - a.com, pB - b.com);
        if (m_byFrequency) {
            const Real omega = Real(2 * 3.14159265358979) * m_hertz;
            m_k = row.mass * omega * omega;
            m_c = 2 * row.mass * m_ratio * omega;
        }
        const Real denominator = m_c + h * m_k;
        if (!(denominator > 0) || row.mass == 0) {
            row.impulse = 0;
            return;
        }
        const Real gamma = 1 / (h * denominator), beta = h * m_k / denominator;
        const Real gm = gamma * row.mass;
        const JointSoftness soft{beta / h, 1 / (1 + gm), gm / (1 + gm)};
        row.lower = -m_maxForce * h;
        row.upper = m_maxForce * h;
        row.solve(a, b, soft.biasRate * (length - m_rest), soft);
    }

private:
    static bool refuse(const wchar_t* why) {
        error((std::wstring(why) + L"; refused").c_str());
        return false;
    }
    Real m_rest, m_k, m_c;
    bool m_byFrequency = false;
    Real m_hertz = 0, m_ratio = 0;
    Real m_maxForce = std::numeric_limits<Real>::infinity();
    Vec3 m_direction = Vec3::UnitY();
};

} // namespace

} // namespace physics

extern "C" iSpring* CreateSpring(iRigidBody* a, iRigidBody* b, const Vector& anchorA, const Vector& anchorB,
                                 float restLength, float stiffness, float damping) {
    if (!(restLength >= 0) || !std::isfinite(restLength) || !(stiffness >= 0) || !std::isfinite(stiffness) ||
        !(damping >= 0) || !std::isfinite(damping)) {
        error(L"CreateSpring: needs finite rest length, stiffness and damping, none negative; refused");
        return nullptr;
    }
    physics::RigidBody *ra, *rb;
    physics::JointFrame fa, fb;
    if (!physics::jointFrames(L"CreateSpring", a, b, anchorA, anchorB, Vector(1, 0, 0), ra, rb, fa, fb))
        return nullptr;
    return new physics::SpringJoint(ra, rb, fa, fb, restLength, stiffness, damping);
}
