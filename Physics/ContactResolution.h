// ContactResolution.h - the scene's side of contact resolution: how its bodies enter the solver, how poses
// are advanced with solved velocities, and the islands that decide who sleeps.
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
    bool alive(const RBDynamics* root) const override;
    bool resting(const RBDynamics* root) const override;
    // Records the solver's writes as the simulator's own, so the next step does not take them for edits;
    // every body leaves the solver (solverSlot -1).
    void acceptWrites(const std::vector<SolverBody>& bodies) const;

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

// Union-find over the scene's bodies, joined by this step's contacts: the islands that sleep and wake
// together. Built in body order, so the result does not depend on addresses.
class Islands {
public:
    void build(const std::vector<RigidBody*>& bodies, const SceneBodyAccess::BodyMap& byDynamics,
               const CollisionContact* contacts, size_t count);
    // Wakes every sleeping body that shares an island with an awake movable body, or whose island touches
    // a moving body outside the islands (fixed in space, kinematic or a game's own, with a velocity or moved
    // since the last step: a platform, a lift).
    void wakeTouched(const std::vector<RigidBody*>& bodies);
    // Wakes the sleeping bodies of every island a member of which is awake again (woken by the game or by a
    // touch): an island sleeps and wakes whole. Returns whether any body woke.
    bool wakeIslandMates(const std::vector<RigidBody*>& bodies);
    // Adds dt of rest to bodies below the sleep speeds; an island whose bodies all rested long enough sleeps.
    // (resolveContacts zeroes the rest time of a body still being pushed out of an overlap.)
    void updateSleep(const std::vector<RigidBody*>& bodies, float dt);
    // Two bodies a joint holds together are one island (nullptr, the world, joins nothing).
    void join(const RigidBody* a, const RigidBody* b);

    // What the next step reads of the last (snapshots): the poses of the bodies outside the islands.
    struct Pose {
        Vector position;
        Matrix orientation;
    };
    using Memory = FlatMap<const RBDynamics*, Pose>;
    const Memory& memory() const { return m_outsiders; }
    void setMemory(const Memory& m) { m_outsiders = m; }

    // A body rests below kSleepSpeed m/s (scaled to the world's length unit) and kSleepSpeed rad/s.
    static constexpr float kSleepSpeed = 0.05f;
    void setLengthUnit(float unitsPerMetre) { m_sleepSpeed = kSleepSpeed * unitsPerMetre; }
    static constexpr float kTimeToSleep = 0.5f; // s

private:
    int find(int i) const;
    // Whether a body outside the islands moves; records its pose for the next step's question.
    bool outsiderMoves(const RBDynamics& d);
    float m_sleepSpeed = kSleepSpeed; // length units per second
    FlatMap<const RigidBody*, int> m_index;
    mutable std::vector<int> m_parent;
    std::vector<char> m_pushed; // per island member: touched by a moving outsider
    FlatMap<const RBDynamics*, Pose> m_outsiders, m_outsidersNext; // last step's poses, this one's
    std::vector<char> m_awake;                                     // per island root (wakeTouched)
    std::vector<float> m_leastRest;                                // per island root (updateSleep)
    std::vector<unsigned> m_sleepIds;                              // per island root: its sleep id
    std::vector<unsigned> m_woken;                                 // sleep ids with a member awake again
    unsigned m_lastSleepId = 0;
};

} // namespace physics
