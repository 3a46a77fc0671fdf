// SimpleCollisionSpace.cpp - membership, per-call pose gathering and the populate call of the collision
// space; the candidate pairs come from its broadphase (SweepAndPrune.cpp, TreeBroadphase.cpp). The pair
// tests are in ContinuousPairTest.cpp, listeners in SpaceListeners.cpp, queries in SpaceQueries.cpp.
#include "SimpleCollisionSpace.h"
#include "Broadphase.h"
#include "MathEigen.h"
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
    m_geometry.push_back(o);
    m_members.push_back(g);
    g->setSpace(this);
    g->spaceState() = CollisionGeometry::SpaceState();
    g->spaceState().order = ++m_joined;
    ++m_membership;
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
    ++m_membership;
    m_geometry.remove(g->asInterface());
    m_members.erase(std::find(m_members.begin(), m_members.end(), g));
    m_broadphase->forget(g);
    forgetEventsOf(g);
    // The contact list outlives the call that built it (a scene reads it after its force generators ran,
    // and they may delete geometry): no contact may name a geometry that is no longer here.
    size_t keep = 0;
    for (size_t i = 0; i < m_contacts.size(); ++i) {
        const CollisionContact& c = m_contacts[i];
        if (c.g1 == g->asInterface() || c.g2 == g->asInterface()) continue;
        m_contacts[keep] = c;
        m_features[keep] = m_features[i];
        m_contactGeoms[keep] = m_contactGeoms[i];
        ++keep;
    }
    m_contacts.resize(keep);
    m_features.resize(keep);
    m_contactGeoms.resize(keep);
    g->setSpace(nullptr);
    g->spaceState() = CollisionGeometry::SpaceState();
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
    for (iCollisionGeometry* o : m_geometry) {
        CollisionGeometry* g = CollisionGeometry::from(o);
        g->setSpace(nullptr);
        g->spaceState() = CollisionGeometry::SpaceState();
    }
    if (getDefaultCollisionSpace() == this) setDefaultCollisionSpace(nullptr);
    collisionSpaceDestroyed(this); // scenes colliding in it forget it (iCollisionSpace.h)
    delete this;
}

namespace {

// Angle of the rotation taking a to b (both row-vector rotations).
float rotationAngle(const Matrix& a, const Matrix& b) {
    gmath::Mat3 rel = gmath::block3(a).transpose() * gmath::block3(b);
    float c = 0.5f * (rel.trace() - 1.0f);
    return std::acos(std::fmax(-1.0f, std::fmin(1.0f, c)));
}

void grow(gcol::Aabb& box, const gcol::Aabb& other) {
    box.min = Vector(std::fmin(box.min.x, other.min.x), std::fmin(box.min.y, other.min.y),
                     std::fmin(box.min.z, other.min.z));
    box.max = Vector(std::fmax(box.max.x, other.max.x), std::fmax(box.max.y, other.max.y),
                     std::fmax(box.max.z, other.max.z));
}

} // namespace

bool SimpleCollisionSpace::gatherEntry(CollisionGeometry* g, bool continuous, Entry& e) {
    CollisionGeometry::SpaceState& st = g->spaceState();
    e.g = g;
    e.body = g->body();
    e.layer = g->getLayer();
    e.mask = g->getMask();
    e.sensor = g->isSensor();
    e.plane = g->isPlane();
    if (!e.body && !e.plane) {
        st.hasPrevious = false;
        return false;
    }
    if (!g->currentPose(e.origin, e.rotation)) {
        if (!st.reportedBad)
            error(L"SimpleCollisionSpace: a body's position or orientation is not finite; its geometry is "
                  L"skipped until it is");
        st.reportedBad = true;
        st.hasPrevious = false;
        return false;
    }
    st.reportedBad = false;
    const RBDynamics* root = e.body ? e.body->getDynamics().attachmentRoot() : nullptr;
    e.teleports =
        root ? root->teleports + (root != &e.body->getDynamics() ? e.body->getDynamics().teleports : 0) : 0;
    // The pose of the previous call, unless the body is new here or was teleported since (never swept).
    const bool samePath = st.hasPrevious && st.previousBody == e.body && st.previousTeleports == e.teleports;
    // Resting bodies (fixed in space, or asleep) that did not move: a pair of two of them needs no test. One
    // the game moved (a platform, a lift) is tested, so it can push and wake what rests on it.
    const bool resting = !root || root->physicsType == PHYS_FixedInSpace || root->sleeping;
    const bool movedSinceLastCall = st.hasPrevious && st.previousBody == e.body &&
                                    (st.previousOrigin != e.origin || st.previousRotation != e.rotation);
    e.fixed = resting && !movedSinceLastCall;
    e.first = int(m_shapes.size());
    g->worldShapes(e.origin, e.rotation, m_shapes);
    e.last = int(m_shapes.size());
    if (e.first == e.last) return false; // an empty compound
    bool usePrevious = continuous && samePath;
    e.prevOrigin = usePrevious ? st.previousOrigin : e.origin;
    e.prevRotation = usePrevious ? st.previousRotation : e.rotation;
    e.minDim = g->minDimension();
    e.rotAngle = 0.0f;
    e.motion = 0.0f;
    e.moved = false;
    if (e.plane) return true; // infinite: no bounds, and nothing passes through a plane unseen
    float bound = g->asInterface()->getBoundingRadius();
    if (usePrevious) {
        e.rotAngle = rotationAngle(e.prevRotation, e.rotation);
        e.motion = (e.origin - e.prevOrigin).length() + e.rotAngle * bound;
        e.moved = e.motion > 0.25f * e.minDim;
    }
    gcol::shapeAabb(m_shapes[size_t(e.first)], e.box);
    for (int i = e.first + 1; i < e.last; ++i) {
        gcol::Aabb b;
        gcol::shapeAabb(m_shapes[size_t(i)], b);
        grow(e.box, b);
    }
    if (e.moved) {
        // Swept bounds: both end poses, inflated by how far rotation can carry a point off that path.
        m_scratchA.clear();
        g->worldShapes(e.prevOrigin, e.prevRotation, m_scratchA);
        for (const gcol::WorldShape& s : m_scratchA) {
            gcol::Aabb b;
            gcol::shapeAabb(s, b);
            grow(e.box, b);
        }
        float r = e.rotAngle * bound;
        e.box.min -= Vector(r, r, r);
        e.box.max += Vector(r, r, r);
    }
    return true;
}

void SimpleCollisionSpace::populateContactList(float delta) {
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
    m_droppedPairs = 0;
    m_contacts.clear();
    m_features.clear();
    m_contactGeoms.clear();
    m_notices.clear();
    const bool continuous = delta > 0.0f && std::isfinite(delta) && m_samplesPerSecond > 0;
    gatherEntries(continuous);
    // Candidate pairs (planes first: when the contact budget fills, the ground is the last thing to lose).
    m_broadphase->findPairs(m_entries, m_pairs);
    const float stepDelta = continuous ? delta : 0.0f;
    for (const std::pair<int, int>& p : m_pairs)
        testPair(m_entries[size_t(p.first)], m_entries[size_t(p.second)], stepDelta);
    if (m_droppedPairs > 0 && !m_reportedDrops) {
        m_reportedDrops = true;
        error(
            L"SimpleCollisionSpace: the contact budget (iContactBudget.h) is full; touching pairs beyond it "
            L"are dropped until bodies move apart (reported once)");
    }
    // Remember this call's poses for the next call's sampling.
    for (const Entry& e : m_entries) {
        CollisionGeometry::SpaceState& st = e.g->spaceState();
        st.hasPrevious = true;
        st.previousBody = e.body;
        st.previousTeleports = e.teleports;
        st.previousOrigin = e.origin;
        st.previousRotation = e.rotation;
    }
    carryRestingPairs(); // pairs not tested because both rest still touch
    m_populating = false;
    reportTouching();
}

void SimpleCollisionSpace::gatherEntries(bool continuous) {
    m_entries.clear();
    m_shapes.clear();
    for (CollisionGeometry* g : m_members) {
        Entry e;
        if (!gatherEntry(g, continuous, e)) continue;
        e.g->spaceState().call = m_call;
        e.g->spaceState().entry = int(m_entries.size());
        m_entries.push_back(e);
    }
}

size_t SimpleCollisionSpace::findCandidatePairs() {
    if (m_notifying || m_populating) return 0;
    ++m_call;
    gatherEntries(false);
    m_broadphase->findPairs(m_entries, m_pairs);
    return m_pairs.size();
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
