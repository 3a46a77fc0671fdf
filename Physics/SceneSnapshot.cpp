// SceneSnapshot.cpp - a scene's whole state saved and put back (iSnapshots.h): each body's dynamics and
// bookkeeping, the solver's memory (last step's manifolds and impulses), the islands' memory of moving
// outsiders, the joints' impulses, the fixed-step clock, and its collision space's own snapshot. The next
// steps after a restore are bit-identical to those after the snapshot (ctest Snapshot.*).
#include "PhysicsScene.h"

#include "Joint.h"

#include "RigidBody.h"
#include "iFrame.h"
#include "iSnapshots.h"
#include "iUtilities.h"

#include <algorithm>
#include <functional>

namespace physics {

namespace {

using SavedJoint = std::pair<const Joint*, Joint::State>;
bool jointFirst(const SavedJoint& a, const SavedJoint& b) {
    return std::less<const Joint*>()(a.first, b.first);
}

class SceneSnapshot final : public iSnapshot {
public:
    ~SceneSnapshot() {
        if (space) space->Delete();
    }
    void Delete() const override { delete this; }

    const PhysicsScene* owner = nullptr;
    unsigned long long membership = 0;
    std::vector<RigidBody*> bodies;
    std::vector<RigidBody::Saved> saved;
    ContactSolver::Memory solver;
    Islands::Memory islands;
    const iCollisionSpace* spaceOwner = nullptr;
    unsigned spaceVersion = 0;
    iSnapshot* space = nullptr; // the space's own, if it has snapshots
    std::int64_t accumulator = 0;
    int lastNow = 0;
    bool hasTimeBase = false;
    long long steps = 0, dropped = 0;
    std::vector<SavedJoint> joints; // the joints whose body A is in the scene, by address
};

} // namespace

RigidBody::Saved RigidBody::save() const {
    return Saved{m_dyn,
                 m_lastValid,
                 m_dyn.sleeping,
                 m_dyn.teleports,
                 m_prevPosition,
                 m_stepPosition,
                 projectedBy,
                 writtenOmega,
                 writtenMomentum,
                 m_prevRotation,
                 rotation,
                 m_stepOrientation,
                 writtenOrientation,
                 forceDv,
                 forceDw,
                 own,
                 m_startPosition,
                 restTime,
                 compositeMass,
                 sleepIsland,
                 hasComposite,
                 compositeInertia};
}

void RigidBody::load(const Saved& s) {
    m_dyn = s.dyn; // keeps the body's place in its attachment chain
    m_dyn.sleeping = s.sleeping;
    m_dyn.teleports = s.teleports;
    m_dyn.updateInertia(); // as it was: derived from the same shape and mass
    m_lastValid = s.lastValid;
    m_lastValidChecked = false; // the next step checks the state in full
    m_prevPosition = s.prevPosition;
    m_stepPosition = s.stepPosition;
    projectedBy = s.projectedBy;
    writtenOmega = s.writtenOmega;
    writtenMomentum = s.writtenMomentum;
    m_prevRotation = s.prevRotation;
    rotation = s.rotation;
    m_stepOrientation = s.stepOrientation;
    writtenOrientation = s.writtenOrientation;
    forceDv = s.forceDv;
    forceDw = s.forceDw;
    own = s.own;
    m_startPosition = s.startPosition;
    restTime = s.restTime;
    compositeMass = s.compositeMass;
    sleepIsland = s.sleepIsland;
    hasComposite = s.hasComposite;
    compositeInertia = s.compositeInertia;
    solverSlot = -1;
    // The frame shows where the game last saw the body; writeFrames puts it where this state draws it.
    if (m_frame) m_writtenWorld = m_frame->world();
}

iSnapshot* PhysicsScene::takeSnapshot() const {
    if (m_busy || updating()) {
        error(L"iSnapshots::takeSnapshot: the scene is updating; take it between updates");
        return nullptr;
    }
    iSnapshots* spaceSnapshots = m_space ? snapshotsOf(m_space) : nullptr;
    iSnapshot* space = spaceSnapshots ? spaceSnapshots->takeSnapshot() : nullptr;
    if (spaceSnapshots && !space) return nullptr; // said why
    SceneSnapshot* s = new SceneSnapshot();
    s->owner = this;
    s->membership = m_membership;
    s->bodies = bodies();
    s->saved.reserve(bodies().size());
    for (const RigidBody* b : bodies()) s->saved.push_back(b->save());
    s->solver = m_solver.memory();
    s->islands = m_islands.memory();
    s->spaceOwner = m_space;
    s->spaceVersion = m_spaceVersion;
    s->space = space;
    s->accumulator = m_accumulator;
    s->lastNow = m_lastNow;
    s->hasTimeBase = m_hasTimeBase;
    s->steps = m_steps;
    s->dropped = m_dropped;
    for (const RigidBody* b : bodies())
        for (const Joint* j : b->joints)
            if (j->bodyA() == b) s->joints.emplace_back(j, j->state());
    std::sort(s->joints.begin(), s->joints.end(), jointFirst);
    return s;
}

bool PhysicsScene::restoreSnapshot(const iSnapshot* snapshot) {
    const SceneSnapshot* s = dynamic_cast<const SceneSnapshot*>(snapshot);
    if (!s || s->owner != this) {
        error(L"iSnapshots::restoreSnapshot: not a snapshot of this scene; refused");
        return false;
    }
    if (m_busy || updating()) {
        error(L"iSnapshots::restoreSnapshot: the scene is updating; refused");
        return false;
    }
    if (s->membership != m_membership || s->bodies != bodies()) {
        error(L"iSnapshots::restoreSnapshot: bodies were added, removed or deleted since the snapshot; "
              L"refused");
        return false;
    }
    if (s->spaceOwner != m_space || s->spaceVersion != m_spaceVersion) {
        error(
            L"iSnapshots::restoreSnapshot: the scene's collision space changed since the snapshot; refused");
        return false;
    }
    // The space checks its own members first and changes nothing when it refuses.
    if (s->space && !snapshotsOf(m_space)->restoreSnapshot(s->space)) return false;
    for (size_t i = 0; i < bodies().size(); ++i) bodies()[i]->load(s->saved[i]);
    RigidBody::invalidatePoses();
    m_solver.setMemory(s->solver);
    m_islands.setMemory(s->islands);
    m_accumulator = s->accumulator;
    m_lastNow = s->lastNow;
    m_hasTimeBase = s->hasTimeBase;
    m_steps = s->steps;
    m_dropped = s->dropped;
    // Joints made since start from nothing; those deleted since are not looked for (only live ones are).
    for (RigidBody* b : bodies())
        for (Joint* j : b->joints) {
            if (j->bodyA() != b) continue;
            j->resetImpulses();
            const SavedJoint key{j, Joint::State{}};
            auto saved = std::lower_bound(s->joints.begin(), s->joints.end(), key, jointFirst);
            if (saved != s->joints.end() && saved->first == j) j->setState(saved->second);
        }
    writeFrames(float(m_accumulator) / 1000.0f);
    return true;
}

} // namespace physics
