// World.cpp - building and measuring a demo scene through the public API only.
#include "World.h"

#include "MathDefinitions.h"
#include "RBDynamics.h"
#include "iCOBB.h"
#include "iCPlane.h"
#include "iCSphere.h"
#include "iCollisionSpace.h"
#include "iJoint.h"
#include "iPhysicsFrame.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneSettings.h"
#include "iRigidBody.h"
#include "iRope.h"
#include "iSimpleCollisionSpace.h"
#include "iSoftBody.h"

#include <algorithm>
#include <cmath>

World::World(iPhysicsScene* scene, iCollisionSpace* space)
    : m_scene(scene), m_space(space ? space : CreateSimpleCollisionSpace()) {
    m_scene->setNewGlobalCollisionSpace(m_space);
}

World::~World() {
    for (iCollisionGeometry* g : m_shapes) g->Delete();
    for (iCollisionGeometry* g : m_partShapes) g->Delete();
    for (iJoint* j : m_joints) j->Delete(); // before their bodies (the other order is safe too)
    for (iRope* r : m_ropes) r->Delete();   // its links, pins and segments
    for (iSoftBody* b : m_softBodies) b->Delete();
    for (iPhysicsFrame* f : m_bodies) f->Delete();
    m_scene->setNewGlobalCollisionSpace(nullptr);
    m_space->Delete();
}

void World::keep(iJoint* j) {
    if (j) m_joints.push_back(j);
}

void World::addPart(iRigidBody* body, float radius) {
    if (!body) return; // a part the scene deleted
    m_parts.push_back({body, radius});
    m_partShapes.push_back(CreateCSphere(body, radius));
}

iRope* World::rope(iRope* r, float radius) {
    if (!r) return r;
    m_ropes.push_back(r);
    r->addToScene(m_scene);
    for (int i = 0; i < r->getSegmentCount(); ++i) addPart(r->getSegments()[i], radius);
    return r;
}

iSoftBody* World::softBody(iSoftBody* s, float radius) {
    if (!s) return s;
    m_softBodies.push_back(s);
    s->addToScene(m_scene);
    for (int i = 0; i < s->getBodyCount(); ++i) addPart(s->getBody(i), radius);
    return s;
}

std::vector<const RBDynamics*> World::allDynamics() const {
    std::vector<const RBDynamics*> all;
    for (const iPhysicsFrame* f : m_bodies) all.push_back(f->getDynamics());
    for (const Part& p : m_parts) all.push_back(&p.body->getDynamics());
    return all;
}

iPhysicsFrame* World::box(const Vector& centre, const Vector& half, float mass, const Matrix& orientation) {
    iPhysicsFrame* f = CreatePhysicsFrame();
    RBDynamics* d = f->getDynamics();
    d->position = centre;
    d->orientation = orientation;
    d->mass = mass;
    d->setInertiaTensor(getBoxInertiaTensor(mass, half));
    m_shapes.push_back(CreateCOBB(f->getRB(), half));
    m_shapeInfo.push_back({Shape::Box, int(m_bodies.size()), half, 0.0f});
    m_bodies.push_back(f);
    return f;
}

iPhysicsFrame* World::sphere(const Vector& centre, float radius, float mass) {
    iPhysicsFrame* f = CreatePhysicsFrame();
    RBDynamics* d = f->getDynamics();
    d->position = centre;
    d->mass = mass;
    d->setInertiaTensor(getSphereInertiaTensor(mass, radius));
    m_shapes.push_back(CreateCSphere(f->getRB(), radius));
    m_shapeInfo.push_back({Shape::Sphere, int(m_bodies.size()), Vector(radius, radius, radius), 0.0f});
    m_bodies.push_back(f);
    return f;
}

iPhysicsFrame* World::fixedBox(const Vector& centre, const Vector& half) {
    iPhysicsFrame* f = box(centre, half, 1.0f);
    f->getDynamics()->physicsType = PHYS_FixedInSpace;
    return f;
}

iPhysicsFrame* World::name(iPhysicsFrame* body, const std::string& name) {
    for (auto& n : m_names)
        if (n.first == name) return n.second = body;
    m_names.emplace_back(name, body);
    return body;
}

iPhysicsFrame* World::named(const std::string& name) const {
    for (const auto& n : m_names)
        if (n.first == name) return n.second;
    return nullptr;
}

void World::ground(float y) {
    m_shapes.push_back(CreateCPlane(nullptr, Vector(0, 1, 0), y));
    m_shapeInfo.push_back({Shape::Plane, -1, Vector(0, 1, 0), y});
}

float World::kineticEnergy() const {
    float e = 0;
    for (const RBDynamics* d : allDynamics()) {
        if (d->physicsType == PHYS_FixedInSpace || !(d->mass < INFINITE_MASS)) continue;
        e +=
            0.5f * d->mass * d->velocity.lengthSquared() + 0.5f * dot(d->angularVelocity, d->angularMomentum);
    }
    return e;
}

float World::mechanicalEnergy() const {
    float e = kineticEnergy();
    Vector g = settingsOf(m_scene)->getGravity();
    for (const RBDynamics* d : allDynamics()) {
        if (d->physicsType != PHYS_Falling || !(d->mass < INFINITE_MASS)) continue;
        e -= d->mass * dot(g, d->position);
    }
    return e;
}

float World::maxPenetration() const {
    float deepest = 0;
    const CollisionContact* c = m_space->getContactList();
    for (size_t i = 0; i < m_space->getNumContacts(); ++i) deepest = std::max(deepest, c[i].depth);
    return deepest;
}

bool World::allFinite() const {
    for (const RBDynamics* d : allDynamics()) {
        if (!d->position.isFinite() || !d->velocity.isFinite() || !d->angularVelocity.isFinite() ||
            !d->orientation.isFinite())
            return false;
    }
    return true;
}

float World::deepestBelow(float y) const {
    float below = 0;
    for (const RBDynamics* d : allDynamics()) below = std::max(below, y - d->position.y);
    return below;
}
