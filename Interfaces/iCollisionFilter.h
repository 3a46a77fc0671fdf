// iCollisionFilter.h - which geometry pairs collide (layers and masks), and sensor geometry that reports
// overlaps without pushing anything.
//
// Not part of the seed's iCollisionGeometry (a game's own geometry need not implement it); this package's
// geometries do, reached with filterOf(geometry). The rule, the same in every space of this package:
//  * two geometries are tested only when each one's layer bits meet the other's mask:
//    (a.layer & b.mask) != 0 && (b.layer & a.mask) != 0 (layersCollide). Defaults: layer 1, mask all bits,
//    so every pair collides until the game says otherwise. A filtered pair gives no contact, no HitWall, no
//    contact event, and the continuous stage's sweeps pass through it;
//  * a sensor (setSensor(true)) that passes the rule and overlaps another geometry at the poses of a
//    populateContactList gives no CollisionContact (nothing is pushed, nothing is slowed) and no HitWall: the
//    overlap is reported through contact events only (iContactEvents.h, with ContactPair::sensor set). A
//    sensor is tested at the current pose only (no sweep or sampling of the motion between calls).
// Changes take effect at the next populateContactList.
#pragma once

#include <cstdint>

#include "iCollisionGeometry.h"

class iCollisionFilter {
public:
    // The layers the geometry is in (bits; usually one). 0: in none, so it collides with nothing.
    virtual void setLayer(std::uint32_t layerBits) = 0;
    virtual std::uint32_t getLayer() const = 0;
    // The layers it collides with (bits).
    virtual void setMask(std::uint32_t maskBits) = 0;
    virtual std::uint32_t getMask() const = 0;
    // A sensor reports overlaps through contact events and never takes part in contact resolution.
    virtual void setSensor(bool sensor) = 0;
    virtual bool isSensor() const = 0;

protected:
    ~iCollisionFilter() = default; // part of a geometry: Delete() the geometry
};

// The rule above, for a game's own checks (and the tests' brute-force reference).
inline bool layersCollide(std::uint32_t layerA, std::uint32_t maskA, std::uint32_t layerB,
                          std::uint32_t maskB) {
    return (layerA & maskB) != 0 && (layerB & maskA) != 0;
}

// The filter of a geometry that has one; nullptr for any other (a game's own geometry).
inline iCollisionFilter* filterOf(iCollisionGeometry* geometry) {
    return dynamic_cast<iCollisionFilter*>(geometry);
}
inline const iCollisionFilter* filterOf(const iCollisionGeometry* geometry) {
    return dynamic_cast<const iCollisionFilter*>(geometry);
}
