// iCollisionQueries.h - questions a collision space answers about its geometry: ray casts and overlaps.
//
// Not part of the seed's iCollisionSpace (a game's own space need not implement it); the simple space
// does, reached with queriesOf(space). Queries look at every geometry of the space at its body's current
// pose; like populateContactList they ignore geometry without a body (except a bodiless plane) and geometry
// whose body's pose is not finite.
#pragma once

#include <vector>

#include "MathDeclarations.h"
#include "iCollisionSpace.h"

class iCollisionGeometry;

struct RayHit {
    iCollisionGeometry* geometry = nullptr; // the closest geometry hit
    Vector point;                           // world-space hit point
    Vector normal;                          // unit surface normal at the hit, facing the ray's origin side
    float distance = 0.0f; // along the (normalised) ray; 0 when the ray starts inside a shape
};

class iCollisionQueries {
public:
    // Closest hit along origin + t * direction, 0 <= t <= maxDistance (direction need not be unit; a zero
    // direction is refused with error()). True on a hit.
    virtual bool rayCast(const Vector& origin, const Vector& direction, float maxDistance, RayHit& hit) = 0;
    // Overlap queries: clear out, then fill it with every geometry that overlaps the given volume (each
    // geometry once). Return out.size().
    virtual size_t overlapSphere(const Vector& centre, float radius,
                                 std::vector<iCollisionGeometry*>& out) = 0;
    // orientation: row-vector rotation (box local -> world).
    virtual size_t overlapBox(const Vector& centre, const Matrix& orientation, const Vector& halfExtents,
                              std::vector<iCollisionGeometry*>& out) = 0;
    virtual size_t overlapAABB(const Vector& min, const Vector& max,
                               std::vector<iCollisionGeometry*>& out) = 0;

protected:
    ~iCollisionQueries() = default; // part of a space: Delete() the space
};

// The queries of a space that answers them (the simple space); nullptr for one that does not. A cross-cast
// to this public interface, not to the space's class: any implementation may provide it.
inline iCollisionQueries* queriesOf(iCollisionSpace* space) {
    return dynamic_cast<iCollisionQueries*>(space);
}
