// CollidePlane.cpp - a one-sided infinite plane against a sphere or a box. Everything behind the plane is
// solid, so a shape that ended up wholly behind it still collides (a plane cannot be tunnelled through).
#include "ManifoldReduce.h"
#include "Narrowphase.h"

#include <cmath>

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
    // Most boxes are well above the plane: its lowest corner is the centre's height less the half extents
    // along the normal, and when that clears the plane by more than the corners' rounding none of them
    // touches (the loop below would find none).
    const Vector& h = b.halfExtents;
    const float lowest = dot(a.normal, b.centre) - a.offset - h.x * std::fabs(dot(a.normal, b.axis[0])) -
                         h.y * std::fabs(dot(a.normal, b.axis[1])) -
                         h.z * std::fabs(dot(a.normal, b.axis[2]));
    const float rounding = 1e-5f * (std::fabs(b.centre.x) + std::fabs(b.centre.y) + std::fabs(b.centre.z) +
                                    h.x + h.y + h.z + std::fabs(a.offset));
    if (lowest > rounding) return 0;
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
