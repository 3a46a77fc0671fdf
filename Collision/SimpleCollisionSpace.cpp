// SimpleCollisionSpace.cpp - membership and the populate call of the collision space; each member's entry is
// gathered in SpaceGather.cpp, the candidate pairs come from its broadphase (SweepAndPrune.cpp,
// TreeBroadphase.cpp). The pair tests are in SpaceNarrowPhase.cpp, listeners in SpaceListeners.cpp, queries
// in SpaceQueries.cpp.
#include "SimpleCollisionSpace.h"
#include "Broadphase.h"
#include "FetchAhead.h"
#include "SweepAndPrune.h"
#include "TreeBroadphase.h"
#include "iOctreeCollisionSpace.h"
#include "iRigidBody.h"
#include "iSimpleCollisionSpace.h"
#include "iUtilities.h"

#include <algorithm>
#include <cmath>

SimpleCollisionSpace::SimpleCollisionSpace(size_t samplesPerSecond, std::unique_ptr<Broadphase> broadphase)
    : m_samplesPerSecond(samplesPerSecond), m_broadphase(std::move(broadphase)) {
    watchRigidBodies(&SimpleCollisionSpace::onBodyDestroyed, this); // contact pairs name bodies
}

SimpleCollisionSpace::~SimpleCollisionSpace() {
    unwatchRigidBodies(&SimpleCollisionSpace::onBodyDestroyed, this);
    for (const ObserverSlot& s : m_observers) ContactObserverLinks::unlinked(s.observer, this);
}

bool SimpleCollisionSpace::add(iCollisionGeometry* o) {
    if (!o) {
        error(L"iCollisionSpace::add: null geometry refused");
        return false;
    }
    CollisionGeometry* g = CollisionGeometry::from(o);
    if (!g) {
        error(L"iCollisionSpace::add: not a geometry of this collision package; refused");
        return false;
    }
    if (g->space() == this) return false;
    if (iCollisionSpace* old = g->space()) {
        auto* busy = dynamic_cast<SimpleCollisionSpace*>(old);
        if (busy && busy->isNotifying()) {
            error(L"iCollisionSpace::add: the geometry's space is notifying listeners; move it afterwards");
            return false;
        }
        old->remove(o); // a geometry is in one space at a time: adding moves it
    }
    settleRemovals(); // a new geometry may have a removed one's address
    g->setSpace(this);
    CollisionGeometry::SpaceState& st = g->spaceState();
    st = CollisionGeometry::SpaceState();
    st.order = ++m_joined;
    st.listed = m_geometry.insert(m_geometry.end(), o);
    st.member = int(m_members.size());
    m_members.push_back(g);
    ++m_membership;
    m_layoutDirty = true;
    querySyncLost();
    return true;
}

void SimpleCollisionSpace::remove(iCollisionGeometry* o) {
    if (!o) {
        error(L"iCollisionSpace::remove: null geometry refused");
        return;
    }
    CollisionGeometry* g = CollisionGeometry::from(o);
    if (!g || g->space() != this) return;
    if (m_notifying) {
        if (!g->spaceState().pendingRemove) {
            g->spaceState().pendingRemove = true;
            m_pendingRemove.push_back(g);
        }
        return;
    }
    removeNow(g);
}

void SimpleCollisionSpace::removeNow(CollisionGeometry* g) {
    wakeSleeper(g->body(), nullptr); // asleep, a body that lost its shape would hang where it rested
    ++m_membership;
    m_layoutDirty = true;
    querySyncLost();
    CollisionGeometry::SpaceState& st = g->spaceState();
    m_geometry.erase(st.listed);
    m_members[size_t(st.member)] = nullptr;
    m_broadphase->forget(g);
    m_gone.push_back(reinterpret_cast<std::uintptr_t>(g));
    g->setSpace(nullptr);
    st = CollisionGeometry::SpaceState();
}

void SimpleCollisionSpace::settleRemovals() {
    if (!m_notifying) settleDeadBodies();
    if (m_gone.empty() || m_notifying) return; // (nothing is removed while notifying: it is queued)
    std::sort(m_gone.begin(), m_gone.end());
    size_t kept = 0;
    for (CollisionGeometry* g : m_members)
        if (g) {
            g->spaceState().member = int(kept);
            m_members[kept++] = g;
        }
    m_members.resize(kept);
    // The contact list outlives the call that built it (a scene reads it after its force generators ran,
    // and they may delete geometry): no contact may name a geometry that is no longer here.
    keepContacts(
        [this](const CollisionGeometry* a, const CollisionGeometry* b) { return !isGone(a) && !isGone(b); });
    forgetEventsOfGone();
    m_gone.clear();
}

void SimpleCollisionSpace::geometryEdited(const CollisionGeometry& g) {
    const int i = g.spaceState().entry;
    if (i >= 0 && size_t(i) < m_entries.size() && m_entries[size_t(i)].g == &g)
        m_entries[size_t(i)].cache.mirrored = false;
}

bool SimpleCollisionSpace::deferDelete(CollisionGeometry* g) {
    if (!m_notifying) return false;
    if (!g->spaceState().pendingDelete) {
        g->spaceState().pendingDelete = true;
        m_pendingDelete.push_back(g);
    }
    return true;
}

void SimpleCollisionSpace::Delete() const {
    if (m_notifying || m_populating) {
        error(L"iCollisionSpace::Delete: refused while the space is notifying listeners");
        return;
    }
    if (m_batchDepth > 0) { // a QueryBatch still in scope would end it after it is gone
        if (!m_deleteAfterBatch)
            error(L"iCollisionSpace::Delete: inside a query batch; the space is deleted when the batch ends");
        m_deleteAfterBatch = true;
        return;
    }
    destroy();
}

void SimpleCollisionSpace::destroy() const {
    for (iCollisionGeometry* o : m_geometry) {
        CollisionGeometry* g = CollisionGeometry::from(o);
        g->setSpace(nullptr);
        g->spaceState() = CollisionGeometry::SpaceState();
    }
    if (getDefaultCollisionSpace() == this) setDefaultCollisionSpace(nullptr);
    collisionSpaceDestroyed(this); // scenes colliding in it forget it (iCollisionSpace.h)
    delete this;
}

void SimpleCollisionSpace::populateContactList(float delta) {
    settleRemovals();
    if (m_notifying || m_populating) {
        error(L"iCollisionSpace::populateContactList: called from inside a listener; ignored");
        return;
    }
    if (std::isnan(delta) || delta < 0.0f) {
        error(L"iCollisionSpace::populateContactList: delta must be >= 0; treated as 0");
        delta = 0.0f;
    }
    m_populating = true;
    ++m_call;
    querySyncLost(); // the broadphase now holds this call's boxes
    m_droppedPairs = 0;
    m_contacts.clear();
    m_features.clear();
    m_contactGeoms.clear();
    m_notices.clear();
    const bool continuous = delta > 0.0f && std::isfinite(delta) && m_samplesPerSecond > 0;
    gatherEntries(continuous);
    if (m_restChanged) wakeDisturbedSleepers();
    // Candidate pairs (planes first: when the contact budget fills, the ground is the last thing to lose).
    const Broadphase::PairList pairs = m_broadphase->findPairs(m_entries, m_relaid ? nullptr : &m_changed);
    m_pairs = pairs.first;
    m_pairCount = pairs.count;
    if (m_restingNewcomer) wakeSleepersUnderNewcomers(pairs.first, pairs.count);
    const float stepDelta = continuous ? delta : 0.0f;
    // The pairs' entries and shapes lie all over their arrays (the pairs come in the broadphase's order):
    // each is asked for a few pairs ahead, the entries first (where its shapes are is in them).
    constexpr size_t kEntriesAhead = 8, kShapesAhead = 4;
    for (size_t k = 0; k < pairs.count; ++k) {
        if (k + kEntriesAhead < pairs.count) {
            const std::pair<int, int>& later = pairs.first[k + kEntriesAhead];
            for (int i : {later.first, later.second}) { // its first line, and the one with first and last
                gcol::fetchAhead(&m_entries[size_t(i)]);
                gcol::fetchAhead(&m_entries[size_t(i)].first);
            }
        }
        if (k + kShapesAhead < pairs.count) {
            const std::pair<int, int>& later = pairs.first[k + kShapesAhead];
            for (int i : {later.first, later.second}) // its first shape (96 bytes: two lines)
                gcol::fetchAhead(m_shapes.data() + m_entries[size_t(i)].first, sizeof(gcol::WorldShape));
        }
        const std::pair<int, int>& p = pairs.first[k];
        testPair(m_entries[size_t(p.first)], m_entries[size_t(p.second)], stepDelta);
    }
    if (m_droppedPairs > 0 && !m_reportedDrops) {
        m_reportedDrops = true;
        error(
            L"SimpleCollisionSpace: the contact budget (iContactBudget.h) is full; touching pairs beyond it "
            L"are dropped until bodies move apart (reported once)");
    }
    // Remember this call's poses for the next call's sampling. (A geometry whose space state holds all of it
    // already, as its entry knows, is not written: a call where nothing moved does not touch the geometry.)
    for (Entry& e : m_entries) {
        if (!e.active) continue;
        Entry::Cache& c = e.cache;
        const bool held = c.prevCurrent && m_mirrors && c.mirrored && c.hadPrevious && c.previousIsBody &&
                          c.previousTeleports == e.teleports;
        if (!held) {
            CollisionGeometry::SpaceState& st = e.g->spaceState();
            st.hasPrevious = true;
            st.previousBody = e.body;
            st.previousTeleports = e.teleports;
            if (!c.prevCurrent) { // (else they hold this pose already)
                st.previousOrigin = e.origin;
                st.previousRotation = e.rotation;
            }
        }
        c.hadPrevious = c.previousIsBody = true;
        c.previousTeleports = e.teleports;
        c.prevIsPose = true;
    }
    carryRestingPairs(); // pairs not tested because both rest still touch
    m_populating = false;
    reportTouching();
}

size_t SimpleCollisionSpace::findCandidatePairs() {
    settleRemovals();
    if (m_notifying || m_populating) return 0;
    ++m_call;
    querySyncLost();
    gatherEntries(false);
    const Broadphase::PairList pairs = m_broadphase->findPairs(m_entries, m_relaid ? nullptr : &m_changed);
    m_pairs = pairs.first;
    m_pairCount = pairs.count;
    return m_pairCount;
}

bool SimpleCollisionSpace::setContactBudget(size_t maxContacts) {
    if (maxContacts == 0) {
        error(L"iContactBudget::setContactBudget: the budget must be at least 1 contact; unchanged");
        return false;
    }
    m_budget = maxContacts;
    return true;
}

bool SimpleCollisionSpace::setLengthUnitsPerMetre(float unitsPerMetre) {
    if (!validLengthUnit(unitsPerMetre)) {
        error(L"iCollisionSpaceScale::setLengthUnitsPerMetre: the unit must be 1e-3..1e3 length units per "
              L"metre; unchanged");
        return false;
    }
    m_lengthUnit = unitsPerMetre;
    m_broadphase->setLengthUnit(unitsPerMetre);
    return true;
}

extern "C" iCollisionSpace* CreateSimpleCollisionSpace(size_t samplesPerSecond) {
    return new SimpleCollisionSpace(samplesPerSecond, std::make_unique<SweepAndPrune>());
}

extern "C" iCollisionSpace* CreateOctreeCollisionSpace(size_t samplesPerSecond) {
    return new SimpleCollisionSpace(samplesPerSecond, std::make_unique<TreeBroadphase>());
}
