// Narrowphase.h - the pure pair tests, the dispatch table over shape kinds, ray casts and the exact sweep.
//
// Each collideXY(a, b, out) fills out with 0..4 contact points (see ContactPoint: normal from a to b, depth
// the minimum translation, pos midway between the surfaces) and returns the count. They read nothing but
// their arguments, so they are tested without a space (tests/collision/NarrowphaseTest.cpp).
#pragma once

#include "Shapes.h"

namespace gcol {

int collideSphereSphere(const SphereShape& a, const SphereShape& b, ContactManifold& out);
int collideSphereBox(const SphereShape& a, const BoxShape& b, ContactManifold& out);
// Separating axis theorem over the 15 axes (normalised; near-parallel edge pairs skipped), then a manifold
// of up to 4 points by clipping the incident face against the reference face (or one edge-edge point).
// lengthUnit: the world's length units per metre (iCollisionSpaceScale.h), for the edge axes' 0.1 mm bias.
int collideBoxBox(const BoxShape& a, const BoxShape& b, ContactManifold& out, float lengthUnit = 1.0f);
int collidePlaneSphere(const PlaneShape& a, const SphereShape& b, ContactManifold& out);
int collidePlaneBox(const PlaneShape& a, const BoxShape& b, ContactManifold& out);

// Any two shapes (mirrored pairs are computed once and flipped: normals negated, features kept).
// Two planes never collide (both are static). lengthUnit as for collideBoxBox.
int collideShapes(const WorldShape& a, const WorldShape& b, ContactManifold& out, float lengthUnit = 1.0f);

// Ray cast: origin + t * dir (dir unit), 0 <= t <= maxT. On a hit sets t, the surface normal (pointing out
// of the shape, toward the ray's origin side) and returns true. A ray starting inside reports t = 0 and
// normal = -dir.
bool rayShape(const WorldShape& s, const Vector& origin, const Vector& dir, float maxT, float& t, Vector& n);

// Distance from a point to a shape's surface (negative inside) and the closest surface point.
float pointShapeDistance(const WorldShape& s, const Vector& p, Vector& closest);

// Exact sweep of a sphere of radius r whose centre moves from p0 to p1 (relative to shape s, which is held
// still): the first fraction t in [0, 1] at which the sphere touches s. Returns false when it never does or
// when it already touches at t = 0.
bool sweepSphere(const WorldShape& s, const Vector& p0, const Vector& p1, float r, float& t);

// A lower bound on the distance between two shapes (negative when they overlap) and the unit axis it was
// measured along, from a toward b (SeparationBound.cpp says how tight it is per pair).
float separationBound(const WorldShape& a, const WorldShape& b, Vector& axis);

// True when the shapes overlap (a cheap test used by the overlap queries).
bool shapesOverlap(const WorldShape& a, const WorldShape& b);

} // namespace gcol
