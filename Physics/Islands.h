// Islands.h - the islands that decide who sleeps: the scene's bodies joined by this step's contacts and its
// joints, sleeping and waking whole.
#pragma once

#include "ContactResolution.h"
#include "FlatMap.h"

#include <vector>

struct CollisionContact;

namespace physics {

class RigidBody;

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
