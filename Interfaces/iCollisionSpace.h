// iCollisionSpace.h - the interface to a collision space, the CollisionContact it produces, and the
// default space that new geometries join.
//
// A space holds geometries and, on populateContactList(delta), finds every touching pair. It is not a
// coordinator: call it when you want contacts (the physics scene calls it every step). The interface is
// exactly the seed's; what the simple space adds (ray and overlap queries, contact feature ids) is on
// interfaces of its own: iCollisionQueries.h, iContactFeatures.h.
#pragma once

#include <algorithm>
#include <cstddef>
#include <list>
#include <utility>
#include <vector>

#include "MathDeclarations.h"

class iCollisionGeometry;

// One contact point. Touching shapes give 1 to 4 consecutive contacts with the same g1, g2 and normal (a box
// face on a box or plane: the corners of the overlap area, whose average is its centre; a compound: one such
// group per touching child pair). Moving g2 by normal * depth separates the pair (the minimum translation).
// For a contact found by continuous sampling (see iSimpleCollisionSpace.h) pos, normal and depth describe
// the first touch along the motion.
struct CollisionContact {
    Vector pos;                  // contact position (world space, on the contact surface: midway between the
                                 // two surfaces along the normal)
    Vector normal;               // unit, world space, perpendicular to the contact surface; points at g2
    float depth;                 // penetration depth (>= 0)
    iCollisionGeometry *g1, *g2; // colliding geoms
};

class iCollisionSpace {
public:
    // execution functions
    virtual bool add(iCollisionGeometry* o) = 0;
    virtual void remove(iCollisionGeometry* o) = 0;
    virtual const std::list<iCollisionGeometry*>& getAttachedGeometry() = 0;
    // Collides every attached geometry with each other; clears, then rebuilds the contact list, then calls
    // the bodies' listeners (iCollisionListener.h). delta: seconds since the previous call (0 <= delta <=
    // infinity); 0 or infinity test the current poses only, otherwise motion since the previous call is
    // sampled as the space documents.
    virtual void populateContactList(float delta) = 0;
    virtual const CollisionContact* getContactList() const = 0;
    virtual size_t getNumContacts() const = 0;

    // termination functions
    virtual void suspend() const = 0;
    virtual void release() const = 0;
    virtual void Delete() const = 0;

protected:
    // Not deleted through the interface: call Delete().
    ~iCollisionSpace() = default;
};

namespace guardian_detail {
inline iCollisionSpace*& defaultCollisionSpaceSlot() {
    static iCollisionSpace* space = nullptr;
    return space;
}
} // namespace guardian_detail

// The space new geometries join on creation (nullptr: none). CollisionGeometry::setGlobalCollisionSpace and
// iPhysicsScene::setNewGlobalCollisionSpace both set it; this is where the two packages meet.
inline void setDefaultCollisionSpace(iCollisionSpace* cs) {
    guardian_detail::defaultCollisionSpaceSlot() = cs;
}
inline iCollisionSpace* getDefaultCollisionSpace() { return guardian_detail::defaultCollisionSpaceSlot(); }

// --- space lifetime: where the collision detector tells the simulator ---
// A space calls collisionSpaceDestroyed(cs) from Delete(), before it goes. A physics scene watches for it and
// forgets a space it was colliding in (as if setNewGlobalCollisionSpace(nullptr) had been called), so
// deleting the space before the scene is safe. The same pattern as watchRigidBodies (iRigidBody.h).
using CollisionSpaceWatcher = void (*)(const iCollisionSpace* dying, void* user);

namespace guardian_detail {
inline std::vector<std::pair<CollisionSpaceWatcher, void*>>& collisionSpaceWatchers() {
    static std::vector<std::pair<CollisionSpaceWatcher, void*>> watchers;
    return watchers;
}
} // namespace guardian_detail

inline void watchCollisionSpaces(CollisionSpaceWatcher w, void* user) {
    guardian_detail::collisionSpaceWatchers().emplace_back(w, user);
}
inline void unwatchCollisionSpaces(CollisionSpaceWatcher w, void* user) {
    auto& ws = guardian_detail::collisionSpaceWatchers();
    ws.erase(std::remove(ws.begin(), ws.end(), std::make_pair(w, user)), ws.end());
}
inline void collisionSpaceDestroyed(const iCollisionSpace* cs) {
    auto ws = guardian_detail::collisionSpaceWatchers(); // a copy: a watcher may unwatch itself
    for (auto& w : ws) w.first(cs, w.second);
}
