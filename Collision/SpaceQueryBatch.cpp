// SpaceQueryBatch.cpp - batches of queries (iCollisionQueries.h): a query outside a batch brings the
// broadphase up to date with every geometry's current pose first (nothing tells a space that a body moved);
// inside one, the first query does it for all, and endQueries() checks the promise that nothing moved.
#include "Broadphase.h"
#include "SimpleCollisionSpace.h"
#include "iRigidBody.h"
#include "iUtilities.h"

#include <algorithm>

void SimpleCollisionSpace::prepareQuery() {
    settleRemovals();
    if (m_batchDepth > 0 && m_queriesSynced) return;
    m_broadphase->syncQueries(m_members, m_entries);
    m_queriesSynced = m_batchDepth > 0;
}

void SimpleCollisionSpace::beginQueries() {
    if (m_batchDepth++ > 0) return; // nested: the outermost batch holds
    settleRemovals();
    m_queriesSynced = false;
    m_batchPoses.clear();
    for (const CollisionGeometry* g : m_members) {
        BatchPose p;
        p.order = g->spaceState().order;
        p.body = g->body();
        p.shapeVersion = g->shapeVersion();
        p.posed = g->currentPose(p.origin, p.rotation);
        m_batchPoses.push_back(p);
    }
}

bool SimpleCollisionSpace::batchMoved() const {
    // Members are in join order, as the poses were recorded: a member that joined since has a later order
    // than any recorded, one that left is simply not found.
    size_t at = 0;
    for (const CollisionGeometry* g : m_members) {
        if (!g) continue;
        const unsigned long long order = g->spaceState().order;
        while (at < m_batchPoses.size() && m_batchPoses[at].order < order) ++at;
        if (at == m_batchPoses.size()) break;
        const BatchPose& was = m_batchPoses[at];
        if (was.order != order) continue; // joined inside the batch
        Vector o;
        Matrix r(1);
        const bool posed = g->currentPose(o, r);
        if (was.body != g->body() || was.shapeVersion != g->shapeVersion() || was.posed != posed ||
            (posed && (o != was.origin || r != was.rotation)))
            return true;
    }
    return false;
}

void SimpleCollisionSpace::endQueries() {
    if (m_batchDepth == 0) {
        error(L"iCollisionQueries::endQueries: no batch was begun; ignored");
        return;
    }
    if (--m_batchDepth > 0) return;
    m_queriesSynced = false;
    if (batchMoved())
        error(L"iCollisionQueries::endQueries: geometry moved or changed inside a query batch; the queries "
              L"after the change may have looked for it where it was (move nothing between beginQueries and "
              L"endQueries)");
    m_batchPoses.clear();
}
