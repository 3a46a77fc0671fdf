// Simulation.h - what the testbed runs: one demo scene (a SceneSpec built into a World) in a physics scene,
// the knobs applied to it through the public settings interfaces, and the course engine loop's
// physicsScene->update(now) with now in milliseconds from a clock (paused, single-stepped or running).
//
// The collision space is a knob too: switching between the simple and the octree space, or changing its
// samples per second, moves every geometry into a new space (iCollisionSpace::add moves a geometry) and
// hands that to the scene, so the bodies keep their state.
#pragma once

#include "MouseSpring.h"
#include "iPhysicsSettings.h"

#include <cstddef>
#include <memory>

struct SceneSpec;
class World;
class iPhysicsScene;
class iCollisionSpace;
class iDebugDraw;

struct Knobs {
    Integrator integrator = INTEGRATOR_SemiImplicitEuler;
    int stepRate = 60;         // Hz
    int solverIterations = 4;  // sub-steps of the contact solve
    int samplesPerSecond = 60; // the space's motion sampling (0: discrete)
    bool octree = false;       // the octree (AABB tree) space instead of the simple space
    bool sleeping = true;
    bool continuous = true; // continuous collision
};

class Simulation {
public:
    Simulation(const SceneSpec& spec, const Knobs& knobs);
    Simulation(const Simulation&) = delete;
    Simulation& operator=(const Simulation&) = delete;
    ~Simulation();

    // Builds spec afresh (at time 0 of the simulation's own clock); reset() builds the current one again.
    void load(const SceneSpec& spec);
    void reset() { load(*m_spec); }
    const SceneSpec& spec() const { return *m_spec; }

    // Applies what changed: settings at once, the space by moving the geometry into a new one.
    void setKnobs(const Knobs& knobs);
    const Knobs& knobs() const { return m_knobs; }

    // One engine frame at clock time clockNow (ms): unless paused, the simulation's time advances by the
    // clock's (at most 250 ms a frame, so a stall does not dump a backlog), physicsScene->update(now) runs,
    // timed, and the scene acts (a shooting scene fires).
    void frame(int clockNow, bool paused);
    // Exactly one physics step (while paused): now advances a millisecond at a time until the scene steps.
    void singleStep();

    // Fires a 0.25 m, 2 kg sphere from origin along the unit direction at speed (m/s).
    void shoot(const Vector& origin, const Vector& direction, float speed = 30.0f);
    MouseSpring& spring() { return m_spring; }
    // Grabs the body under the ray with the mouse spring.
    bool grab(const Vector& origin, const Vector& direction, const Vector& viewForward);

    // Draws the scene (its space's shapes, contacts...: DebugDrawFlag values) into out.
    void draw(iDebugDraw& out, unsigned flags) const;

    // The box around every body's centre; false when there is no body.
    bool bounds(Vector& lo, Vector& hi) const;

    iPhysicsScene* scene() const { return m_scene; }
    iCollisionSpace* space() const { return m_space; }
    size_t bodyCount() const;
    size_t awakeCount() const;
    long long stepCount() const;
    size_t contactCount() const;
    int now() const { return m_now; }
    double lastUpdateMs() const { return m_lastUpdateMs; } // wall time of the last update() call
    int stepsLastFrame() const { return m_stepsLastFrame; }

private:
    void destroy();
    void timedUpdate();
    iCollisionSpace* makeSpace() const;
    void applySettings();

    const SceneSpec* m_spec = nullptr;
    Knobs m_knobs;
    iPhysicsScene* m_scene = nullptr;
    World* m_world = nullptr;
    iCollisionSpace* m_space = nullptr;      // the space in use
    iCollisionSpace* m_worldSpace = nullptr; // the one the world made and deletes
    MouseSpring m_spring;
    int m_now = 0, m_lastClock = -1, m_frame = 0, m_stepsLastFrame = 0;
    double m_lastUpdateMs = 0.0;
};
