// iCollisionQueries.h - what a collision space's queries return: the closest ray hit.
//
// Queries (iCollisionSpace::rayCast, overlapSphere, overlapBox, overlapAABB) look at every geometry of the
// space at its body's current pose; like populateContactList they ignore geometry without a body (except a
// bodiless plane) and geometry whose body's pose is not finite.
#pragma once

#include "MathDeclarations.h"

class iCollisionGeometry;

struct RayHit {
    iCollisionGeometry* geometry = nullptr; // the closest geometry hit
    Vector point;                           // world-space hit point
    Vector normal;                          // unit surface normal at the hit, facing the ray's origin side
    float distance = 0.0f; // along the (normalised) ray; 0 when the ray starts inside a shape
};
