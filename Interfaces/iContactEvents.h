// iContactEvents.h - contact begin, persist and end per body pair, for observers attached to a space.
//
// Not part of the seed's iCollisionSpace (a game's own space need not implement it); this package's spaces
// do, reached with contactEventsOf(space). Beside HitWall (iCollisionListener.h, every frame two bodies
// touch), an observer hears when a pair starts touching (onBegin), goes on touching (onPersist) and stops
// (onEnd). Events come when HitWall does (iCollisionEvents.h): with a physics scene, once per update() after
// its steps, a pair counting as touching in an update when it touched in any of its steps (so begin and end
// never flicker across the sub-steps of one update); without one, at the end of each populateContactList.
// Rules:
//  * a pair is two bodies (all geometries of one body count once); a geometry without a body (a plane) is
//    its own side. A sensor overlap (iCollisionFilter.h) is a pair of its own, apart from a solid contact
//    of the same two bodies: ContactPair::sensor tells them apart;
//  * a pair resting (both asleep or fixed) stays touching: sleeping never ends a pair;
//  * a pair ends when the bodies stop touching or a side goes (its geometry leaves the space or its body is
//    destroyed): onEnd then names the side that went as nullptr;
//  * an observer attached while pairs touch hears onBegin for each at its first delivery: every observer
//    hears onBegin, then onPersist on every later delivery while touching, then onEnd once;
//  * an observer destroyed without detaching is never called again: ContactObserver's destructor detaches
//    it from every space it is attached to. A space deleted first detaches its observers.
// Observers may do during a call what a HitWall listener may (detach or destroy observers, remove or delete
// geometry, delete bodies): changes take effect safely, and an observer detached meanwhile is not called.
#pragma once

#include <algorithm>
#include <vector>

#include "MathDeclarations.h"
#include "iCollisionSpace.h"

class iRigidBody;
class iCollisionGeometry;

struct ContactPair {
    iRigidBody* bodyA = nullptr; // nullptr: a side without a body (a plane), or destroyed (onEnd)
    iRigidBody* bodyB = nullptr;
    iCollisionGeometry* geometryA = nullptr; // a geometry of that side that touched (nullptr: left the space)
    iCollisionGeometry* geometryB = nullptr;
    bool sensor = false; // an overlap involving a sensor: no contact response
    Vector normal;       // unit, world space, from A toward B, at the latest contact
    Vector point;        // world space: the latest contact's centre
};

class iContactEvents;

// What a game derives its observers from: every function does nothing unless overridden.
class ContactObserver {
public:
    virtual void onBegin(const ContactPair&) {}
    virtual void onPersist(const ContactPair&) {}
    virtual void onEnd(const ContactPair&) {}

    ContactObserver() = default;
    ContactObserver(const ContactObserver&) = delete; // attachment is per object
    ContactObserver& operator=(const ContactObserver&) = delete;
    // Detaches from every space it is still attached to: a destroyed observer is never called.
    virtual ~ContactObserver();

private:
    friend class ContactObserverLinks;
    std::vector<iContactEvents*> m_sources; // the spaces it is attached to
};

class iContactEvents {
public:
    // Attaches an observer (false: null, or already attached: refused with error()).
    virtual bool addObserver(ContactObserver* observer) = 0;
    // Detaches it (false: it was not attached). Safe during a call.
    virtual bool removeObserver(ContactObserver* observer) = 0;

protected:
    ~iContactEvents() = default; // part of a space: Delete() the space
};

// For implementations of iContactEvents: keep an observer's list of spaces in step with the space's own.
class ContactObserverLinks {
public:
    static void linked(ContactObserver* o, iContactEvents* source) { o->m_sources.push_back(source); }
    static void unlinked(ContactObserver* o, iContactEvents* source) {
        auto& s = o->m_sources;
        s.erase(std::remove(s.begin(), s.end(), source), s.end());
    }
};

inline ContactObserver::~ContactObserver() {
    std::vector<iContactEvents*> sources;
    sources.swap(m_sources); // removeObserver unlinks from a list that is already empty
    for (iContactEvents* s : sources) s->removeObserver(this);
}

// The contact events of a space that has them; nullptr for any other (a game's own space).
inline iContactEvents* contactEventsOf(iCollisionSpace* space) {
    return dynamic_cast<iContactEvents*>(space);
}
