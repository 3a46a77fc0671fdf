// Shapes.h - collision shapes as plain data in world space, and the contact points pair tests produce.
//
// Every narrowphase function is a pure function of two of these (no bodies, no spaces), so each pair can be
// tested alone. A geometry turns its body's pose into one or more WorldShapes (a compound gives several).
#pragma once

#include "MathDeclarations.h"

#include <cmath>

namespace gcol {

enum class ShapeKind : unsigned char { Sphere = 0, Box = 1, Plane = 2 };
constexpr int kShapeKinds = 3;

struct SphereShape {
    Vector centre;
    float radius = 0.0f;
};

// A box: axis[i] is the box's local axis i in world space (row i of the row-vector rotation matrix), so a
// local point p maps to centre + p.x axis[0] + p.y axis[1] + p.z axis[2].
struct BoxShape {
    Vector centre;
    Vector axis[3] = {Vector(1, 0, 0), Vector(0, 1, 0), Vector(0, 0, 1)};
    Vector halfExtents;
};

// A one-sided infinite plane: the solid is every point p with dot(normal, p) < offset. normal is unit and
// points into free space.
struct PlaneShape {
    Vector normal = Vector(0, 1, 0);
    float offset = 0.0f;
};

// One shape of a geometry, at one pose. Only the member named by kind is meaningful.
struct WorldShape {
    ShapeKind kind = ShapeKind::Sphere;
    SphereShape sphere;
    BoxShape box;
    PlaneShape plane;
};

// A contact point. normal is unit and points from the first shape to the second; moving the second shape by
// normal * depth separates the two (depth is the minimum translation). pos lies midway between the two
// surfaces along the normal. feature identifies which features touch (stable while they keep touching), for
// warm starting a solver.
struct ContactPoint {
    Vector pos;
    Vector normal;
    float depth = 0.0f;
    unsigned feature = 0;
};

constexpr int kMaxManifoldPoints = 4;
struct ContactManifold {
    ContactPoint points[kMaxManifoldPoints];
    int count = 0;
};

struct Aabb {
    Vector min, max;
};

// --- small helpers shared by the pair functions ---
inline Vector boxToLocal(const BoxShape& b, const Vector& p) {
    Vector d = p - b.centre;
    return Vector(dot(d, b.axis[0]), dot(d, b.axis[1]), dot(d, b.axis[2]));
}
inline Vector boxToWorld(const BoxShape& b, const Vector& l) {
    return b.centre + b.axis[0] * l.x + b.axis[1] * l.y + b.axis[2] * l.z;
}
inline float component(const Vector& v, int i) { return i == 0 ? v.x : i == 1 ? v.y : v.z; }
inline void setComponent(Vector& v, int i, float s) { (i == 0 ? v.x : i == 1 ? v.y : v.z) = s; }
// Half the box's extent along a unit axis.
inline float boxProjectedRadius(const BoxShape& b, const Vector& n) {
    return b.halfExtents.x * std::fabs(dot(b.axis[0], n)) + b.halfExtents.y * std::fabs(dot(b.axis[1], n)) +
           b.halfExtents.z * std::fabs(dot(b.axis[2], n));
}
// Corner i (bits 0..2 choose the sign along axis 0..2).
inline Vector boxCorner(const BoxShape& b, int i) {
    return boxToWorld(b, Vector(i & 1 ? b.halfExtents.x : -b.halfExtents.x,
                                i & 2 ? b.halfExtents.y : -b.halfExtents.y,
                                i & 4 ? b.halfExtents.z : -b.halfExtents.z));
}

// The point of a sphere or box farthest along dir (its support point: where it first meets what lies that
// way). Not for a plane (unbounded).
inline Vector supportPoint(const WorldShape& s, const Vector& dir) {
    if (s.kind == ShapeKind::Sphere) return s.sphere.centre + dir * s.sphere.radius;
    const BoxShape& b = s.box;
    return boxToWorld(b, Vector(dot(b.axis[0], dir) < 0.0f ? -b.halfExtents.x : b.halfExtents.x,
                                dot(b.axis[1], dir) < 0.0f ? -b.halfExtents.y : b.halfExtents.y,
                                dot(b.axis[2], dir) < 0.0f ? -b.halfExtents.z : b.halfExtents.z));
}

// Bounds of a shape; a plane has none (infinite) and returns false.
bool shapeAabb(const WorldShape& s, Aabb& out);
// The interval a shape covers along a unit axis (a plane: the whole line unless the axis is its normal).
void shapeProjection(const WorldShape& s, const Vector& axis, float& min, float& max);

} // namespace gcol
