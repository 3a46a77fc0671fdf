// PhysicsSceneContacts.cpp - the scene's collision events and its solver and sleeping settings.
#include "PhysicsScene.h"

#include "MathEigen.h"
#include "RigidBody.h"
#include "iCollisionEvents.h"
#include "iCollisionSpaceScale.h"
#include "iShapeCast.h"
#include "iUtilities.h"

namespace physics {

void PhysicsScene::setSpace(iCollisionSpace* space) {
    m_space = space;
    m_spaceEvents = space ? eventsOf(space) : nullptr;
    m_spaceCast = space ? castOf(space) : nullptr;
    ++m_spaceVersion;
}

void PhysicsScene::holdCollisionEvents() {
    if (m_spaceEvents) m_spaceEvents->holdEvents(true);
}

void PhysicsScene::deliverCollisionEvents() {
    iCollisionEvents* events = m_spaceEvents;
    if (!events || !m_listenersOn) return; // listeners off: the held events are never delivered
    beginSteps(); // listeners may delete bodies and scenes, or call update(): as in a step
    events->deliverEvents();
    flushDeferred();
    endSteps();
}

bool PhysicsScene::setSolverIterations(int n) {
    if (n < 1 || n > 1000) {
        error(L"PhysicsScene::setSolverIterations: iterations must be 1..1000; unchanged");
        return false;
    }
    SolverSettings s = m_solver.settings();
    s.substeps = n;
    m_solver.setSettings(s);
    return true;
}

bool PhysicsScene::setLengthUnitsPerMetre(float unitsPerMetre) {
    if (!validLengthUnit(unitsPerMetre)) {
        error(L"PhysicsScene::setLengthUnitsPerMetre: the unit must be 1e-3..1e3 length units per metre; "
              L"unchanged");
        return false;
    }
    m_lengthUnit = unitsPerMetre;
    m_solver.setSettings(withLengthUnit(m_solver.settings(), unitsPerMetre));
    m_islands.setLengthUnit(unitsPerMetre);
    if (iCollisionSpaceScale* scale = scaleOf(m_space)) scale->setLengthUnitsPerMetre(unitsPerMetre);
    return true;
}

static bool validRule(CombineRule r) { return r >= COMBINE_Sum && r <= COMBINE_GeometricMean; }

bool PhysicsScene::setFrictionRule(CombineRule r) {
    if (!validRule(r)) {
        error(L"PhysicsScene::setFrictionRule: unknown rule; unchanged");
        return false;
    }
    SolverSettings s = m_solver.settings();
    s.friction = r;
    m_solver.setSettings(s);
    return true;
}

bool PhysicsScene::setRestitutionRule(CombineRule r) {
    if (!validRule(r)) {
        error(L"PhysicsScene::setRestitutionRule: unknown rule; unchanged");
        return false;
    }
    SolverSettings s = m_solver.settings();
    s.restitution = r;
    m_solver.setSettings(s);
    return true;
}

void PhysicsScene::setSleepingEnabled(bool on) {
    m_sleeping = on;
    if (!on) wakeAll();
}

void PhysicsScene::wakeAll() {
    for (RigidBody* b : bodies()) b->wake();
}

size_t PhysicsScene::getAwakeBodyCount() const {
    size_t awake = 0;
    for (const RigidBody* b : bodies())
        if (!b->asleep() && b->getDynamics().physicsType != PHYS_FixedInSpace) ++awake;
    return awake;
}

} // namespace physics
