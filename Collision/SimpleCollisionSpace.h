// SimpleCollisionSpace.h - the collision space of this package: with sort-and-sweep it is the simple space
// (CreateSimpleCollisionSpace), the reference every faster space is checked against; with the persistent
// tree broadphase it is the octree space (CreateOctreeCollisionSpace). Only step 2 differs (Broadphase.h).
//
// populateContactList(delta):
//  1. reads every geometry's pose from its body (a geometry without a body, except a plane, or with a
//     non-finite pose is skipped; a non-finite pose is reported once with error()); each geometry's entry
//     is kept between calls, and one whose pose, shape version and body are as at the last call keeps its
//     world shapes and box (only the resting state, filter and motion since the previous call are read
//     again), so the broadphase hears of the boxes that changed;
//  2. finds candidate pairs, the ones whose world AABBs (swept over the motion since the previous call when
//     sampling is on) overlap, with its broadphase (sort-and-sweep or the tree); AABBs are conservative, so
//     the pairs tested are a superset of the overlapping ones and the result equals plain all-pairs;
//  3. skips pairs on the same body, pairs the layer rule filters out (iCollisionFilter.h) and pairs of two
//     bodies that are each PHYS_FixedInSpace or sleeping (RBDynamics::sleeping; a bodiless plane is fixed);
//     a pair with a sensor is tested at the current pose for overlap only (no contacts);
//  4. runs the exact pair test at the current pose, and when nothing touches and the pair moved fast,
//     the continuous tests (SpaceNarrowPhase.cpp);
//  5. notifies listeners (SpaceListeners.cpp) and contact observers (SpaceContactEvents.cpp).
// At most the contact budget's contacts are reported (iContactBudget.h): once it is full, the remaining
// candidate pairs are dropped untested.
// Storage is reused between calls: after warm-up a call does not allocate.
#pragma once

#include "CollisionGeometry.h"
#include "Narrowphase.h"
#include "PoseInputs.h"
#include "SpaceEntry.h"
#include "iCollisionEvents.h"
#include "iCollisionQueries.h"
#include "iCollisionSpace.h"
#include "iCollisionSpaceScale.h"
#include "iContactBudget.h"
#include "iContactEvents.h"
#include "iContactFeatures.h"
#include "iDebugDrawable.h"
#include "iShapeCast.h"
#include "iSnapshots.h"

#include <algorithm>
#include <cstdint>
#include <list>
#include <memory>
#include <utility>
#include <vector>

class iRigidBody;
class iCollisionListener;
class Broadphase;

class SimpleCollisionSpace final : public iCollisionSpace,
                                   public iCollisionQueries,
                                   public iContactFeatures,
                                   public iCollisionEvents,
                                   public iContactBudget,
                                   public iShapeCast,
                                   public iSnapshots,
                                   public iDebugDrawable,
                                   public iCollisionSpaceScale,
                                   public iContactEvents {
public:
    SimpleCollisionSpace(size_t samplesPerSecond, std::unique_ptr<Broadphase> broadphase);

    // A geometry is in at most one space: adding one that is in another space moves it here. Returns false
    // when it is already here, is null, or is not a geometry of this package.
    bool add(iCollisionGeometry* o) override;
    // During listener notification the removal is deferred until the notifications end.
    void remove(iCollisionGeometry* o) override;
    const std::list<iCollisionGeometry*>& getAttachedGeometry() override { return m_geometry; }
    void populateContactList(float delta) override;
    const CollisionContact* getContactList() const override {
        settle();
        return m_contacts.empty() ? nullptr : m_contacts.data();
    }
    size_t getNumContacts() const override {
        settle();
        return m_contacts.size();
    }
    const unsigned* getContactFeatureIds() const override {
        settle();
        return m_features.empty() ? nullptr : m_features.data();
    }
    bool rayCast(const Vector& origin, const Vector& direction, float maxDistance, RayHit& hit) override;
    size_t overlapSphere(const Vector& centre, float radius, std::vector<iCollisionGeometry*>& out) override;
    size_t overlapBox(const Vector& centre, const Matrix& orientation, const Vector& halfExtents,
                      std::vector<iCollisionGeometry*>& out) override;
    size_t overlapAABB(const Vector& min, const Vector& max, std::vector<iCollisionGeometry*>& out) override;
    // SpaceQueryBatch.cpp
    void beginQueries() override;
    void endQueries() override;
    void holdEvents(bool hold) override { m_holdEvents = hold; }
    // SpaceSnapshot.cpp
    iSnapshot* takeSnapshot() const override;
    bool restoreSnapshot(const iSnapshot* s) override;
    void deliverEvents() override; // SpaceEvents.cpp
    // SpaceContactEvents.cpp
    bool addObserver(ContactObserver* observer) override;
    bool removeObserver(ContactObserver* observer) override;
    bool setContactBudget(size_t maxContacts) override;
    size_t getContactBudget() const override { return m_budget; }
    size_t getDroppedPairCount() const override { return m_droppedPairs; }
    size_t sweepBodies(BodySweep* sweeps, size_t count) override; // SpaceShapeCast.cpp
    // Geometry, bounds and the current contact list (SpaceDebugDraw.cpp).
    void debugDraw(iDebugDraw& out, unsigned flags) const override;
    bool setLengthUnitsPerMetre(float unitsPerMetre) override;
    float getLengthUnitsPerMetre() const override { return m_lengthUnit; }
    void suspend() const override {}
    void release() const override {}
    // Geometries are not deleted: they leave the space (and stay usable). Clears the default space if it
    // was this one. Inside a query batch the space goes when the batch ends (a QueryBatch in scope ends it).
    void Delete() const override;

    // Called by a geometry's Delete(): while listeners are being notified the deletion is queued (true);
    // otherwise false and the geometry deletes itself.
    bool deferDelete(CollisionGeometry* g);
    bool isNotifying() const { return m_notifying; }
    // What g's entry mirrors of it may have changed (CollisionGeometry::edited): it reads g again.
    void geometryEdited(const CollisionGeometry& g);
    // Its candidate-pair stage (for tests and benchmarks: TreeBroadphase counts its tree queries).
    Broadphase& broadphase() { return *m_broadphase; }
    // That stage alone, as another engine's broadphase is timed (each geometry's box at its pose, then the
    // candidate pairs; no exact test, contact or event): how many candidate pairs it found. For benchmarks.
    size_t findCandidatePairs();
    // For tests: false has every call read every geometry, as before entries mirrored them (SpaceGather.cpp):
    // the reference a space with mirrors is checked against.
    void setGeometryMirrors(bool on) { m_mirrors = on; }

    // Per-geometry working state, kept between calls (SpaceEntry.h).
    using Entry = SpaceEntry;
    // One touching geometry pair, as listeners hear of it.
    struct Notice {
        CollisionGeometry *g1, *g2; // ours (the space's entries): no cross-cast needed per notice
        iRigidBody *b1, *b2;
        Vector normal, pos;
        int points;
        bool atPose; // touching at the poses of the call (not found along the motion before them)
        bool sensor; // an overlap involving a sensor: no contacts, no HitWall, contact events only
    };

private:
    ~SimpleCollisionSpace();
    void removeNow(CollisionGeometry* g);
    // Removal is O(1) (removeNow); the lists that may still name removed geometry (members, contacts, the
    // touching and event pairs) are cleaned in one pass over them at the next call that reads them, so
    // deleting N geometries costs O(N + lists), not O(N x lists). Every public call begins with it.
    void settleRemovals();
    // The same from a const call: what it changes is invisible from outside (the removed geometry is
    // already gone as far as any caller can tell).
    void settle() const { const_cast<SimpleCollisionSpace*>(this)->settleRemovals(); }
    bool isGone(const void* p) const { // removed since the last settleRemovals (m_gone sorted)
        return std::binary_search(m_gone.begin(), m_gone.end(), reinterpret_cast<std::uintptr_t>(p));
    }
    // Keeps the contacts (and their features and geometry pairs, in step) whose two geometries keep(g1, g2)
    // accepts, in their order.
    template <class Keep> void keepContacts(Keep keep) {
        size_t kept = 0;
        for (size_t i = 0; i < m_contacts.size(); ++i) {
            if (!keep(m_contactGeoms[i].first, m_contactGeoms[i].second)) continue;
            m_contacts[kept] = m_contacts[i];
            m_features[kept] = m_features[i];
            m_contactGeoms[kept] = m_contactGeoms[i];
            ++kept;
        }
        m_contacts.resize(kept);
        m_features.resize(kept);
        m_contactGeoms.resize(kept);
    }
    bool gatherEntry(Entry& e, bool continuous);

public:
    // Whether g is at its entry e's pose now, bit for bit, told from its body's raw pose inputs alone (a body
    // without a parent, as at the last call, with the same shape version): then e's shapes and box still
    // hold. False when it cannot tell so cheaply. (SpaceGather.cpp; queries ask it of every geometry.)
    static bool atEntryPose(const Entry& e, const CollisionGeometry& g);

private:
    void moveToEnd(Entry& e, int n);     // e's room in m_shapes, too small for its n shapes, moves
    void layOutEntries();                // one entry per member again, cached ones carried over
    void gatherEntries(bool continuous); // every member's entry brought up to date; m_changed, m_relaid
    void testPair(const Entry& a, const Entry& b, float delta);
    void testSensorPair(const Entry& a, const Entry& b);
    bool testAtPoses(const Entry& a, const Entry& b, float t, unsigned tag);
    bool sweepSpheres(const Entry& a, const Entry& b);
    void emit(const Entry& a, const Entry& b, const gcol::ContactManifold& m, unsigned childPair,
              unsigned tag);
    void notifyListeners(const std::vector<Notice>& notices);
    // SpaceEvents.cpp: the pairs still touching (resting pairs carried from their last contact), and HitWall
    // now or held for deliverEvents.
    void carryRestingPairs();
    void reportTouching();
    void forgetEventsOfGone(); // the removed geometry (m_gone) out of the touching and event pairs
    // SpaceWake.cpp: a sleeping body whose support moved, changed or left wakes.
    void wakeDisturbedSleepers();
    void wakeSleepersUnderNewcomers(const std::pair<int, int>* pairs, size_t count);
    void wakeSleeper(iRigidBody* body, Entry* entry);
    Entry* activeEntryOf(const CollisionGeometry* g); // its entry if it takes part in this call, else nullptr
    void finishNotifications();
    // SpaceContactEvents.cpp: the pairs touching in notices, then begin/persist/end against the last ones.
    void gatherContactPairs(const std::vector<Notice>& notices);
    void deliverContactEvents();
    void forgetContactPairsOfGone();
    static void onBodyDestroyed(const iRigidBody* dying, void* self);
    void settleDeadBodies(); // the pairs of bodies that died since the last call marked gone
    bool queryShapes(CollisionGeometry* g, std::vector<gcol::WorldShape>& out); // (a member: no cast back)
    // Query batches (SpaceQueryBatch.cpp): every query starts with prepareQuery (removals settled, the
    // broadphase synced with the current poses unless this batch synced it already); whatever changes what
    // the broadphase holds outside a query (membership, a call) says so with querySyncLost().
    void prepareQuery();
    void querySyncLost() { m_queriesSynced = false; }
    bool batchMoved() const; // some geometry's pose or shapes differ from those the batch began with
    struct BatchPose {
        unsigned long long order; // the geometry's join order (never reused: one that left is never matched)
        const iRigidBody* body;
        unsigned shapeVersion;
        bool raw; // its body has no parent: pose holds what its pose is made of (compared bit for bit)
        bool posed = true; // else: its pose was finite, and pose holds it (origin, rotation rows; com zero)
        gcol::PoseInputs pose;
    };
    static BatchPose batchPoseOf(const CollisionGeometry& g);
    void destroy() const;                // Delete()'s work (at once, or at the end of the batch it came in)
    std::vector<BatchPose> m_batchPoses; // per member at beginQueries(), in the members' (join) order
    int m_batchDepth = 0;                // beginQueries() not yet ended
    mutable bool m_deleteAfterBatch = false; // Delete() came inside the batch: endQueries() deletes
    bool m_queriesSynced = false;            // inside a batch: the broadphase holds every member at its pose
    // SpaceShapeCast.cpp (the cast) and SpaceCastObstacles.cpp (what a sweep may meet)
    static constexpr int kUnusableSweep = -2; // CastGeometry::sweep of a geometry whose pose is not finite
    struct CastGeometry {
        CollisionGeometry* g;
        int sweep;     // the sweep moving it, or -1 (kUnusableSweep: its pose is not finite)
        bool posed;    // origin and rotation are read
        Vector origin; // current pose
        Matrix rotation;
        Vector localOrigin;   // a swept one's origin from its root's COM, in the root's axes
        Matrix localRotation; // and its rotation relative to the root's
        Vector shift;         // how far it moves over the motion (indexObstacles)
    };
    void sweepOne(BodySweep& sweep, int index);
    // Poses every geometry once and sorts the bounded ones by the low x of a sphere around their motion, so
    // that a fast body's obstacles are found in O(log N + nearby), not by a pass over all (O(fast x N)).
    void indexObstacles();
    void gatherCandidates(const Vector& lo, const Vector& hi);
    // A bounded geometry's sphere around its motion (centre, radius) with its low x and m_cast index; the
    // index is sorted by low x (then m_cast index).
    struct ObstacleSphere {
        float lowX;
        int cast;
        float y, z, r;
        bool operator<(const ObstacleSphere& o) const {
            return lowX < o.lowX || (lowX == o.lowX && cast < o.cast);
        }
    };
    std::vector<ObstacleSphere> m_byLowX;
    std::vector<int> m_unbounded;      // planes and anything without finite bounds: always candidates
    std::vector<int> m_castCandidates; // scratch: one sweep's, in m_cast order
    float m_maxSpan = 0.0f;            // the largest such sphere's diameter
    bool m_obstaclesIndexed = false;
    // Whether a geometry of the sweep whose geometry is m_castOrder[range] touched obstacle at the last call.
    bool touchedAtStart(std::pair<int, int> range, const CollisionGeometry* obstacle);
    using GeometryPair = std::pair<const CollisionGeometry*, const CollisionGeometry*>; // lower address first
    static GeometryPair pairOf(const CollisionGeometry* a, const CollisionGeometry* b) {
        return a < b ? GeometryPair(a, b) : GeometryPair(b, a);
    }
    std::vector<GeometryPair> m_touchedAtStart; // sorted
    bool m_touchedAtStartListed = false;        // this sweepBodies call's, once a sweep asked
    // Appends to m_moving the shapes of sweep's geometry with its root at (position, row-vector rotation).
    void castShapesAt(int sweep, const Vector& position, const Matrix& rotation);

    // The contact budget (iContactBudget.h): what the last call dropped, and whether that was said.
    bool full() const { return m_contacts.size() >= m_budget; }
    size_t m_budget = kDefaultContactBudget;
    size_t m_droppedPairs = 0;
    bool m_reportedDrops = false;
    bool m_cut = false; // the pair being tested lost contacts to the budget
    size_t m_samplesPerSecond;
    float m_lengthUnit = 1.0f; // length units per metre (iCollisionSpaceScale.h)
    std::unique_ptr<Broadphase> m_broadphase;
    unsigned long long m_joined = 0;     // geometries added so far (SpaceState::order)
    unsigned long long m_membership = 0; // changes with every geometry added or removed (snapshots)
    std::list<iCollisionGeometry*> m_geometry;
    // The same geometry in the same order, without a cast each (nullptr: removed, until settleRemovals).
    std::vector<CollisionGeometry*> m_members;
    std::vector<std::uintptr_t> m_gone; // geometry removed since the last settleRemovals, by address
    std::vector<CollisionContact> m_contacts;
    std::vector<unsigned> m_features;
    // Each contact's two geometries as this space's own records (so that no contact is cross-cast back).
    std::vector<std::pair<CollisionGeometry*, CollisionGeometry*>> m_contactGeoms;
    // Kept between calls: the entries, their shapes (each entry's from first, room for cache.capacity), which
    // entries' boxes or activity changed this call, and whether they were laid out anew (all changed).
    std::vector<Entry> m_entries, m_oldEntries;
    // Per entry, its geometry as the interface a contact names (emit): kept apart from the entries, whose
    // first lines are all that a call where nothing moved reads of them.
    std::vector<iCollisionGeometry*> m_interfaces;
    std::vector<gcol::WorldShape> m_shapes, m_oldShapes;
    std::vector<int> m_changed;
    bool m_relaid = true;
    bool m_restChanged = false;     // this call: something a sleeping body may rest on moved, changed or left
    bool m_restingNewcomer = false; // this call: a resting geometry (fixed, bodiless) joined the space
    bool m_layoutDirty = true;      // members were added or removed, or m_shapes is mostly waste
    // RBDynamics::attachmentEpoch at the last gathering, and whether it is the same now
    // (Entry::Cache::rootIsSelf holds).
    unsigned long long m_linksEpoch = 0;
    bool m_linksUnchanged = false;
    bool m_mirrors = true;   // entries may stand for their geometries (setGeometryMirrors)
    size_t m_shapeWaste = 0; // shapes in m_shapes no entry owns
    // Scratch reused between calls.
    std::vector<gcol::WorldShape> m_scratchA, m_scratchB;
    const std::pair<int, int>* m_pairs =
        nullptr; // this call's candidate pairs, in test order (the broadphase's)
    size_t m_pairCount = 0;
    std::vector<CollisionGeometry*> m_candidates; // a query's
    std::vector<Notice> m_notices;  // this call's touching pairs, then the resting ones carried over
    std::vector<Notice> m_touching; // the pairs touching at the last call
    std::vector<Notice> m_held;     // pairs that touched since the last delivery (events held), once a
                                    // second call is held (the first's are m_touching's until then)
    int m_heldCalls = 0;            // populate calls held since the last delivery
    std::vector<Notice> m_delivery; // scratch
    struct BodyPair {
        std::uintptr_t lo, hi; // the two bodies' addresses, lower first
        size_t index;          // the notice's place in its list
    };
    std::vector<BodyPair> m_bodyPairs; // scratch: notifyListeners finds repeated body pairs
    std::vector<char> m_repeat;        // scratch: notifyListeners' notices of a body pair listed before
    bool m_holdEvents = false;
    unsigned long long m_call = 0; // populateContactList calls, to tell this call's entries
    std::vector<iCollisionListener*> m_listenerSnapshot;
    std::vector<CollisionGeometry*> m_pendingRemove, m_pendingDelete;
    // Contact events (SpaceContactEvents.cpp): kept only while an observer is attached.
    struct ObserverSlot {
        ContactObserver* observer;
        bool fresh; // attached since the last delivery: hears onBegin for every pair touching
    };
    std::vector<ObserverSlot> m_observers, m_observerSnapshot;
    struct ActivePair {
        std::uintptr_t lo, hi; // the sides (body, or bodiless geometry) by address, lower first
        bool sensor;
        bool gone;                  // a side went: it can no longer match (its address may be reused)
        bool announced;             // observers heard its onBegin (only those hear its onEnd)
        size_t order;               // place in the list it was found in (delivery order)
        ContactPair pair;           // as observers hear it
        CollisionGeometry *gA, *gB; // our records of pair.geometryA/B
    };
    std::vector<ActivePair> m_active, m_current; // sorted by sides: at the last delivery; at this one
    struct ContactEvent {
        int kind;     // 0 end (m_active), 1 begin, 2 persist (m_current)
        size_t index; // in that list
    };
    std::vector<ContactEvent> m_contactEvents;   // scratch
    std::vector<const iRigidBody*> m_deadBodies; // died since the pairs were last walked (onBodyDestroyed)
    bool m_gathered = false;                     // m_current holds this delivery's pairs
    bool m_deliveringContacts = false;           // m_active and m_current are being iterated
    // Shape cast scratch.
    std::vector<CastGeometry> m_cast;
    std::vector<const CollisionGeometry*> m_movingOwner;   // the geometry of each m_moving shape
    std::vector<std::pair<const void*, int>> m_sweepIndex; // (root dynamics, sweep), hashed
    std::vector<int> m_castOrder;                          // m_cast indices grouped by sweep
    std::vector<std::pair<int, int>> m_sweepRange;         // each sweep's range in m_castOrder
    std::vector<gcol::WorldShape> m_moving, m_obstacles;
    std::vector<int> m_obstacleOwner;    // m_cast index of each obstacle shape
    std::vector<Vector> m_obstacleShift; // how far it moves over the motion (another swept body's)
    std::vector<Vector> m_sweepShift;    // each sweep's translation
    struct SweepMotion {                 // bounds on a sweep's motion (motionBound)
        float move = 0.0f;               // how far its COM moves, at most
        float turn = 0.0f;               // how far it turns (radians), at most
        float slack = 0.0f;              // rounding allowance on a length at its distance from the origin
        bool exact = true;               // no bound: every geometry of it is tested exactly
    };
    static SweepMotion motionBound(const BodySweep& sweep, const RBDynamics& d);
    static bool mayPassThrough(const SweepMotion& m, CollisionGeometry& g, const RBDynamics& d);
    std::vector<SweepMotion> m_sweepMotion;
    std::vector<unsigned char> m_mayPass; // per sweep: some geometry of it may be fast (sweepOne looks)
    struct SweepHit {
        int obstacleSweep = -1; // the sweep moving what it hit, or -1
        float touch = 1.0f;     // the fraction it stops at
        Vector recede;          // how far what it hit moves away from the touch over the whole motion
    };
    std::vector<SweepHit> m_sweepHits;    // per sweep
    std::vector<unsigned char> m_ignored; // moving x obstacle pairs touching at the start
    bool m_notifying = false;
    bool m_populating = false;
};
