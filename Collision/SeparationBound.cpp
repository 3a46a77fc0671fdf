// SeparationBound.cpp - a lower bound on the distance between two shapes, the step size of the shape cast's
// conservative advancement (SpaceShapeCast.cpp).
//
// Exact for sphere pairs and a sphere against a box; for two boxes the largest gap over the separating axes
// (3 + 3 face normals and 9 edge cross products), which never exceeds the true distance (a gap along any
// unit axis is a projection of the separation) and reaches it when faces approach faces. Against a plane,
// the shape's lowest point above the plane's surface.
#include "Narrowphase.h"

namespace gcol {
namespace {

float sphereBox(const SphereShape& s, const BoxShape& b, Vector& axis) {
    WorldShape w;
    w.kind = ShapeKind::Box;
    w.box = b;
    Vector q;
    float d = pointShapeDistance(w, s.centre, q);
    axis = (d > 0.0f ? q - s.centre : b.centre - s.centre).normalize();
    if (axis.lengthSquared() == 0.0f) axis = Vector(0, 1, 0);
    return d - s.radius;
}

float boxBox(const BoxShape& a, const BoxShape& b, Vector& axis) {
    const Vector between = b.centre - a.centre;
    float best = -3.4e38f;
    auto tryAxis = [&](Vector l) {
        float len = l.length();
        if (len < 1e-5f) return; // near-parallel edges: the face axes already cover that direction
        l = l / len;
        float c = dot(between, l);
        float gap = std::fabs(c) - boxProjectedRadius(a, l) - boxProjectedRadius(b, l);
        if (gap > best) {
            best = gap;
            axis = c >= 0.0f ? l : -l;
        }
    };
    for (int i = 0; i < 3; ++i) tryAxis(a.axis[i]);
    for (int i = 0; i < 3; ++i) tryAxis(b.axis[i]);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) tryAxis(cross(a.axis[i], b.axis[j]));
    return best;
}

float lowestAbovePlane(const WorldShape& s, const PlaneShape& p) {
    float c = s.kind == ShapeKind::Sphere ? dot(s.sphere.centre, p.normal) : dot(s.box.centre, p.normal);
    float r = s.kind == ShapeKind::Sphere ? s.sphere.radius : boxProjectedRadius(s.box, p.normal);
    return c - r - p.offset;
}

} // namespace

float separationBound(const WorldShape& a, const WorldShape& b, Vector& axis) {
    if (a.kind == ShapeKind::Plane && b.kind == ShapeKind::Plane) {
        axis = Vector(0, 1, 0);
        return 3.4e38f; // two planes never collide
    }
    if (b.kind == ShapeKind::Plane) {
        axis = -b.plane.normal;
        return lowestAbovePlane(a, b.plane);
    }
    if (a.kind == ShapeKind::Plane) {
        axis = a.plane.normal;
        return lowestAbovePlane(b, a.plane);
    }
    if (a.kind == ShapeKind::Sphere && b.kind == ShapeKind::Sphere) {
        Vector d = b.sphere.centre - a.sphere.centre;
        float len = d.length();
        axis = len > 0.0f ? d / len : Vector(0, 1, 0);
        return len - a.sphere.radius - b.sphere.radius;
    }
    if (a.kind == ShapeKind::Sphere) return sphereBox(a.sphere, b.box, axis);
    if (b.kind == ShapeKind::Sphere) {
        float d = sphereBox(b.sphere, a.box, axis);
        axis = -axis;
        return d;
    }
    return boxBox(a.box, b.box, axis);
}

} // namespace gcol
