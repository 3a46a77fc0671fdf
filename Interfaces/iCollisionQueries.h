// iCollisionQueries.h - questions a collision space answers about its geometry: ray casts and overlaps.
//
// Not part of the seed's iCollisionSpace (a game's own space need not implement it); the simple space
// does, reached with queriesOf(space). Queries look at every geometry of the space at its body's current
// pose; like populateContactList they ignore geometry without a body (except a bodiless plane) and geometry
// whose body's pose is not finite.
//
// A space cannot tell that a body moved without reading it (a game writes RBDynamics directly), so each query
// first looks at every geometry's body: O(N) a query even where a tree answers in O(log N). A batch
// (beginQueries ... endQueries, or a QueryBatch in scope) does that once for all the queries in it: the game
// promises that nothing moves inside it.
#pragma once

#include <vector>

#include "MathDeclarations.h"
#include "iCollisionSpace.h"

class iCollisionGeometry;

struct RayHit {
    iCollisionGeometry* geometry = nullptr; // the closest geometry hit
    Vector point;                           // world-space hit point
    Vector normal;                          // unit surface normal at the hit, facing the ray's origin side
    float distance = 0.0f; // along the (normalised) ray; 0 when the ray starts inside a shape
};

class iCollisionQueries {
public:
    // Closest hit along origin + t * direction, 0 <= t <= maxDistance (direction need not be unit; a zero
    // direction is refused with error()). True on a hit.
    virtual bool rayCast(const Vector& origin, const Vector& direction, float maxDistance, RayHit& hit) = 0;
    // Overlap queries: clear out, then fill it with every geometry that overlaps the given volume (each
    // geometry once). Return out.size().
    virtual size_t overlapSphere(const Vector& centre, float radius,
                                 std::vector<iCollisionGeometry*>& out) = 0;
    // orientation: row-vector rotation (box local -> world).
    virtual size_t overlapBox(const Vector& centre, const Matrix& orientation, const Vector& halfExtents,
                              std::vector<iCollisionGeometry*>& out) = 0;
    virtual size_t overlapAABB(const Vector& min, const Vector& max,
                               std::vector<iCollisionGeometry*>& out) = 0;

    // A batch of queries. Between beginQueries() and endQueries() the game promises that no body or geometry
    // of the space moves or is reshaped; the space then looks at every geometry once, at beginQueries(), and
    // each query costs what its candidates cost (the octree space: O(log N + hits) instead of O(N); the
    // simple space: a box compare a geometry instead of an exact test). Queries answer as outside a batch
    // while the promise holds. Geometry may join or leave inside a batch (the next query looks at every
    // geometry again). endQueries() checks the promise, O(N) once: a geometry
    // whose pose or shapes changed since beginQueries() is reported with error(), as the queries after the
    // change may have looked for it where it was. Batches nest (the outermost one counts); an endQueries()
    // without a beginQueries() is refused with error(). The space's Delete() inside a batch is reported with
    // error() and done when the outermost batch ends (the space answers until then), so that a QueryBatch
    // still in scope never ends a deleted space. A space without batches (a game's own) answers every query
    // on its own: these do nothing.
    virtual void beginQueries() {}
    virtual void endQueries() {}

protected:
    ~iCollisionQueries() = default; // part of a space: Delete() the space
};

// A batch of queries for the lifetime of this object (beginQueries() now, endQueries() when it goes out of
// scope); q may be nullptr. A space deleted inside a batch says so with error() and goes when the batch ends.
class QueryBatch {
public:
    explicit QueryBatch(iCollisionQueries* q) : m_queries(q) {
        if (m_queries) m_queries->beginQueries();
    }
    ~QueryBatch() {
        if (m_queries) m_queries->endQueries();
    }
    QueryBatch(const QueryBatch&) = delete;
    QueryBatch& operator=(const QueryBatch&) = delete;

private:
    iCollisionQueries* m_queries;
};

// The queries of a space that answers them (the simple space); nullptr for one that does not. A cross-cast
// to this public interface, not to the space's class: any implementation may provide it.
inline iCollisionQueries* queriesOf(iCollisionSpace* space) {
    return dynamic_cast<iCollisionQueries*>(space);
}
