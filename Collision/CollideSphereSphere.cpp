// CollideSphereSphere.cpp - sphere against sphere, in closed form.
#include "Narrowphase.h"

namespace gcol {

int collideSphereSphere(const SphereShape& a, const SphereShape& b, ContactManifold& out) {
    out.count = 0;
    Vector d = b.centre - a.centre;
    float r = a.radius + b.radius;
    float d2 = d.lengthSquared();
    if (d2 > r * r) return 0;
    float dist = std::sqrt(d2);
    // Coincident centres: any direction is a minimum translation; pick +y (up) so the result is finite.
    Vector n = dist > 1e-7f * r ? d / dist : Vector(0, 1, 0);
    ContactPoint& c = out.points[0];
    c.depth = r - dist;
    c.normal = n;
    c.pos = a.centre + n * (a.radius - 0.5f * c.depth);
    c.feature = 0;
    out.count = 1;
    return 1;
}

} // namespace gcol
