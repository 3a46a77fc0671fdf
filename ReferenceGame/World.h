// World.h - what one demo scene owns: a collision space handed to the physics scene, and the bodies and
// shapes built in it. The reference game, the tests and the benchmarks build their scenes with it, so each
// scene is written once.
#pragma once

#include "MathDeclarations.h"

#include <string>
#include <utility>
#include <vector>

class iPhysicsScene;
class iPhysicsFrame;
class iCollisionSpace;
class iCollisionGeometry;
class iJoint;
class iRigidBody;
class iRope;
class iSoftBody;
struct RBDynamics;

class World {
public:
    // Makes space (by default a new simple collision space) the scene's and the default for new geometry;
    // the world owns it.
    explicit World(iPhysicsScene* scene, iCollisionSpace* space = nullptr);
    World(const World&) = delete;
    World& operator=(const World&) = delete;
    // Deletes every joint, rope and soft body it was given, every shape and body it built and its space (the
    // physics scene stays).
    ~World();

    iPhysicsFrame* box(const Vector& centre, const Vector& halfExtents, float mass,
                       const Matrix& orientation = Matrix(1));
    iPhysicsFrame* sphere(const Vector& centre, float radius, float mass);
    iPhysicsFrame* fixedBox(const Vector& centre, const Vector& halfExtents);
    // A world-space floor: a one-sided plane at height y, no body.
    void ground(float y = 0.0f);

    // Takes a joint between bodies of this world (Create*Joint, CreateSpring) to delete with it; returns it
    // (nullptr, a factory's refusal, is passed through and not kept).
    template <class J> J* joint(J* j) {
        keep(j);
        return j;
    }
    const std::vector<iJoint*>& joints() const { return m_joints; }
    // Takes a rope or soft body (iRope.h, iSoftBody.h) to delete with it, adds its bodies to the scene and
    // gives each a sphere of radius in this world's space; returns it (nullptr passed through). Its bodies
    // are no PhysicsFrames: they are parts(), not bodies(); the measurements below count them, shapes() (and
    // so a recording) leaves them out.
    iRope* rope(iRope* r, float radius);
    iSoftBody* softBody(iSoftBody* s, float radius);
    const std::vector<iRope*>& ropes() const { return m_ropes; }
    const std::vector<iSoftBody*>& softBodies() const { return m_softBodies; }
    struct Part {
        iRigidBody* body;
        float radius; // its sphere's
    };
    const std::vector<Part>& parts() const { return m_parts; }

    iPhysicsScene* scene() const { return m_scene; }
    iCollisionSpace* space() const { return m_space; }
    const std::vector<iPhysicsFrame*>& bodies() const { return m_bodies; }

    // What each collision shape was built as, in the order built (the order the space holds and draws them),
    // so that a picture can be drawn without the space (the game's --record and --replay).
    struct Shape {
        enum Kind { Sphere, Box, Plane } kind;
        int body;     // its body's index in bodies(); -1 for a plane (it has no body)
        Vector size;  // Sphere: (r, r, r); Box: half extents; Plane: the unit normal
        float offset; // Plane: where it lies along its normal (0 for the others)
    };
    const std::vector<Shape>& shapes() const { return m_shapeInfo; }

    // Names a body of this world for people (the game's --track, its CSV columns): a scene names the few
    // bodies worth watching, e.g. name(tower.back(), "top"). A name given again moves to the new body;
    // returns body. named() is nullptr for a name no body has.
    iPhysicsFrame* name(iPhysicsFrame* body, const std::string& name);
    iPhysicsFrame* named(const std::string& name) const;
    const std::vector<std::pair<std::string, iPhysicsFrame*>>& names() const { return m_names; }

    // Measurements over the moving bodies.
    float kineticEnergy() const;       // translational + rotational, J
    float mechanicalEnergy() const;    // kinetic + potential against the scene's gravity, J
    float maxPenetration() const;      // deepest contact in the space's current list, m
    bool allFinite() const;            // no NaN or Inf in any body's state
    float deepestBelow(float y) const; // how far the lowest body centre is below y (0 when none is)

private:
    void keep(iJoint* j);
    void addPart(iRigidBody* body, float radius);
    std::vector<const RBDynamics*> allDynamics() const; // bodies' then parts'
    iPhysicsScene* m_scene;
    iCollisionSpace* m_space;
    std::vector<iPhysicsFrame*> m_bodies;
    std::vector<iCollisionGeometry*> m_shapes;
    std::vector<iJoint*> m_joints;
    std::vector<iRope*> m_ropes;
    std::vector<iSoftBody*> m_softBodies;
    std::vector<Part> m_parts;
    std::vector<iCollisionGeometry*> m_partShapes;               // the parts' spheres (not in m_shapeInfo)
    std::vector<Shape> m_shapeInfo;                              // m_shapes' descriptions
    std::vector<std::pair<std::string, iPhysicsFrame*>> m_names; // in naming order
};
