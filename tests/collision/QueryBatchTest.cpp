// QueryBatchTest.cpp - batches of queries (iCollisionQueries.h): inside one the octree space reads each body
// once, not once a query, and answers as outside it; a body moved inside a batch is reported when it ends;
// geometry may join and leave inside one; batches nest, and an end without a begin is refused; a space
// deleted inside one goes when it ends.
#include "DefaultSpace.h"
#include "ErrorRecorder.h"
#include "UserBody.h"
#include "iCOBB.h"
#include "iCSphere.h"
#include "iCollisionListener.h"
#include "iCollisionQueries.h"
#include "iOctreeCollisionSpace.h"
#include "iSimpleCollisionSpace.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <random>
#include <vector>

namespace {

using guardian_test::ErrorRecorder;

// n unit boxes on a 2 m grid (10 a row, 10 rows a layer), in space.
struct Grid {
    iCollisionSpace* space;
    std::vector<UserBody*> bodies;
    std::vector<iCollisionGeometry*> geometry;
    Grid(iCollisionSpace* in, int n) : space(in) {
        DefaultSpace joins(space);
        for (int i = 0; i < n; ++i) {
            bodies.push_back(new UserBody(Vector(2.0f * (i % 10), 2.0f * (i / 100), 2.0f * (i / 10 % 10))));
            geometry.push_back(CreateCOBB(bodies.back(), Vector(0.5f, 0.5f, 0.5f)));
        }
        space->populateContactList(1.0f / 60.0f);
    }
    ~Grid() {
        for (iCollisionGeometry* g : geometry)
            if (g) g->Delete();
        for (UserBody* b : bodies) b->Delete();
    }
};

struct Answer {
    bool hit;
    iCollisionGeometry* geometry;
    float distance;
    std::vector<iCollisionGeometry*> overlaps;
    bool operator==(const Answer& o) const {
        return hit == o.hit && geometry == o.geometry && distance == o.distance && overlaps == o.overlaps;
    }
};

// k rays along +x through the grid's rows and spheres around its boxes, from a fixed seed.
std::vector<Answer> ask(iCollisionQueries* q, int k) {
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> cell(0, 9);
    std::vector<Answer> answers;
    for (int i = 0; i < k; ++i) {
        const Vector row(-5.0f, 2.0f * float(cell(rng)), 2.0f * float(cell(rng)));
        RayHit hit;
        Answer a;
        a.hit = q->rayCast(row, Vector(1, 0, 0), 100.0f, hit);
        a.geometry = hit.geometry;
        a.distance = hit.distance;
        q->overlapSphere(
            Vector(2.0f * float(cell(rng)) + 1.0f, 2.0f * float(cell(rng) % 2), 2.0f * float(cell(rng))),
            0.7f, a.overlaps);
        answers.push_back(a);
    }
    return answers;
}

// k rays and k overlaps asked one at a time, then again in a batch: the answers, the body reads each way
// took, and the errors the batch reported.
struct AloneAndBatched {
    std::vector<Answer> alone, batched;
    unsigned long readsAlone = 0, readsBatched = 0, errors = 0;
};
AloneAndBatched askBothWays(iCollisionQueries* q, int k) {
    AloneAndBatched r;
    UserBody::reads = 0;
    r.alone = ask(q, k);
    r.readsAlone = UserBody::reads;
    ErrorRecorder errors;
    UserBody::reads = 0;
    {
        QueryBatch batch(q);
        r.batched = ask(q, k);
    }
    r.readsBatched = UserBody::reads;
    r.errors = errors.count();
    return r;
}

} // namespace

// 1,000 boxes, 50 rays and 50 overlaps: outside a batch every query reads every body (O(N) a query: nothing
// tells the space that a body moved); inside one the bodies are read at its start (its record and the tree's
// sync) and by the check at its end, and then only the candidates'. The answers are the same, and the ray
// along a row meets that row's first box, 4.5 m along it (from x = -5 to its face at -0.5).
TEST(QueryBatch, TheOctreeSpaceReadsEachBodyOnceABatchNotOnceAQuery) {
    iCollisionSpace* space = CreateOctreeCollisionSpace();
    {
        Grid grid(space, 1000);
        const AloneAndBatched r = askBothWays(queriesOf(space), 50);
        EXPECT_EQ(r.errors, 0u);
        EXPECT_TRUE(r.alone == r.batched);
        for (const Answer& a : r.alone) {
            ASSERT_TRUE(a.hit);
            EXPECT_NEAR(a.distance, 4.5f, 1e-5f);
            EXPECT_GE(a.overlaps.size(), 1u);
        }
        EXPECT_GE(r.readsAlone, 100u * 1000u); // every body, every query
        // The start (the record once, the tree's sync twice) and the end's check read each body; the queries
        // themselves their candidates' (a row's ten boxes, a sphere's neighbours: 4,597 reads in all).
        EXPECT_LE(r.readsBatched, 4u * 1000u + 100u * 20u) << "alone " << r.readsAlone;
    }
    space->Delete();
}

// The simple space (the brute-force reference: outside a batch every query tests every geometry exactly) in
// a batch tests exactly only the geometry whose box, kept from the batch's start, the query meets: the same
// answers, each body read a few times for the batch instead of once a query.
TEST(QueryBatch, TheSimpleSpaceAnswersAsOutsideABatchReadingEachBodyOnceABatch) {
    iCollisionSpace* space = CreateSimpleCollisionSpace();
    {
        Grid grid(space, 300);
        const AloneAndBatched r = askBothWays(queriesOf(space), 20);
        EXPECT_TRUE(r.alone == r.batched);
        EXPECT_EQ(r.errors, 0u);
        EXPECT_GE(r.readsAlone, 40u * 300u);
        EXPECT_LE(r.readsBatched, 4u * 300u + 40u * 20u) << "alone " << r.readsAlone;
    }
    space->Delete();
}

// test(space's queries, its grid, whether it is the octree space) in the octree and the simple space, each
// holding 100 boxes.
template <class Test> void inEachSpace(Test test) {
    for (bool octree : {true, false}) {
        iCollisionSpace* space = octree ? CreateOctreeCollisionSpace() : CreateSimpleCollisionSpace();
        {
            Grid grid(space, 100);
            test(queriesOf(space), grid, octree);
        }
        space->Delete();
    }
}

// A body moved inside a batch: the end says so (once), the space is intact, and the next query, outside a
// batch, finds the box where it is now.
TEST(QueryBatch, ABodyMovedInsideABatchIsReportedAtItsEnd) {
    inEachSpace([](iCollisionQueries* q, Grid& grid, bool octree) {
        std::vector<iCollisionGeometry*> found;
        ErrorRecorder errors;
        {
            QueryBatch batch(q);
            EXPECT_EQ(q->overlapSphere(Vector(0, 0, 0), 0.3f, found), 1u);
            grid.bodies[0]->getDynamics().position = Vector(0, 50, 0); // broken promise
        }
        EXPECT_EQ(errors.count(), 1u) << "octree " << octree;
        EXPECT_NE(ErrorRecorder::last().find(L"moved or changed inside a query batch"), std::wstring::npos);
        EXPECT_EQ(q->overlapSphere(Vector(0, 0, 0), 0.3f, found), 0u);
        ASSERT_EQ(q->overlapSphere(Vector(0, 50, 0), 0.3f, found), 1u);
        EXPECT_EQ(found[0], grid.geometry[0]);
        RayHit hit;
        ASSERT_TRUE(q->rayCast(Vector(0, 60, 0), Vector(0, -1, 0), 20.0f, hit));
        EXPECT_EQ(hit.geometry, grid.geometry[0]);
        EXPECT_NEAR(hit.distance, 9.5f, 1e-5f);
        // Reshaped inside a batch: reported too.
        {
            QueryBatch batch(q);
            static_cast<iCOBB*>(grid.geometry[1])->setRadius(Vector(0.6f, 0.6f, 0.6f));
        }
        EXPECT_EQ(errors.count(), 2u);
    });
}

// Geometry joining inside a batch is found by the next query in it; geometry leaving (and deleted) is not;
// neither breaks the promise.
TEST(QueryBatch, GeometryMayJoinAndLeaveInsideABatch) {
    inEachSpace([](iCollisionQueries* q, Grid& grid, bool octree) {
        std::vector<iCollisionGeometry*> found;
        ErrorRecorder errors;
        UserBody* newcomer = new UserBody(Vector(-10, 0, 0));
        iCollisionGeometry* sphere = nullptr;
        {
            QueryBatch batch(q);
            EXPECT_EQ(q->overlapSphere(Vector(-10, 0, 0), 0.5f, found), 0u);
            EXPECT_EQ(q->overlapSphere(Vector(2, 0, 0), 0.3f, found), 1u);
            {
                DefaultSpace joins(grid.space);
                sphere = CreateCSphere(newcomer, 1.0f);
            }
            grid.geometry[1]->Delete(); // the box at (2, 0, 0)
            grid.geometry[1] = nullptr;
            ASSERT_EQ(q->overlapSphere(Vector(-10, 0, 0), 0.5f, found), 1u) << "octree " << octree;
            EXPECT_EQ(found[0], sphere);
            EXPECT_EQ(q->overlapSphere(Vector(2, 0, 0), 0.3f, found), 0u);
            RayHit hit;
            ASSERT_TRUE(q->rayCast(Vector(-20, 0, 0), Vector(1, 0, 0), 100.0f, hit));
            EXPECT_EQ(hit.geometry, sphere);
            EXPECT_NEAR(hit.distance, 9.0f, 1e-5f);
        }
        EXPECT_EQ(errors.count(), 0u);
        sphere->Delete();
        newcomer->Delete();
    });
}

// Batches nest: only the outermost end checks (and ends the batch). An end without a begin is refused.
TEST(QueryBatch, BatchesNestAndAnUnmatchedEndIsRefused) {
    iCollisionSpace* space = CreateOctreeCollisionSpace();
    {
        Grid grid(space, 10);
        iCollisionQueries* q = queriesOf(space);
        ErrorRecorder errors;
        q->endQueries();
        EXPECT_EQ(errors.count(), 1u);
        EXPECT_NE(ErrorRecorder::last().find(L"no batch was begun"), std::wstring::npos);
        std::vector<iCollisionGeometry*> found;
        q->beginQueries();
        q->beginQueries();
        EXPECT_EQ(q->overlapSphere(Vector(0, 0, 0), 0.3f, found), 1u);
        grid.bodies[0]->getDynamics().position = Vector(0, 50, 0);
        q->endQueries();
        EXPECT_EQ(errors.count(), 1u); // the inner end: nothing checked yet
        q->endQueries();
        EXPECT_EQ(errors.count(), 2u);
        EXPECT_EQ(q->overlapSphere(Vector(0, 50, 0), 0.3f, found), 1u);
        q->endQueries();
        EXPECT_EQ(errors.count(), 3u);
    }
    space->Delete();
}

// The space deleted inside a batch (a QueryBatch still in scope) says so and answers until the outermost
// batch ends; then it goes, its geometry left without a space. (Under ASan, a batch ending a deleted space
// is a use after free.)
TEST(QueryBatch, ASpaceDeletedInsideABatchGoesWhenTheBatchEnds) {
    for (bool octree : {false, true}) {
        iCollisionSpace* space = octree ? CreateOctreeCollisionSpace() : CreateSimpleCollisionSpace();
        static const iCollisionSpace* gone = nullptr;
        const CollisionSpaceWatcher watcher = [](const iCollisionSpace* dying, void*) { gone = dying; };
        watchCollisionSpaces(watcher, nullptr);
        gone = nullptr;
        UserBody* body = new UserBody(Vector(0, 0, 0));
        iCollisionGeometry* box = nullptr;
        {
            DefaultSpace joins(space);
            box = CreateCOBB(body, Vector(0.5f, 0.5f, 0.5f));
        }
        ErrorRecorder errors;
        iCollisionQueries* q = queriesOf(space);
        std::vector<iCollisionGeometry*> found;
        {
            QueryBatch outer(q);
            {
                QueryBatch inner(q);
                space->Delete();
                EXPECT_EQ(errors.count(), 1u) << "octree " << octree;
                EXPECT_NE(ErrorRecorder::last().find(L"inside a query batch"), std::wstring::npos);
                space->Delete(); // said once
                EXPECT_EQ(errors.count(), 1u);
                EXPECT_EQ(q->overlapSphere(Vector(0.8f, 0, 0), 0.5f, found), 1u); // the box reaches x = 0.5
                EXPECT_EQ(q->overlapSphere(Vector(1.1f, 0, 0), 0.5f, found), 0u);
            }
            EXPECT_EQ(gone, nullptr); // the inner batch ended: the outer one holds
            EXPECT_EQ(box->getSpace(), space);
        }
        EXPECT_EQ(gone, space);
        EXPECT_EQ(box->getSpace(), nullptr);
        EXPECT_EQ(errors.count(), 1u);
        unwatchCollisionSpaces(watcher, nullptr);
        box->Delete();
        body->Delete();
    }
}

// A batch whose deletion is pending, ended by a listener while the space notifies it: the space cannot go
// from under its own call, so the deletion is refused as Delete() there is, and the space stays usable.
TEST(QueryBatch, ADeletionPendingWhenAListenerEndsTheBatchIsRefused) {
    struct EndsTheBatch final : iCollisionListener {
        iCollisionQueries* q = nullptr;
        int calls = 0;
        void HitWall(iRigidBody*, Vector, Vector) override {
            if (calls++ == 0) q->endQueries();
        }
    };
    iCollisionSpace* space = CreateSimpleCollisionSpace();
    UserBody* a = new UserBody(Vector(0, 0, 0));
    UserBody* b = new UserBody(Vector(0.9f, 0, 0)); // overlapping a by 0.1 m
    iCollisionGeometry *ga = nullptr, *gb = nullptr;
    {
        DefaultSpace joins(space);
        ga = CreateCOBB(a, Vector(0.5f, 0.5f, 0.5f));
        gb = CreateCOBB(b, Vector(0.5f, 0.5f, 0.5f));
    }
    EndsTheBatch listener;
    listener.q = queriesOf(space);
    a->attachListener(&listener);
    ErrorRecorder errors;
    listener.q->beginQueries();
    space->Delete(); // pending until the batch ends
    EXPECT_EQ(errors.count(), 1u);
    space->populateContactList(1.0f / 60.0f);
    EXPECT_EQ(listener.calls, 1);
    EXPECT_EQ(errors.count(), 2u);
    EXPECT_NE(ErrorRecorder::last().find(L"refused while the space is notifying"), std::wstring::npos);
    EXPECT_EQ(ga->getSpace(), space); // still here, and working
    space->populateContactList(1.0f / 60.0f);
    EXPECT_GT(space->getNumContacts(), 0u);
    EXPECT_EQ(listener.calls, 2);
    a->detachListener(&listener);
    space->Delete(); // outside any batch: now
    EXPECT_EQ(ga->getSpace(), nullptr);
    EXPECT_EQ(errors.count(), 2u);
    ga->Delete();
    gb->Delete();
    a->Delete();
    b->Delete();
}
