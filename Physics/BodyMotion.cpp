// BodyMotion.cpp - the simulator body's iRigidBodyMotion: teleport, drive toward a pose, wake.
#include "MathEigen.h"
#include "PhysicsConstants.h"
#include "PhysicsScene.h"
#include "RigidBody.h"
#include "iUtilities.h"

#include <cmath>

namespace physics {

namespace {
bool validPose(const Vector& position, const Matrix& orientation, const wchar_t* what) {
    if (position.isFinite() && orientation.isFinite() && isRotation(orientation, 1e-3f)) return true;
    error(what);
    return false;
}
} // namespace

bool RigidBody::teleport(const Vector& position, const Matrix& orientation) {
    if (!validPose(position, orientation,
                   L"iRigidBodyMotion::teleport: refused, the position is not finite or the orientation is "
                   L"not a rotation"))
        return false;
    if (m_dyn.attachedTo()) {
        error(L"iRigidBodyMotion::teleport: refused, the body is attached; teleport the root of its chain");
        return false;
    }
    m_dyn.position = position;
    m_dyn.orientation = orthoNormalize(orientation);
    m_dyn.markTeleported();
    wake();
    return true;
}

bool RigidBody::moveTo(const Vector& position, const Matrix& orientation, float seconds) {
    if (!validPose(position, orientation,
                   L"iRigidBodyMotion::moveTo: refused, the position is not finite or the orientation is not "
                   L"a rotation"))
        return false;
    if (!(seconds > 0.0f) || !std::isfinite(seconds)) {
        error(L"iRigidBodyMotion::moveTo: refused, seconds must be positive and finite");
        return false;
    }
    if (m_dyn.mass != INFINITE_MASS || m_dyn.physicsType == PHYS_FixedInSpace || m_dyn.attachedTo()) {
        error(L"iRigidBodyMotion::moveTo: refused, it drives kinematic bodies (mass INFINITE_MASS, not fixed "
              L"in space, not attached)");
        return false;
    }
    // The rotation still to go, in world axes: target = delta * current.
    Quat delta = toQuat(orientation) * toQuat(m_dyn.orientation).conjugate();
    if (delta.w() < 0) delta.coeffs() = -delta.coeffs(); // the short way round
    Eigen::AngleAxis<Real> turn(delta.normalized());
    m_dyn.velocity = (position - m_dyn.position) / seconds;
    m_dyn.angularVelocity = toVector(turn.axis() * (turn.angle() / seconds));
    wake();
    return true;
}

// An attached body sleeps with its attachment root (the root is what the islands put to sleep): it wakes
// the root.
void RigidBody::wake() {
    setAsleep(false);
    restTime = 0.0f;
    const RBDynamics* root = getDynamics().attachmentRoot();
    if (root == &getDynamics() || !m_scene) return;
    if (RigidBody* r = m_scene->bodyOf(root)) r->wake();
}

} // namespace physics
