// FuzzCalls.cpp - the fuzz walk's calls on live objects: dynamics, scene membership and settings, updates
// and time, geometry edits, callbacks and queries (World.h).
#include "World.h"
#include "iLifetime.h"

namespace fuzz {

void World::dynamics() {
    iRigidBody* b = anyBody();
    if (!b) return;
    RBDynamics& d = b->getDynamics();
    switch (pick(20)) {
    case 0:
        d.position = vec();
        break;
    case 1:
        d.velocity = vec();
        break;
    case 2:
        d.acceleration = vec();
        break;
    case 3:
        d.force = vec();
        break;
    case 4:
        d.temporalForce = vec();
        break;
    case 5:
        d.mass = value();
        break;
    case 6:
        d.dragCoefficient = value();
        break;
    case 7:
        d.restitution = value();
        break;
    case 8:
        d.friction = value();
        break;
    case 9:
        d.com = vec();
        break;
    case 10:
        d.physicsType = PhysicsType(pick(5) - 1);
        break; // -1 and 3 are not types: refused
    case 11:
        d.orientation = rotation();
        break;
    case 12:
        d.angularVelocity = vec();
        break;
    case 13:
        d.angularMomentum = vec();
        break;
    case 14:
        d.torque = vec();
        break;
    case 15:
        d.temporalTorque = vec();
        break;
    case 16: {
        Matrix t = pick(2) ? getBoxInertiaTensor(std::fabs(value()), vec()) : Matrix(value());
        if (pick(2))
            d.setInertiaTensor(t);
        else if (pick(2))
            d.setInverseInertiaTensor(pick(4) ? t : Matrix(0));
        else
            d.getInertiaTensor() = t; // written through the reference: validated before a step
        break;
    }
    case 17:
        d.useShapeInertia();
        break;
    case 18:
        d.ApplyImpulse(vec(), vec());
        break;
    default: {
        RBDynamics copy(d);
        copy.mass = value();
        copy.position = vec();
        b->setDynamics(copy);
        break;
    }
    }
}

void World::sceneMembership() {
    iPhysicsScene* s = any(m_scenes);
    iRigidBody* b = anyBody();
    if (!s || !b) return;
    switch (pick(4)) {
    case 0:
        s->add(b);
        break;
    case 1:
        s->remove(b);
        break;
    case 2:
        lifetimeOf(b)->kill(); // every body here is the simulator's (CreateRigidBody, clones, frames)
        break;
    default:
        lifetimeOf(b)->resetAlive();
        break;
    }
}

void World::update(Where where) {
    iPhysicsScene* s = any(m_scenes);
    if (!s) return;
    if (where != Where::Top) { // refused when a scene is mid-update
        s->update(now());
        return;
    }
    const int r = pick(40);
    if (r == 0)
        m_now -= pick(1000); // the clock went back: re-based
    else if (r == 1)
        m_now += 100000 + pick(1000000); // a long stall: capped
    else if (r == 2)
        m_now = pick(2) ? INT_MAX : INT_MIN; // the ends of `now`
    else if (m_now > INT_MAX / 2)
        m_now = 0; // back from the end: a re-base, then time flows again
    else
        m_now += pick(100);
    s->update(now());
}

int World::now() {
    m_now = std::min<long long>(INT_MAX, std::max<long long>(INT_MIN, m_now));
    return int(m_now);
}

void World::time() {
    iPhysicsScene* s = any(m_scenes);
    if (!s) return;
    switch (pick(3)) {
    case 0:
        s->suspend();
        break;
    case 1:
        s->restore(now());
        break;
    default:
        s->reset(now());
        break;
    }
}

void World::sceneSettings() {
    iPhysicsScene* s = any(m_scenes);
    if (!s) return;
    iPhysicsSceneSettings* set = settingsOf(s);
    switch (pick(8)) {
    case 0:
        set->setGravity(vec());
        break;
    case 1:
        set->setStepRate(pick(4) ? 30 + pick(300) : pick(2) ? 0 : 20000);
        break;
    case 2:
        set->setMaxStepsPerUpdate(pick(5));
        break;
    case 3:
        set->setIntegrator(Integrator(pick(7) - 1));
        break;
    case 4:
        set->setSolverIterations(pick(3) ? 1 + pick(20) : -3);
        break;
    case 5:
        set->setFrictionRule(CombineRule(pick(6) - 1));
        break;
    case 6:
        set->setRestitutionRule(CombineRule(pick(6) - 1));
        break;
    default:
        set->setSleepingEnabled(pick(2));
        break;
    }
}

void World::geometryEdits() {
    iCollisionGeometry* g = any(m_geoms);
    if (!g) return;
    switch (g->getCollisionType()) {
    case CT_SPHERE:
        if (pick(2)) static_cast<iCSphere*>(g)->setRadius(value());
        break;
    case CT_OBB:
        if (pick(2)) static_cast<iCOBB*>(g)->setRadius(vec());
        break;
    case CT_PLANE:
        if (pick(2)) static_cast<iCPlane*>(g)->setPlane(vec(), value());
        break;
    default:
        if (pick(3) == 0) static_cast<iCCompound*>(g)->clearChildren();
        break;
    }
    if (pick(2)) g->attach(pick(4) ? anyBody() : nullptr);
    float lo, hi;
    g->getProjectionBounds(vec(), lo, hi);
}

void World::hooks() {
    Hook* h = m_hooks[size_t(pick(int(m_hooks.size())))].get();
    iRigidBody* b = anyBody();
    iPhysicsScene* s = any(m_scenes);
    switch (pick(6)) {
    case 0:
        if (b) b->attachListener(h);
        break;
    case 1:
        if (b) b->detachListener(h);
        break;
    case 2:
        if (s) hooksOf(s)->addFixedUpdater(h);
        break;
    case 3:
        if (s) hooksOf(s)->removeFixedUpdater(h);
        break;
    case 4:
        if (s && b) hooksOf(s)->addForceGenerator(b, h);
        break;
    default:
        if (s && b) hooksOf(s)->removeForceGenerator(b, h);
        break;
    }
}

void World::queries() {
    iCollisionSpace* cs = any(m_spaces);
    if (!cs) return;
    if (pick(2)) cs->populateContactList(pick(2) ? 1.0f / 60 : value());
    if (iCollisionQueries* q = queriesOf(cs)) {
        RayHit hit;
        q->rayCast(vec(), vec(), value(), hit);
        std::vector<iCollisionGeometry*> out;
        q->overlapSphere(vec(), std::fabs(unit()) * 5, out);
    }
}

} // namespace fuzz
