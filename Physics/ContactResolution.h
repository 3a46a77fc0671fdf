// ContactResolution.h - the scene's side of contact resolution: how its bodies enter the solver and how poses
// are advanced with solved velocities. (The islands that decide who sleeps: Islands.h.)
//
// Bodies enter the solver as composites (an attachment chain is one body about its combined centre of mass).
// A body this scene does not simulate (another owner's, a sleeping one, a kinematic one) enters as
// immovable, keeping its velocity, so a game-animated body still pushes. A body the solver moves enters at
// the step's start, before its forces act; the integrator then works out only what the forces do to its
// velocities (setMotion), and the solver's sub-steps move it through the step, once (semi-implicit Euler,
// with that change added a share per sub-step), so it never moves into what it touches.
#pragma once

#include "Composite.h"
#include "ContactSolver.h"
#include "FlatMap.h"

#include <vector>

struct CollisionContact;

namespace physics {

class JointClosing;
class RigidBody;

class SceneBodyAccess final : public SolverBodyAccess {
public:
    using BodyMap = FlatMap<const RBDynamics*, RigidBody*>;
    // The scene keeps one (its tables keep their storage from step to step); gravity is set each step.
    explicit SceneBodyAccess(const BodyMap& bodies) : m_bodies(bodies) {}
    void startStep(const Vec3& gravity) { m_gravity = gravity; }

    // A movable body enters with its start pose only and RigidBody::solverSlot set: setMotion completes it.
    SolverBody enter(RBDynamics* root, int slot) const override;
    void refresh(SolverBody& b) const override;
    // A movable body's motion once its forces acted: its composite's velocities v and w about the centre of
    // mass, and what the forces added to them over the step (dv, dw).
    void setMotion(SolverBody& b, RigidBody* body, const Composite& c, const Vec3& v, const Vec3& w,
                   const Vec3& dv, const Vec3& dw) const;
    void storeVelocity(const SolverBody& b) const override;
    void storePose(const SolverBody& b) const override; // and the body's own Real pose (RigidBody.h)
    void prefetch(const SolverBody& b) const override;
    bool alive(const RBDynamics* root) const override;
    bool resting(const RBDynamics* root) const override;
    // Records the solver's writes as the simulator's own, so the next step does not take them for edits;
    // every body leaves the solver (solverSlot -1). A body projected out of a deep overlap goes to closing
    // (its joints' partners follow it).
    void acceptWrites(const std::vector<SolverBody>& bodies, JointClosing& closing) const;

private:
    struct Mass {
        RigidBody* body = nullptr;
        Vec3 rootOffset = Vec3::Zero(); // root COM - composite COM, root axes
        Mat3 inertia = Mat3::Zero();    // local, about the composite COM
    };
    const BodyMap& m_bodies;
    Vec3 m_gravity = Vec3::Zero();
    RigidBody* bodyOf(const RBDynamics* root) const;
    // By solver slot; read only for this step's movable bodies, whose setMotion wrote them (the rest may hold
    // an earlier step's: kept, not cleared, so that the table is not written afresh each step).
    mutable std::vector<Mass> m_mass;
};

} // namespace physics
