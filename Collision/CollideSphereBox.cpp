// CollideSphereBox.cpp - sphere against box: closest point when the centre is outside, nearest face when the
// centre is inside (so a sphere swallowed by a box still gets the minimum translation).
#include "Narrowphase.h"

namespace gcol {

int collideSphereBox(const SphereShape& a, const BoxShape& b, ContactManifold& out) {
    out.count = 0;
    Vector local = boxToLocal(b, a.centre);
    Vector clamped = local;
    bool inside = true;
    for (int i = 0; i < 3; ++i) {
        float h = component(b.halfExtents, i), v = component(local, i);
        if (v > h) {
            setComponent(clamped, i, h);
            inside = false;
        } else if (v < -h) {
            setComponent(clamped, i, -h);
            inside = false;
        }
    }
    ContactPoint& c = out.points[0];
    if (!inside) {
        Vector diffLocal = clamped - local; // from the sphere centre to the box, local axes
        float d2 = diffLocal.lengthSquared();
        if (d2 > a.radius * a.radius) return 0;
        float dist = std::sqrt(d2);
        Vector q = boxToWorld(b, clamped);
        // Normalised in world space (the local distance and the world one differ by rounding).
        Vector n = dist > 1e-7f * a.radius ? (q - a.centre).normalize() : (b.centre - a.centre).normalize();
        if (n.lengthSquared() == 0.0f) n = Vector(0, 1, 0);
        c.depth = a.radius - dist;
        c.normal = n;
        c.pos = a.centre + n * (a.radius - 0.5f * c.depth);
        // Feature: which region of the box (face, edge, corner) the closest point lies in.
        unsigned f = 0;
        for (int i = 0; i < 3; ++i) {
            float v = component(local, i), h = component(b.halfExtents, i);
            f = f * 3 + (v > h ? 2u : v < -h ? 1u : 0u);
        }
        c.feature = f;
    } else {
        // Inside: leave through the nearest face. The box moves against that face's outward normal.
        int best = 0;
        float bestGap = component(b.halfExtents, 0) - std::fabs(local.x);
        for (int i = 1; i < 3; ++i) {
            float gap = component(b.halfExtents, i) - std::fabs(component(local, i));
            if (gap < bestGap) {
                bestGap = gap;
                best = i;
            }
        }
        float s = component(local, best) >= 0.0f ? 1.0f : -1.0f;
        Vector outward = b.axis[best] * s;
        c.normal = -outward;
        c.depth = bestGap + a.radius;
        // Midway between the box face point and the sphere's deepest point along the normal.
        Vector facePoint = a.centre + outward * bestGap;
        Vector deepest = a.centre + c.normal * a.radius;
        c.pos = (facePoint + deepest) * 0.5f;
        c.feature = 27u + unsigned(best * 2 + (s > 0 ? 1 : 0));
    }
    out.count = 1;
    return 1;
}

} // namespace gcol
