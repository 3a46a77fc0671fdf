// MouseSpring.cpp - grabbing a body by a ray cast and pulling it with a damped spring (MouseSpring.h).
#include "MouseSpring.h"

#include "MathDefinitions.h"
#include "RBDynamics.h"
#include "iCollisionGeometry.h"
#include "iCollisionQueries.h"
#include "iPhysicsSceneHooks.h"
#include "iRigidBody.h"
#include "iRigidBodyMotion.h"

#include <cmath>

bool MouseSpring::grab(iPhysicsScene* scene, iCollisionSpace* space, const Vector& origin,
                       const Vector& direction, const Vector& viewForward) {
    release();
    iCollisionQueries* queries = space ? queriesOf(space) : nullptr;
    iPhysicsSceneHooks* hooks = scene ? hooksOf(scene) : nullptr;
    RayHit hit;
    if (!queries || !hooks || !queries->rayCast(origin, direction, 1000.0f, hit) || !hit.geometry)
        return false;
    iRigidBody* body = hit.geometry->getRigidBody();
    if (!body) return false; // a plane
    const RBDynamics& d = body->getDynamics();
    if (d.physicsType == PHYS_FixedInSpace || !(d.mass < INFINITE_MASS)) return false;
    if (!hooks->addForceGenerator(body, this)) return false;
    m_scene = scene;
    m_body = body;
    const Vector centre = d.getWorldPosition();
    m_localAnchor = d.getWorldOrientation().transpose().direction(hit.point - centre);
    m_planeNormal = viewForward;
    m_planeDistance = dot(hit.point, viewForward);
    m_target = hit.point;
    if (iRigidBodyMotion* motion = motionOf(body)) motion->wake();
    return true;
}

void MouseSpring::drag(const Vector& origin, const Vector& direction) {
    if (!m_body) return;
    const float along = dot(direction, m_planeNormal);
    if (std::fabs(along) > 1e-4f) {
        const float t = (m_planeDistance - dot(origin, m_planeNormal)) / along;
        if (t > 0) m_target = origin + direction * t;
    }
    if (iRigidBodyMotion* motion = motionOf(m_body)) motion->wake();
}

void MouseSpring::release() {
    if (m_body && m_scene)
        if (iPhysicsSceneHooks* hooks = hooksOf(m_scene)) hooks->removeForceGenerator(m_body, this);
    m_body = nullptr;
    m_scene = nullptr;
}

Vector MouseSpring::anchor() const {
    if (!m_body) return m_target;
    const RBDynamics& d = m_body->getDynamics();
    return d.getWorldPosition() + d.getWorldOrientation().direction(m_localAnchor);
}

void MouseSpring::addForces(const iRigidBody* body, const RigidBodyState& s, Vector& force, Vector& torque) {
    if (body != m_body) return;
    const float mass = body->getDynamics().mass;
    const float omega = 2.0f * float(M_PI) * kFrequency;
    const Vector r = s.orientation.direction(m_localAnchor);
    const Vector pointVelocity = s.velocity + cross(s.angularVelocity, r);
    const Vector f =
        ((m_target - (s.position + r)) * (omega * omega) - pointVelocity * (2.0f * omega)) * mass;
    force += f;
    // The pull at the grabbed point turns the body; a little angular damping keeps it from spinning up.
    torque += cross(r, f) - s.angularVelocity * (0.5f * mass);
}
