// iCollisionSpaceScale.h - the collision space's length unit: how many of the world's length units make a
// metre, so that its tolerances (which are lengths) follow a world built in centimetres or kilometres.
//
// Every tolerance of the spaces made by CreateSimpleCollisionSpace and CreateOctreeCollisionSpace is a
// metre figure times this unit: the octree space's fat-box margin (0.1 m), the shape cast's touch
// tolerance and skin (0.1 mm, 0.2 mm) and the box-box test's edge-axis bias (0.1 mm). Everything else is
// relative to the shapes' own sizes. A physics scene made by CreatePhysicsScene forwards its own unit
// (iPhysicsSceneSettings::setLengthUnitsPerMetre) to the space it is given and whenever the unit changes;
// a collision-only game sets it here. Not part of the seed's iCollisionSpace, so that a game's own space
// need not implement it; scaleOf(space) reaches it (nullptr for any other space).
#pragma once

#include "iCollisionSpace.h"

// The range of length units per metre a space or a scene accepts: a world in kilometres to one in
// millimetres (further out, float positions run out of digits for bodies of everyday size).
constexpr float MIN_LENGTH_UNITS_PER_METRE = 1e-3f;
constexpr float MAX_LENGTH_UNITS_PER_METRE = 1e3f;
// Whether u is such a unit (false for NaN and infinities).
inline bool validLengthUnit(float u) {
    return u >= MIN_LENGTH_UNITS_PER_METRE && u <= MAX_LENGTH_UNITS_PER_METRE;
}

class iCollisionSpaceScale {
public:
    // Length units per metre: 1 (the default) for a world in metres, 100 for one in centimetres, 0.001 for
    // one in kilometres. Refused with error() outside [1e-3, 1e3] or when not finite (the old unit kept).
    virtual bool setLengthUnitsPerMetre(float unitsPerMetre) = 0;
    virtual float getLengthUnitsPerMetre() const = 0;

protected:
    ~iCollisionSpaceScale() = default; // part of a space: Delete() the space
};

// The length unit of a space made by the library; nullptr for a space that has none (a game's own).
inline iCollisionSpaceScale* scaleOf(iCollisionSpace* space) {
    return dynamic_cast<iCollisionSpaceScale*>(space);
}
inline const iCollisionSpaceScale* scaleOf(const iCollisionSpace* space) {
    return dynamic_cast<const iCollisionSpaceScale*>(space);
}
