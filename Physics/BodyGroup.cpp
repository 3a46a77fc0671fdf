// BodyGroup.cpp - a rope's or soft body's bodies handled together (BodyGroup.h).
#include "BodyGroup.h"

#include "RigidBody.h"
#include "iLifetime.h"
#include "iPhysicsScene.h"
#include "iUtilities.h"

#include <string>

namespace physics {

BodyGroup::BodyGroup() { watchRigidBodies(&BodyGroup::forget, this); }

BodyGroup::~BodyGroup() { unwatchRigidBodies(&BodyGroup::forget, this); }

iRigidBody* BodyGroup::makeBody(const Vector& p, float m, float r) {
    RigidBody* body = new RigidBody(nullptr); // not CreateRigidBody: that adds it to the active scene
    RBDynamics& d = body->getDynamics();
    d.mass = m;
    d.position = p;
    d.setInertiaTensor(getSphereInertiaTensor(m, r));
    body->snapshotValid();
    body->recordPreviousPose();
    body->recordStepPose();
    bodies.push_back(body);
    return body;
}

bool BodyGroup::addTo(iPhysicsScene* scene, const wchar_t* who) const {
    if (!scene) {
        error((std::wstring(who) + L"::addToScene: nullptr scene; refused").c_str());
        return false;
    }
    bool all = true;
    for (iRigidBody* body : bodies) {
        if (!body) {
            error((std::wstring(who) + L"::addToScene: a body was deleted; skipped").c_str());
            all = false;
        } else {
            all = scene->add(body) && all; // the scene says why when it refuses
        }
    }
    return all;
}

void BodyGroup::killAll() const {
    for (iRigidBody* body : bodies)
        if (body) lifetimeOf(body)->kill();
}

void BodyGroup::deleteAll() const {
    for (iRigidBody* body : bodies)
        if (body) body->Delete(); // waits for the end of a running step by itself
}

void BodyGroup::forget(const iRigidBody* destroyed, void* group) {
    for (iRigidBody*& body : static_cast<BodyGroup*>(group)->bodies)
        if (body == destroyed) body = nullptr;
}

} // namespace physics
