// CollidePlane.cpp - a one-sided infinite plane against a sphere or a box. Everything behind the plane is
// solid, so a shape that ended up wholly behind it still collides (a plane cannot be tunnelled through).
#include "ManifoldReduce.h"
#include "Narrowphase.h"

namespace gcol {

int collidePlaneSphere(const PlaneShape& a, const SphereShape& b, ContactManifold& out) {
    out.count = 0;
    float s = dot(a.normal, b.centre) - a.offset; // signed height of the centre above the plane
    if (s > b.radius) return 0;
    ContactPoint& c = out.points[0];
    c.normal = a.normal;
    c.depth = b.radius - s;
    // Midway between the sphere's lowest point and the plane.
    c.pos = b.centre - a.normal * (0.5f * (s + b.radius));
    c.feature = 0;
    out.count = 1;
    return 1;
}

int collidePlaneBox(const PlaneShape& a, const BoxShape& b, ContactManifold& out) {
    out.count = 0;
    ContactPoint candidates[8];
    int n = 0;
    for (int i = 0; i < 8; ++i) {
        Vector v = boxCorner(b, i);
        float s = dot(a.normal, v) - a.offset;
        if (s > 0.0f) continue;
        ContactPoint& c = candidates[n++];
        c.normal = a.normal;
        c.depth = -s;
        c.pos = v - a.normal * (0.5f * s);
        c.feature = unsigned(i);
    }
    reduceManifold(candidates, n, a.normal, out);
    return out.count;
}

} // namespace gcol
