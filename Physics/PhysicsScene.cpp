// PhysicsScene.cpp - the fixed-step clock, the body list and its lifecycle, and the step itself.
#include "PhysicsScene.h"

#include "MathEigen.h"
#include "RigidBody.h"
#include "iCollisionSpace.h"
#include "iCollisionSpaceScale.h"
#include "iFixedUpdater.h"
#include "iUtilities.h"

#include <algorithm>

namespace physics {

namespace {
// Passes over every body ask for the lines of the body this many places ahead (Prefetch.h).
constexpr size_t kBodiesAhead = 4;
constexpr int MAX_STEP_RATE = 10000;
} // namespace

// --- bodies ---

RigidBody* PhysicsScene::sceneBody(const iRigidBody* o) const {
    RigidBody* b = const_cast<RigidBody*>(dynamic_cast<const RigidBody*>(o));
    return b && b->scene() == this ? b : nullptr;
}

bool PhysicsScene::add(iRigidBody* o) {
    if (!o) {
        error(L"PhysicsScene::add: nullptr refused");
        return false;
    }
    RigidBody* b = dynamic_cast<RigidBody*>(o);
    if (!b) {
        error(
            L"PhysicsScene::add: only bodies made by CreateRigidBody or CreatePhysicsFrame can be simulated");
        return false;
    }
    if (b->dying()) {
        error(L"PhysicsScene::add: the body is being deleted");
        return false;
    }
    if (m_deleteRequested) {
        error(L"PhysicsScene::add: this scene is being deleted; refused");
        return false;
    }
    if (b->scene() == this) {
        if (b->pendingRemoval) { // removed and re-added within one step: it simply stays (unless killed)
            if (b->isAlive()) b->pendingRemoval = false;
            return true;
        }
        error(L"PhysicsScene::add: the body is already in this scene");
        return false;
    }
    if (b->scene()) {
        error(L"PhysicsScene::add: the body is in another scene; remove it there first");
        return false;
    }
    b->sceneSlot = int(m_bodies.size());
    m_bodies.push_back(b);
    m_byDynamics[&b->getDynamics()] = b;
    ++m_membership;
    b->setScene(this);
    if (!b->isAlive()) deferRemove(b); // killed and not resetAlive(): removed again (iLifetime.h)
    return true;
}

void PhysicsScene::remove(const iRigidBody* o) {
    if (!o) {
        error(L"PhysicsScene::remove: nullptr refused");
        return;
    }
    RigidBody* b = sceneBody(o);
    if (!b) {
        error(L"PhysicsScene::remove: the body is not in this scene");
        return;
    }
    if (b->dying()) return; // already leaving
    if (m_busy) {
        deferRemove(b);
        return;
    }
    forget(b);
    b->setScene(nullptr);
}

// --- settings ---

void PhysicsScene::setNewGlobalCollisionSpace(iCollisionSpace* cs) {
    // Deleting the space later is safe: the scene hears of it (onSpaceDestroyed) and forgets it.
    setSpace(cs); // contacts gathered from the old space are not resolved
    // The space measures its tolerances in the scene's unit (a space the game scaled itself is told again).
    if (iCollisionSpaceScale* scale = scaleOf(cs)) scale->setLengthUnitsPerMetre(m_lengthUnit);

    setDefaultCollisionSpace(cs);
}

bool PhysicsScene::setGravity(const Vector& g) {
    if (!g.isFinite()) {
        error(L"PhysicsScene::setGravity: non-finite gravity refused");
        return false;
    }
    if (g != m_gravity) wakeAll(); // asleep under the old gravity, a body would hang where it lay
    m_gravity = g;
    SolverSettings s = m_solver.settings();
    s.gravity = g.length(); // what a resting contact carries (SolverSettings::restingOverlap)
    s.up = s.gravity > 0 ? Vec3(-toEigen(g) / s.gravity) : Vec3(Vec3::Zero()); // what rests on what
    m_solver.setSettings(s);
    return true;
}

bool PhysicsScene::setStepRate(int hz) {
    if (hz < 1 || hz > MAX_STEP_RATE) {
        error(L"PhysicsScene::setStepRate: the step rate must be 1..10000 steps per second; refused");
        return false;
    }
    m_accumulator = m_accumulator * hz / m_stepRate; // the same leftover time in the new units
    m_stepRate = hz;
    return true;
}

bool PhysicsScene::setMaxStepsPerUpdate(int n) {
    if (n < 1) {
        error(L"PhysicsScene::setMaxStepsPerUpdate: at least one step per update is needed; refused");
        return false;
    }
    m_maxSteps = n;
    return true;
}

bool PhysicsScene::setIntegrator(Integrator i) {
    if (i < INTEGRATOR_Default || i >= INTEGRATOR_Count) {
        error(L"PhysicsScene::setIntegrator: not an Integrator value; refused");
        return false;
    }
    m_integrator = i == INTEGRATOR_Default ? INTEGRATOR_SemiImplicitEuler : i;
    return true;
}

bool PhysicsScene::addFixedUpdater(iFixedUpdater* u) {
    if (!u || std::find(m_updaters.begin(), m_updaters.end(), u) != m_updaters.end()) {
        error(L"PhysicsScene::addFixedUpdater: nullptr or an updater already added; refused");
        return false;
    }
    m_updaters.push_back(u);
    return true;
}

void PhysicsScene::removeFixedUpdater(const iFixedUpdater* u) {
    auto it = std::find(m_updaters.begin(), m_updaters.end(), u);
    if (!u || it == m_updaters.end()) return;
    if (m_busy)
        *it = nullptr; // the updater loop may be walking the list: compact after the step
    else
        m_updaters.erase(it);
}

bool PhysicsScene::addForceGenerator(iRigidBody* body, iForceGenerator* g) {
    RigidBody* b = sceneBody(body);
    if (!b || !g) {
        error(L"PhysicsScene::addForceGenerator: needs a generator and a body in this scene; refused");
        return false;
    }
    auto& gens = b->generators();
    if (std::find(gens.begin(), gens.end(), g) == gens.end()) gens.push_back(g);
    b->wake(); // a sleeping body's generators are not evaluated: asleep, it would never feel this one
    return true;
}

void PhysicsScene::removeForceGenerator(const iRigidBody* body, const iForceGenerator* g) {
    if (RigidBody* b = sceneBody(body)) {
        auto& gens = b->generators();
        const size_t before = gens.size();
        gens.erase(std::remove(gens.begin(), gens.end(), g), gens.end());
        if (gens.size() != before) b->wake(); // what it held up (or down) has to be found again
    }
}

// --- time ---

void PhysicsScene::restore(int now) {
    m_suspended = false;
    m_lastNow = now;
    m_hasTimeBase = true;
}

void PhysicsScene::reset(int now) {
    m_lastNow = now;
    m_hasTimeBase = true;
    m_accumulator = 0;
}

void PhysicsScene::update(int now) {
    if (updating()) { // from a callback: this or another scene is mid-step, its lists are being walked
        error(L"PhysicsScene::update: called from inside a scene update (a fixed updater, force generator or "
              L"listener); refused");
        return;
    }
    if (m_suspended || !m_hasTimeBase || now < m_lastNow) {
        // Nothing to integrate: suspended, the first update, or the clock went back (re-based, not replayed).
        m_lastNow = now;
        m_hasTimeBase = true;
        if (m_suspended) return;
        deliverCollisionEvents(); // what still touches is heard every frame
        if (m_deleteRequested) {
            delete this;
            return;
        }
        writeFrames(m_interpolationOn ? float(m_accumulator) / 1000.0f : 1.0f);
        return;
    }
    m_profiler.beginUpdate();
    holdCollisionEvents();
    m_accumulator += (std::int64_t(now) - m_lastNow) * m_stepRate;
    m_lastNow = now;
    const float dt = 1.0f / float(m_stepRate);
    int steps = 0;
    beginSteps();
    while (m_accumulator >= 1000 && steps < m_maxSteps && !m_deleteRequested) {
        m_accumulator -= 1000;
        step(dt);
        ++steps;
    }
    endSteps();                  // scenes deleted from callbacks meanwhile are deleted now
    if (m_accumulator >= 1000) { // the catch-up cap: drop the backlog, keep the partial step
        m_dropped += m_accumulator / 1000;
        m_accumulator %= 1000;
        if (!m_reportedDrops && m_dropped >= m_stepRate) { // a second of simulated time lost: say so once
            m_reportedDrops = true;
            error(L"PhysicsScene::update: the catch-up cap (maxStepsPerUpdate) has dropped a second of "
                  L"simulated time; the game runs slower than real time (reported once)");
        }
    }
    if (!m_deleteRequested) deliverCollisionEvents(); // HitWall once a frame per touching pair
    m_profiler.lap(&PhysicsProfile::events);
    countProfile();
    m_profiler.endUpdate();
    if (m_deleteRequested) {
        delete this;
        return;
    }
    writeFrames(m_interpolationOn ? float(m_accumulator) / 1000.0f : 1.0f); // 1: the last step's pose
}

void PhysicsScene::writeFrames(float alpha) {
    const unsigned long long round = RigidBody::newFrameRound(); // parents' frames before their children's
    RigidBody::PoseCache poses;                                  // no game code runs while frames are written
    for (RigidBody* b : bodies())
        if (!b->dying() && !b->pendingRemoval) b->writeFrameAfterParent(alpha, round);
}

// --- the step ---

void PhysicsScene::step(float dt) {
    // 1. Game code at the physics rate. It may add, remove or delete bodies: removals wait for step 10.
    runFixedUpdaters(dt);
    m_profiler.lap(&PhysicsProfile::updaters);

    // 2. Take in the game's edits: a written pose or a moved frame teleports the body; an invalid state is
    //    reported and replaced by the body's last valid one; a sleeping body the game touched wakes. The pose
    //    now is where this step's interpolation starts. An inertia tensor the engine derives catches up with
    //    the mass and com the game may have written (RBDynamics.h); integrateComposite then keeps the angular
    //    velocity.
    for (size_t i = 0; i < bodies().size(); ++i) {
        if (i + kBodiesAhead < bodies().size()) bodies()[i + kBodiesAhead]->prefetchDynamics(m_validationOn);
        RigidBody* b = bodies()[i];
        if (b->dying() || b->pendingRemoval) continue;
        b->getDynamics().updateInertia();
        if (b->asleep() && !b->editedWhileAsleep()) continue;
        b->setAsleep(false); // before the space looks: its pairs are tested again
        b->adoptFrameEdits();
        if (m_validationOn) b->acceptState("before a step"); // valid edits kept on failure
        b->checkedStep = m_steps;
    }
    if (m_sleeping)
        m_islands.wakeIslandMates(bodies()); // a sleeping island wakes whole, before the space looks
    { // After every edit is in (a root's adopted frame moves its chain): world poses, O(1) a body.
        RigidBody::PoseCache poses;
        for (RigidBody* b : bodies())
            if (!b->dying() && !b->pendingRemoval) {
                if (b->movedByGame()) b->getDynamics().markTeleported(); // spaces do not sweep across it
                b->recordPreviousPose();
            }
    }
    m_profiler.lap(&PhysicsProfile::edits);

    // 3. Contacts at the step's starting poses. Listeners hear of them after the steps (HitWall, once per
    //    frame), or now with a space that cannot hold its events; they may delete things.
    const CollisionContact* contacts = nullptr;
    size_t contactCount = 0;
    const unsigned spaceVersion = m_spaceVersion;
    findContacts(dt, spaceVersion, contacts, contactCount);
    gatherJoints(); // the joints this step solves (SceneJoints.cpp)
    m_profiler.lap(&PhysicsProfile::collision);

    // 4. Islands of touching bodies: a sleeping body touched by an awake one wakes, and with it its whole
    //    island as it fell asleep (at once: woken a layer a step, a pyramid woken at its top collapsed in a
    //    wave, each layer starting cold under the weight above). The pairs among the woken were not tested
    //    (both slept): the contacts are found again.
    if (m_sleeping) {
        m_islands.build(bodies(), m_byDynamics, contacts, contactCount);
        joinJointIslands(); // jointed bodies sleep and wake together
        m_islands.wakeTouched(bodies());
        if (m_islands.wakeIslandMates(bodies()) && m_spaceVersion == spaceVersion) {
            findContacts(dt, spaceVersion, contacts, contactCount);
            m_islands.build(bodies(), m_byDynamics, contacts, contactCount);
            joinJointIslands();
        }
    }
    // A body that woke after the edits were taken in (touched, with its island, or by the space) is checked
    // now, before the solver reads it: an impossible value written into a sleeper is refused, never used.
    for (size_t i = 0; m_validationOn && i < bodies().size(); ++i) {
        RigidBody* b = bodies()[i];
        if (b->dying() || b->pendingRemoval || b->asleep() || b->checkedStep == m_steps) continue;
        b->acceptState("as it woke");
        b->checkedStep = m_steps;
    }
    m_profiler.lap(&PhysicsProfile::islands);

    // 5. The contact solver collects this step's manifolds and joints at the starting poses, before any force
    //    acts. The bodies they hold enter it: it moves them through the step in step 7.
    const bool solving = contactCount > 0 || !m_joints.empty();
    if (solving) {
        m_bodyAccess.startStep(toEigen(m_gravity));
        m_solver.setJoints(m_joints);
        m_solver.collect(contacts, contactCount, m_bodyAccess);
    }
    m_profiler.lap(&PhysicsProfile::solver);

    // 6. Forces on each awake composite (unattached bodies and attachment roots; attached bodies ride
    //    along). A free body is moved by the game's integrator; for one the solver moves, the integrator
    //    only works out what the forces do to its velocities.
    for (size_t i = 0; i < bodies().size(); ++i) {
        if (i + kBodiesAhead < bodies().size()) {
            const int slot = bodies()[i + kBodiesAhead]->solverSlot;
            if (slot >= 0) prefetchLines(&m_solver.body(slot), sizeof(SolverBody));
        }
        RigidBody* b = bodies()[i];
        if (b->dying() || b->pendingRemoval || b->asleep() || b->getDynamics().attachedTo()) continue;
        integrateComposite(b, dt);
    }
    m_profiler.lap(&PhysicsProfile::integration);

    // 7. Resolve contacts: the touched bodies move from the step's start in sub-steps, impulses keeping them
    //    apart, their forces added a share per sub-step; then leftover overlap is pushed out.
    //    A force generator may have deleted the space or a geometry in contact (the space dropped its
    //    contacts): the manifolds are collected again from what is left (never read from freed memory).
    if (solving) {
        if (!m_space || m_spaceVersion != spaceVersion)
            m_solver.dropManifolds();
        else if (m_space->getContactList() != contacts || m_space->getNumContacts() != contactCount)
            m_solver.recollect(m_space->getContactList(), m_space->getNumContacts(), m_bodyAccess);
        m_solver.solve(dt, m_bodyAccess);
        m_bodyAccess.acceptWrites(m_solver.bodies(), m_jointClosing);
        finishJoints(); // reactions; a joint past its break force breaks
    }
    m_profiler.lap(&PhysicsProfile::solver);

    // 7b. Continuous collision: a body whose motion passed into or through something goes back to where it
    //     first touched it; the next step resolves that contact (ContinuousStage.h).
    if (m_continuousOn) m_continuous.run(bodies(), m_spaceCast, m_jointClosing);
    // 7c. What the solver's projection or the continuous stage moved alone takes its joints' partners along,
    //     positions only, a put-back body held where it was put (JointClosing.h).
    m_jointClosing.close();
    m_profiler.lap(&PhysicsProfile::continuous);

    // 8. A step that produced NaN or Inf (absurd forces) is undone; otherwise it is the new valid state. The
    //    pose each body ends the step with is recorded in the same pass, while its dynamics are at hand (a
    //    settled 10,000-box pile: this phase 0.92x, the step 0.995x, against two passes); a body put back
    //    moves the bodies attached to it, so then every one is recorded again.
    bool restored = false;
    {
        RigidBody::PoseCache poses;
        for (size_t i = 0; i < bodies().size(); ++i) {
            if (i + kBodiesAhead < bodies().size())
                bodies()[i + kBodiesAhead]->prefetchDynamics(m_validationOn);
            RigidBody* b = bodies()[i];
            if (b->dying() || b->pendingRemoval || b->asleep()) continue;
            if (m_validationOn && !b->acceptState("after a step")) restored = true;
            b->recordStepPose();
        }
    }
    if (restored) {
        RigidBody::PoseCache poses;
        for (RigidBody* b : bodies())
            if (!b->dying() && !b->pendingRemoval && !b->asleep()) b->recordStepPose();
    }

    // 9. Islands that rested long enough fall asleep.
    //    RBDynamics::sleeping tells the collision space which pairs need no test.
    if (m_sleeping) m_islands.updateSleep(bodies(), dt);

    // 10. Joints that broke are heard of; then removals and deletions requested during the step.
    deliverJointBreaks();
    ++m_steps;
    flushDeferred();
    m_profiler.current().steps += 1;
    m_profiler.current().contacts = contactCount;
    m_lastStepSolved = solving;
    m_profiler.lap(&PhysicsProfile::sleeping);
}

// The profile's counts, once an update, after its last step (nothing of this runs per step).
void PhysicsScene::countProfile() {
    PhysicsProfile& p = m_profiler.current();
    if (p.steps == 0) return;
    p.bodies = bodies().size();
    p.awakeBodies = getAwakeBodyCount();
    p.touchingPairs = m_lastStepSolved ? m_solver.manifolds().size() : 0;
    p.solverRows = 0;
    if (m_lastStepSolved)
        for (const Manifold& m : m_solver.manifolds()) p.solverRows += 3 * size_t(m.count);
}

void PhysicsScene::findContacts(float dt, unsigned spaceVersion, const CollisionContact*& contacts,
                                size_t& count) {
    contacts = nullptr;
    count = 0;
    if (iCollisionSpace* space = m_space) {
        space->populateContactList(dt);
        // A listener may have replaced this scene's space meanwhile (a notifying space cannot be deleted,
        // so `space` is alive): then its contacts are not this scene's any more.
        if (m_spaceVersion == spaceVersion) {
            contacts = space->getContactList();
            count = space->getNumContacts();
        }
    }
}

void PhysicsScene::runFixedUpdaters(float dt) {
    for (size_t i = 0; i < m_updaters.size(); ++i) // by index: an updater may add or remove updaters
        if (iFixedUpdater* u = m_updaters[i]) u->fixedUpdate(this, dt);
}

} // namespace physics

// The context is the seed's parameter; the scene's knobs are set through settingsOf(scene) (iPhysicsScene.h).
extern "C" iPhysicsScene* CreatePhysicsScene(iContext*) { return new physics::PhysicsScene(); }
