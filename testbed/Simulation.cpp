// Simulation.cpp - building, stepping and tuning the testbed's scene (Simulation.h).
#include "Simulation.h"

#include "RBDynamics.h"
#include "Scenes.h"
#include "World.h"
#include "iCollisionSpace.h"
#include "iDebugDrawable.h"
#include "iOctreeCollisionSpace.h"
#include "iPhysicsFrame.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneSettings.h"
#include "iPhysicsSceneStats.h"
#include "iSimpleCollisionSpace.h"

#include <algorithm>
#include <chrono>
#include <list>

Simulation::Simulation(const SceneSpec& spec, const Knobs& knobs) : m_knobs(knobs) { load(spec); }

Simulation::~Simulation() { destroy(); }

void Simulation::destroy() {
    m_spring.release();
    delete m_world; // deletes the shapes and bodies, and the space it made (empty if the knobs moved them)
    m_world = nullptr;
    if (m_space != m_worldSpace && m_space) m_space->Delete();
    m_space = m_worldSpace = nullptr;
    if (m_scene) m_scene->Delete();
    m_scene = nullptr;
}

iCollisionSpace* Simulation::makeSpace() const {
    const size_t samples = size_t(std::max(0, m_knobs.samplesPerSecond));
    return m_knobs.octree ? CreateOctreeCollisionSpace(samples) : CreateSimpleCollisionSpace(samples);
}

void Simulation::applySettings() {
    iPhysicsSceneSettings* s = settingsOf(m_scene);
    s->setIntegrator(m_knobs.integrator);
    s->setStepRate(m_knobs.stepRate);
    s->setSolverIterations(m_knobs.solverIterations);
    s->setSleepingEnabled(m_knobs.sleeping);
    s->setContinuousCollisionEnabled(m_knobs.continuous);
}

void Simulation::load(const SceneSpec& spec) {
    destroy();
    m_spec = &spec;
    m_scene = CreatePhysicsScene(nullptr);
    applySettings();
    m_space = m_worldSpace = makeSpace();
    m_world = new World(m_scene, m_space);
    spec.build(*m_world);
    m_now = 0;
    m_frame = 0;
    m_scene->update(m_now); // the first update sets the time base
}

void Simulation::setKnobs(const Knobs& knobs) {
    const bool newSpace =
        knobs.octree != m_knobs.octree || knobs.samplesPerSecond != m_knobs.samplesPerSecond;
    m_knobs = knobs;
    applySettings();
    if (!newSpace) return;
    iCollisionSpace* next = makeSpace();
    const std::list<iCollisionGeometry*> members = m_space->getAttachedGeometry(); // a copy: add() moves
    for (iCollisionGeometry* g : members) next->add(g);
    m_scene->setNewGlobalCollisionSpace(next); // also the default space of new geometry (shots)
    if (m_space != m_worldSpace) m_space->Delete();
    m_space = next;
}

void Simulation::timedUpdate() {
    const long long before = stepCount();
    const auto start = std::chrono::steady_clock::now();
    m_scene->update(m_now);
    m_lastUpdateMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    m_stepsLastFrame = int(stepCount() - before);
}

void Simulation::frame(int clockNow, bool paused) {
    const int elapsed = m_lastClock < 0 ? 0 : std::min(250, std::max(0, clockNow - m_lastClock));
    m_lastClock = clockNow;
    if (paused) return;
    m_now += elapsed;
    timedUpdate();
    ++m_frame;
    if (m_spec->act) m_spec->act(*m_world, m_frame);
}

void Simulation::singleStep() {
    const long long before = stepCount();
    for (int i = 0; i < 1000 && stepCount() == before; ++i) {
        ++m_now;
        timedUpdate();
    }
}

void Simulation::shoot(const Vector& origin, const Vector& direction, float speed) {
    iPhysicsFrame* ball = m_world->sphere(origin + direction * 1.0f, 0.25f, 2.0f);
    ball->getDynamics()->velocity = direction * speed;
}

bool Simulation::grab(const Vector& origin, const Vector& direction, const Vector& viewForward) {
    return m_spring.grab(m_scene, m_space, origin, direction, viewForward);
}

void Simulation::draw(iDebugDraw& out, unsigned flags) const {
    if (const iDebugDrawable* drawable = debugDrawOf(m_scene)) drawable->debugDraw(out, flags);
}

size_t Simulation::bodyCount() const { return statsOf(m_scene)->getBodyCount(); }
size_t Simulation::awakeCount() const { return statsOf(m_scene)->getAwakeBodyCount(); }
long long Simulation::stepCount() const { return statsOf(m_scene)->getStepCount(); }
size_t Simulation::contactCount() const { return m_space->getNumContacts(); }

bool Simulation::bounds(Vector& lo, Vector& hi) const {
    const auto& bodies = m_world->bodies();
    if (bodies.empty()) return false;
    lo = hi = bodies.front()->getDynamics()->position;
    for (const iPhysicsFrame* f : bodies) {
        const Vector p = f->getDynamics()->position;
        lo = Vector(std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z));
        hi = Vector(std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z));
    }
    return true;
}
