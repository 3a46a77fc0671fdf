// iCollisionSpace.h - the interface to a collision space, the CollisionContact it produces, and the
// default space that new geometries join.
//
// A space holds geometries and, on populateContactList(delta), finds every touching pair. It is not a
// coordinator: call it when you want contacts (the physics scene calls it every step).
#pragma once

#include <cstddef>
#include <list>

#include "MathDeclarations.h"

class iCollisionGeometry;

struct CollisionContact {
    Vector pos;                  // contact position (world space, on the contact surface)
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
    // Collides every attached geometry with each other; clears, then rebuilds the contact list.
    // delta: seconds since the previous call (0 <= delta <= infinity).
    virtual void populateContactList(float delta) = 0;
    virtual const CollisionContact* getContactList() const = 0;
    virtual size_t getNumContacts() const = 0;
    // termination functions
    virtual void suspend() const = 0;
    virtual void release() const = 0;
    virtual void Delete() const = 0;
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
