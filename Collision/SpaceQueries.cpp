// SpaceQueries.cpp - ray casts and overlap queries of the space: its broadphase names the candidates (every
// geometry for sort-and-sweep, the tree's hits for the octree space), in the space's order; each is tested
// exactly against its shapes at its body's current pose.
#include "Broadphase.h"
#include "SimpleCollisionSpace.h"
#include "iUtilities.h"

#include <cmath>

bool SimpleCollisionSpace::queryShapes(CollisionGeometry* g, std::vector<gcol::WorldShape>& out) {
    out.clear();
    const CollisionGeometry::SpaceState& st = g->spaceState();
    if (st.pendingDelete || st.pendingRemove) return false;
    if (!g->body() && !g->isPlane()) return false;
    Vector o;
    Matrix r(1);
    if (!g->currentPose(o, r)) return false;
    g->worldShapes(o, r, out);
    return !out.empty();
}

bool SimpleCollisionSpace::rayCast(const Vector& origin, const Vector& direction, float maxDistance,
                                   RayHit& hit) {
    prepareQuery();
    float len = direction.length();
    if (!origin.isFinite() || !direction.isFinite() || !(len > 0.0f) || std::isnan(maxDistance)) {
        error(L"iCollisionSpace::rayCast: origin and direction must be finite, direction non-zero");
        return false;
    }
    if (maxDistance < 0.0f) return false;
    Vector dir = direction / len;
    float best = maxDistance;
    bool found = false;
    std::vector<gcol::WorldShape>& shapes = m_scratchA;
    m_broadphase->rayCandidates(m_members, origin, dir, maxDistance, m_candidates);
    for (CollisionGeometry* g : m_candidates) {
        if (!queryShapes(g, shapes)) continue;
        iCollisionGeometry* ig = g->asInterface();
        for (const gcol::WorldShape& s : shapes) {
            float t;
            Vector n;
            if (gcol::rayShape(s, origin, dir, best, t, n) && (!found || t < best)) {
                found = true;
                best = t;
                hit.geometry = ig;
                hit.distance = t;
                hit.point = origin + dir * t;
                hit.normal = n;
            }
        }
    }
    return found;
}

namespace {

size_t overlapWith(SimpleCollisionSpace& space, const std::vector<CollisionGeometry*>& candidates,
                   const gcol::WorldShape& query, std::vector<gcol::WorldShape>& shapes,
                   bool (SimpleCollisionSpace::*get)(CollisionGeometry*, std::vector<gcol::WorldShape>&),
                   std::vector<iCollisionGeometry*>& out) {
    out.clear();
    for (CollisionGeometry* g : candidates) {
        if (!(space.*get)(g, shapes)) continue;
        for (const gcol::WorldShape& s : shapes)
            if (gcol::shapesOverlap(query, s)) {
                out.push_back(g->asInterface());
                break;
            }
    }
    return out.size();
}

} // namespace

size_t SimpleCollisionSpace::overlapSphere(const Vector& centre, float radius,
                                           std::vector<iCollisionGeometry*>& out) {
    prepareQuery();
    if (!centre.isFinite() || !(std::isfinite(radius) && radius >= 0.0f)) {
        error(L"iCollisionSpace::overlapSphere: centre and radius must be finite, radius >= 0");
        out.clear();
        return 0;
    }
    gcol::WorldShape q;
    q.kind = gcol::ShapeKind::Sphere;
    q.sphere.centre = centre;
    q.sphere.radius = radius;
    gcol::Aabb box;
    gcol::shapeAabb(q, box);
    m_broadphase->overlapCandidates(m_members, box, m_candidates);
    return overlapWith(*this, m_candidates, q, m_scratchA, &SimpleCollisionSpace::queryShapes, out);
}

size_t SimpleCollisionSpace::overlapBox(const Vector& centre, const Matrix& orientation,
                                        const Vector& halfExtents, std::vector<iCollisionGeometry*>& out) {
    prepareQuery();
    if (!centre.isFinite() || !isRotation(orientation, 1e-3f) || !halfExtents.isFinite() ||
        halfExtents.x < 0 || halfExtents.y < 0 || halfExtents.z < 0) {
        error(L"iCollisionSpace::overlapBox: needs a finite centre, a rotation and half extents >= 0");
        out.clear();
        return 0;
    }
    gcol::WorldShape q;
    q.kind = gcol::ShapeKind::Box;
    q.box.centre = centre;
    q.box.axis[0] = orientation.direction('x');
    q.box.axis[1] = orientation.direction('y');
    q.box.axis[2] = orientation.direction('z');
    q.box.halfExtents = halfExtents;
    gcol::Aabb box;
    gcol::shapeAabb(q, box);
    m_broadphase->overlapCandidates(m_members, box, m_candidates);
    return overlapWith(*this, m_candidates, q, m_scratchA, &SimpleCollisionSpace::queryShapes, out);
}

size_t SimpleCollisionSpace::overlapAABB(const Vector& min, const Vector& max,
                                         std::vector<iCollisionGeometry*>& out) {
    settleRemovals();
    if (!min.isFinite() || !max.isFinite() || max.x < min.x || max.y < min.y || max.z < min.z) {
        error(L"iCollisionSpace::overlapAABB: min and max must be finite with min <= max");
        out.clear();
        return 0;
    }
    return overlapBox((min + max) * 0.5f, Matrix(1), (max - min) * 0.5f, out);
}
