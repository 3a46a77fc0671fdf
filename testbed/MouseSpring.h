// MouseSpring.h - dragging a body with the mouse: a damped spring (an iForceGenerator) from a point on the
// body to a target the mouse moves, grabbed by a ray cast into the collision space (iCollisionQueries.h).
//
// The spring is critically damped at kFrequency whatever the body's mass, so light and heavy bodies follow
// the mouse alike; it pulls the grabbed point, so the body also turns. The target moves in the plane facing
// the camera through the grabbed point.
#pragma once

#include "MathDeclarations.h"
#include "iForceGenerator.h"

class iPhysicsScene;
class iCollisionSpace;
class iRigidBody;

class MouseSpring final : public iForceGenerator {
public:
    static constexpr float kFrequency = 3.0f; // Hz

    MouseSpring() = default;
    MouseSpring(const MouseSpring&) = delete;
    MouseSpring& operator=(const MouseSpring&) = delete;
    ~MouseSpring() { release(); }

    // Casts the ray (origin, unit direction) into space; grabs the first movable body it hits and registers
    // the spring with scene. viewForward: the camera's unit forward (the drag plane's normal). True on a
    // grab.
    bool grab(iPhysicsScene* scene, iCollisionSpace* space, const Vector& origin, const Vector& direction,
              const Vector& viewForward);
    // Moves the target to where the ray meets the drag plane; wakes the body.
    void drag(const Vector& origin, const Vector& direction);
    // Lets go (also when nothing is held).
    void release();

    bool holding() const { return m_body != nullptr; }
    const iRigidBody* body() const { return m_body; }
    Vector target() const { return m_target; }
    Vector anchor() const; // the grabbed point on the body, world space

    void addForces(const iRigidBody* body, const RigidBodyState& s, Vector& force, Vector& torque) override;

private:
    iPhysicsScene* m_scene = nullptr;
    iRigidBody* m_body = nullptr;
    Vector m_localAnchor; // from the centre of mass, body axes
    Vector m_target, m_planeNormal;
    float m_planeDistance = 0.0f; // the drag plane: dot(p, m_planeNormal) = m_planeDistance
};
