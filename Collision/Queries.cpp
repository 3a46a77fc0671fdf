// Queries.cpp - per-shape ray casts, point distances and the exact swept-sphere test.
#include "Narrowphase.h"

namespace gcol {

bool rayShape(const WorldShape& s, const Vector& o, const Vector& dir, float maxT, float& t, Vector& n) {
    switch (s.kind) {
    case ShapeKind::Sphere: {
        Vector m = o - s.sphere.centre;
        float b = dot(m, dir), c = dot(m, m) - s.sphere.radius * s.sphere.radius;
        if (c <= 0.0f) {
            t = 0.0f;
            n = -dir;
            return true;
        }
        if (b > 0.0f) return false;
        float disc = b * b - c;
        if (disc < 0.0f) return false;
        float th = -b - std::sqrt(disc);
        if (th > maxT) return false;
        t = std::fmax(0.0f, th);
        n = (o + dir * t - s.sphere.centre).normalize();
        return true;
    }
    case ShapeKind::Box: {
        const BoxShape& b = s.box;
        Vector lo = boxToLocal(b, o);
        Vector ld(dot(dir, b.axis[0]), dot(dir, b.axis[1]), dot(dir, b.axis[2]));
        bool inside = true;
        float tEnter = -3.4e38f, tExit = 3.4e38f;
        int axis = -1;
        float sign = 1.0f;
        for (int i = 0; i < 3; ++i) {
            float h = component(b.halfExtents, i), p = component(lo, i), d = component(ld, i);
            if (p > h || p < -h) inside = false;
            if (std::fabs(d) < 1e-12f) {
                if (p > h || p < -h) return false;
                continue;
            }
            float t1 = (-h - p) / d, t2 = (h - p) / d;
            float sg = -1.0f; // entering through the -h face when moving in +d
            if (t1 > t2) {
                std::swap(t1, t2);
                sg = 1.0f;
            }
            if (t1 > tEnter) tEnter = t1, axis = i, sign = sg;
            tExit = std::fmin(tExit, t2);
        }
        if (inside) {
            t = 0.0f;
            n = -dir;
            return true;
        }
        if (axis < 0 || tEnter > tExit || tExit < 0.0f || tEnter > maxT || tEnter < 0.0f) return false;
        t = tEnter;
        n = b.axis[axis] * sign;
        return true;
    }
    case ShapeKind::Plane: {
        float h = dot(s.plane.normal, o) - s.plane.offset;
        if (h < 0.0f) {
            t = 0.0f;
            n = -dir;
            return true;
        }
        float denom = dot(s.plane.normal, dir);
        if (denom >= 0.0f) return false;
        float th = -h / denom;
        if (th > maxT) return false;
        t = th;
        n = s.plane.normal;
        return true;
    }
    }
    return false;
}

float pointShapeDistance(const WorldShape& s, const Vector& p, Vector& closest) {
    switch (s.kind) {
    case ShapeKind::Sphere: {
        Vector d = p - s.sphere.centre;
        float len = d.length();
        Vector u = len > 0.0f ? d / len : Vector(0, 1, 0);
        closest = s.sphere.centre + u * s.sphere.radius;
        return len - s.sphere.radius;
    }
    case ShapeKind::Box: {
        const BoxShape& b = s.box;
        Vector l = boxToLocal(b, p), c = l;
        bool inside = true;
        for (int i = 0; i < 3; ++i) {
            float h = component(b.halfExtents, i), v = component(l, i);
            if (v > h) setComponent(c, i, h), inside = false;
            if (v < -h) setComponent(c, i, -h), inside = false;
        }
        if (!inside) {
            closest = boxToWorld(b, c);
            return (l - c).length();
        }
        int best = 0;
        float gap = b.halfExtents.x - std::fabs(l.x);
        for (int i = 1; i < 3; ++i) {
            float g = component(b.halfExtents, i) - std::fabs(component(l, i));
            if (g < gap) gap = g, best = i;
        }
        float h = component(b.halfExtents, best);
        setComponent(c, best, component(l, best) >= 0.0f ? h : -h);
        closest = boxToWorld(b, c);
        return -gap;
    }
    case ShapeKind::Plane: {
        float h = dot(s.plane.normal, p) - s.plane.offset;
        closest = p - s.plane.normal * h;
        return h;
    }
    }
    closest = p;
    return 0.0f;
}

bool sweepSphere(const WorldShape& s, const Vector& p0, const Vector& p1, float r, float& t) {
    // f(u) = signed distance from the centre at u to the shape, minus r. Signed distance to a convex set is
    // convex, and so is f along a line: a golden-section search finds its minimum, then bisection finds the
    // first root before it. About 70 distance evaluations, exact to float precision.
    Vector tmp;
    auto f = [&](float u) { return pointShapeDistance(s, p0 + (p1 - p0) * u, tmp) - r; };
    if (f(0.0f) <= 0.0f) return false;
    float hi;
    if (f(1.0f) <= 0.0f) {
        hi = 1.0f;
    } else {
        const float g = 0.381966f;
        float a = 0.0f, b = 1.0f;
        float x1 = a + g * (b - a), x2 = b - g * (b - a);
        float f1 = f(x1), f2 = f(x2);
        for (int i = 0; i < 40 && f1 > 0.0f && f2 > 0.0f; ++i) {
            if (f1 < f2) {
                b = x2, x2 = x1, f2 = f1;
                x1 = a + g * (b - a), f1 = f(x1);
            } else {
                a = x1, x1 = x2, f1 = f2;
                x2 = b - g * (b - a), f2 = f(x2);
            }
        }
        if (f1 > 0.0f && f2 > 0.0f) return false;
        hi = f1 <= 0.0f ? x1 : x2;
    }
    float lo = 0.0f;
    for (int i = 0; i < 32; ++i) {
        float mid = 0.5f * (lo + hi);
        if (f(mid) > 0.0f)
            lo = mid;
        else
            hi = mid;
    }
    t = lo;
    return true;
}

} // namespace gcol
