// SpaceQueryBatch.cpp - batches of queries (iCollisionQueries.h): a query outside a batch brings the
// broadphase up to date with every geometry's current pose first (nothing tells a space that a body moved);
// a batch does it once, at its start (again only after geometry joined or left, or a call), and
// endQueries() checks the promise that nothing moved.
#include "Broadphase.h"
#include "PoseInputs.h"
#include "SimpleCollisionSpace.h"
#include "iRigidBody.h"
#include "iUtilities.h"

void SimpleCollisionSpace::prepareQuery() {
    settleRemovals();
    if (m_batchDepth > 0 && m_queriesSynced) return;
    m_broadphase->syncQueries(m_members, m_entries, m_batchDepth > 0);
    m_queriesSynced = m_batchDepth > 0;
}

SimpleCollisionSpace::BatchPose SimpleCollisionSpace::batchPoseOf(const CollisionGeometry& g) {
    BatchPose p;
    p.order = g.spaceState().order;
    p.body = g.body();
    p.shapeVersion = g.shapeVersion();
    const RBDynamics* d = p.body ? &p.body->getDynamics() : nullptr;
    p.raw = d && !d->attachedTo();
    if (p.raw) { // what its pose is made of, without working the pose out (PoseInputs.h)
        p.pose.store(*d);
        return p;
    }
    Vector origin;
    Matrix rotation(1);
    p.posed = g.currentPose(origin, rotation);
    p.pose.position = p.posed ? origin : Vector();
    const float* r = rotation.data();
    for (int i = 0; i < 3; ++i)
        p.pose.rows[i] = p.posed ? Vector(r[4 * i], r[4 * i + 1], r[4 * i + 2]) : Vector();
    return p;
}

void SimpleCollisionSpace::beginQueries() {
    if (m_batchDepth++ > 0) return; // nested: the outermost batch holds
    settleRemovals();
    m_batchPoses.clear();
    for (const CollisionGeometry* g : m_members) m_batchPoses.push_back(batchPoseOf(*g));
    // The broadphase synced now, while what it reads of each geometry is still in cache.
    m_broadphase->syncQueries(m_members, m_entries, true);
    m_queriesSynced = true;
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
        const BatchPose now = batchPoseOf(*g);
        if (now.body != was.body || now.shapeVersion != was.shapeVersion || now.raw != was.raw ||
            now.posed != was.posed || !gcol::sameWords<15>(&now.pose, &was.pose))
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
    if (!m_deleteAfterBatch) return;
    m_deleteAfterBatch = false;
    if (m_notifying || m_populating) // the batch ended in a listener: the space cannot go from under it
        error(L"iCollisionSpace::Delete (at the query batch's end): refused while the space is notifying "
              L"listeners");
    else
        destroy(); // Delete() came inside the batch
}
