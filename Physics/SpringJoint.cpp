// SpringJoint.cpp - a damped spring between two anchors, solved inside the sub-steps (iSpring.h).
//
// One row along n = (pB - pA) / L (JointRows.h), C = L - rest, K = 1 / m its inverse effective mass. Over a
// sub-step h the spring's impulse is h times its force at the velocity the sub-step ends with (v1 = v0 +
// K lambda) and at a position theta of the way there:
//   lambda = -h (k (C + theta h Cdot1) + c Cdot1)  =>  lambda = -(h k C + e Cdot0) / (1 + K e),
//   e = h (theta h k + c).
// With the sub-step's semi-implicit Euler move this is, for an undamped spring, area-preserving at
// theta = 0 (symplectic Euler: the energy oscillates about its value within a factor 1 / (1 - wh / 2), never
// drifts; period error (wh)^2 / 24) and stable up to wh = 2; at theta = 1 it is the soft constraint of
// Catto, "Soft Constraints" (GDC 2011), implicit Euler: stable for any k, c, h, always dissipating.
// theta = clamp(((wh)^2 - 1/4) / (3/4), 0, 1) keeps a spring the sub-step resolves (wh <= 1/2) conservative
// and makes one of wh >= 1 implicit (the per-sub-step amplification's determinant 1 / (1 + theta (wh)^2)
// stays <= 1 and its eigenvalues inside the unit circle for every wh). Solved once per sub-step, in the
// velocity pass, within +-maxForce h. Given as a frequency f and ratio z, k = m w^2 and c = 2 m z w (Box2D's
// b2LinearStiffness).
#include "Joint.h"
#include "JointRowsInline.h"

#include "iSpring.h"
#include "iUtilities.h"

#include <algorithm>
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
        m_warmStarts = false; // a force, worked out afresh each sub-step along the spring as it is now
    }

    bool setRestLength(float length) override {
        if (!(length >= 0) || !std::isfinite(length))
            return refuse(L"iSpring::setRestLength: needs a finite length >= 0");
        change(m_rest, length);
        return true;
    }
    float getRestLength() const override { return float(m_rest); }
    bool setStiffness(float k) override {
        if (!(k >= 0) || !std::isfinite(k)) return refuse(L"iSpring::setStiffness: needs a finite k >= 0");
        change(m_k, k);
        change(m_byFrequency, false);
        return true;
    }
    bool setDamping(float c) override {
        if (!(c >= 0) || !std::isfinite(c)) return refuse(L"iSpring::setDamping: needs a finite c >= 0");
        change(m_c, c);
        change(m_byFrequency, false);
        return true;
    }
    float getStiffness() const override { return float(m_k); }
    float getDamping() const override { return float(m_c); }
    bool setFrequency(float hertz, float dampingRatio) override {
        if (!(hertz > 0) || !std::isfinite(hertz) || !(dampingRatio >= 0) || !std::isfinite(dampingRatio))
            return refuse(L"iSpring::setFrequency: needs finite hertz > 0 and ratio >= 0");
        change(m_hertz, hertz);
        change(m_ratio, dampingRatio);
        change(m_byFrequency, true);
        return true;
    }
    bool setMaxForce(float newtons) override {
        if (!(newtons > 0)) return refuse(L"iSpring::setMaxForce: needs a force > 0 (infinite: no limit)");
        change(m_maxForce, newtons);
        return true;
    }
    float getLength() const override { return float(anchorDistance()); }

    void prepare(const SolverBody& a, const SolverBody& b, Real) override {
        const Vec3 pA = worldPoint(a, m_frameA), pB = worldPoint(b, m_frameB);
        const Vec3 d = pB - pA;
        const Real length = d.norm();
        if (length > Real(1e-9)) m_direction = d / length;
        JointRow& row = m_rows[0];
        row.setLinear(a, b, m_direction, pA - a.com, pB - b.com);
        makeEqual(row, length - m_rest);
        if (m_byFrequency) {
            const Real omega = Real(2 * 3.14159265358979) * m_hertz;
            m_k = row.mass * omega * omega;
            m_c = 2 * row.mass * m_ratio * omega;
        }
    }

    void solve(SolverBody& a, SolverBody& b, Real h, JointPass pass, const JointSoftness&) override {
        JointRow& row = m_rows[0];
        if (pass != JointPass::Velocity || row.mass == 0 || (m_k == 0 && m_c == 0)) return;
        const Real inverseMass = 1 / row.mass, wh2 = m_k * inverseMass * h * h;
        const Real theta = std::clamp((wh2 - Real(0.25)) / Real(0.75), Real(0), Real(1));
        const Real e = h * (theta * h * m_k + m_c);
        // From the velocities with row.impulse (this sub-step's so far) already in them: Cdot0 = Cdot - K
        // lambda_acc.
        const Real change =
            -(h * m_k * row.error + e * row.speed(a, b) + row.impulse) / (1 + inverseMass * e);
        const Real total = std::clamp(row.impulse + change, -m_maxForce * h, m_maxForce * h);
        row.apply(a, b, total - row.impulse);
        row.impulse = total;
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
