// BodyGroup.h - the bodies a rope or a soft body made, handled together: made in no scene, added to a
// scene, killed, deleted. A scene's Delete() deletes the bodies in it, so the group watches its bodies'
// destruction (watchRigidBodies): one deleted by anyone else reads nullptr from then on and is never deleted
// twice.
#pragma once

#include "iRigidBody.h"

#include <vector>

class iPhysicsScene;

namespace physics {

class BodyGroup {
public:
    BodyGroup();
    ~BodyGroup();
    BodyGroup(const BodyGroup&) = delete;
    BodyGroup& operator=(const BodyGroup&) = delete;

    // A point-like body of mass m at p (the inertia of a solid sphere of radius r), in no scene, its
    // bookkeeping started at p (as a body made at its frame's pose); it joins the group.
    iRigidBody* makeBody(const Vector& p, float m, float r);
    // Adds every body to scene; false (error() naming who) for nullptr or a body deleted since.
    bool addTo(iPhysicsScene* scene, const wchar_t* who) const;
    void killAll() const;
    void deleteAll() const;
    std::vector<iRigidBody*> bodies; // in the order made; nullptr once deleted elsewhere

private:
    static void forget(const iRigidBody* destroyed, void* group);
};

} // namespace physics
