// Dispatch.cpp - the table of pair functions by shape kind, with a flip wrapper for mirrored pairs, and
// the per-shape bounds used by the broad phase.
#include "Narrowphase.h"

namespace gcol {
namespace {

using PairFn = int (*)(const WorldShape&, const WorldShape&, ContactManifold&, float lengthUnit);

int sphereSphere(const WorldShape& a, const WorldShape& b, ContactManifold& m, float) {
    return collideSphereSphere(a.sphere, b.sphere, m);
}
int sphereBox(const WorldShape& a, const WorldShape& b, ContactManifold& m, float) {
    return collideSphereBox(a.sphere, b.box, m);
}
int boxBox(const WorldShape& a, const WorldShape& b, ContactManifold& m, float lengthUnit) {
    return collideBoxBox(a.box, b.box, m, lengthUnit);
}
int planeSphere(const WorldShape& a, const WorldShape& b, ContactManifold& m, float) {
    return collidePlaneSphere(a.plane, b.sphere, m);
}
int planeBox(const WorldShape& a, const WorldShape& b, ContactManifold& m, float) {
    return collidePlaneBox(a.plane, b.box, m);
}
int none(const WorldShape&, const WorldShape&, ContactManifold& m, float) { return m.count = 0; }

// The function for (kind a, kind b) with a <= b in the order Sphere, Box, Plane ... except that the plane
// functions take the plane first; flipped[] says which entries need their arguments swapped.
template <PairFn F>
int flipped(const WorldShape& a, const WorldShape& b, ContactManifold& m, float lengthUnit) {
    int n = F(b, a, m, lengthUnit);
    for (int i = 0; i < n; ++i) m.points[i].normal = -m.points[i].normal;
    return n;
}

const PairFn kTable[kShapeKinds][kShapeKinds] = {
    /* Sphere */ {sphereSphere, sphereBox, flipped<planeSphere>},
    /* Box    */ {flipped<sphereBox>, boxBox, flipped<planeBox>},
    /* Plane  */ {planeSphere, planeBox, none},
};

} // namespace

int collideShapes(const WorldShape& a, const WorldShape& b, ContactManifold& out, float lengthUnit) {
    return kTable[int(a.kind)][int(b.kind)](a, b, out, lengthUnit);
}

bool shapeAabb(const WorldShape& s, Aabb& out) {
    switch (s.kind) {
    case ShapeKind::Sphere: {
        Vector r(s.sphere.radius, s.sphere.radius, s.sphere.radius);
        out.min = s.sphere.centre - r;
        out.max = s.sphere.centre + r;
        return true;
    }
    case ShapeKind::Box: {
        Vector e(boxProjectedRadius(s.box, Vector(1, 0, 0)), boxProjectedRadius(s.box, Vector(0, 1, 0)),
                 boxProjectedRadius(s.box, Vector(0, 0, 1)));
        out.min = s.box.centre - e;
        out.max = s.box.centre + e;
        return true;
    }
    case ShapeKind::Plane:
        break;
    }
    return false;
}

void shapeProjection(const WorldShape& s, const Vector& axis, float& min, float& max) {
    switch (s.kind) {
    case ShapeKind::Sphere: {
        float c = dot(s.sphere.centre, axis);
        min = c - s.sphere.radius;
        max = c + s.sphere.radius;
        return;
    }
    case ShapeKind::Box: {
        float c = dot(s.box.centre, axis), r = boxProjectedRadius(s.box, axis);
        min = c - r;
        max = c + r;
        return;
    }
    case ShapeKind::Plane: {
        // The half-space covers the whole line unless the axis is (anti)parallel to its normal.
        float k = dot(s.plane.normal, axis);
        const float inf = 3.4e38f;
        min = -inf;
        max = inf;
        if (k > 1.0f - 1e-6f) max = s.plane.offset;
        if (k < -1.0f + 1e-6f) min = -s.plane.offset;
        return;
    }
    }
}

bool shapesOverlap(const WorldShape& a, const WorldShape& b) {
    ContactManifold m;
    return collideShapes(a, b, m) > 0;
}

} // namespace gcol
