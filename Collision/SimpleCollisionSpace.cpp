// SimpleCollisionSpace.cpp - membership, per-call pose gathering and the sort-and-sweep broad phase of the
// all-pairs space. The pair tests are in ContinuousPairTest.cpp, listeners in SpaceListeners.cpp, queries
// in SpaceQueries.cpp.
#include "SimpleCollisionSpace.h"
#include "MathEigen.h"
#include "iRigidBody.h"
#include "iSimpleCollisionSpace.h"
#include "iUtilities.h"

#include <algorithm>
#include <cmath>

SimpleCollisionSpace::SimpleCollisionSpace(size_t samplesPerSecond) : m_samplesPerSecond(samplesPerSecond) {}

SimpleCollisionSpace::~SimpleCollisionSpace() = default;

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
    g->setSpace(this);
    g->spaceState() = CollisionGeometry::SpaceState();
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
    m_geometry.remove(g->asInterface());
    forgetEventsOf(g);
    // The contact list outlives the call that built it (a scene reads it after its force generators ran,
    // and they may delete geometry): no contact may name a geometry that is no longer here.
    size_t keep = 0;
    for (size_t i = 0; i < m_contacts.size(); ++i) {
        const CollisionContact& c = m_contacts[i];
        if (c.g1 == g->asInterface() || c.g2 == g->asInterface()) continue;
        m_contacts[keep] = c;
        m_features[keep] = m_features[i];
        ++keep;
    }
    m_contacts.resize(keep);
    m_features.resize(keep);
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
    m_entries.clear();
    m_shapes.clear();
    m_notices.clear();
    const bool continuous = delta > 0.0f && std::isfinite(delta) && m_samplesPerSecond > 0;
    for (iCollisionGeometry* o : m_geometry) {
        Entry e;
        if (!gatherEntry(CollisionGeometry::from(o), continuous, e)) continue;
        e.g->spaceState().call = m_call;
        e.g->spaceState().entry = int(m_entries.size());
        m_entries.push_back(e);
    }
    // Sort and sweep along x; planes (unbounded) meet every bounded entry.
    m_order.clear();
    m_planes.clear();
    for (int i = 0; i < int(m_entries.size()); ++i)
        (m_entries[size_t(i)].plane ? m_planes : m_order).push_back(i);
    std::sort(m_order.begin(), m_order.end(), [this](int a, int b) {
        float ma = m_entries[size_t(a)].box.min.x, mb = m_entries[size_t(b)].box.min.x;
        return ma < mb || (ma == mb && a < b);
    });
    const float stepDelta = continuous ? delta : 0.0f;
    // Planes first: when the contact budget fills, the ground is the last thing to lose.
    for (int p : m_planes)
        for (int i : m_order) {
            if (p < i)
                testPair(m_entries[size_t(p)], m_entries[size_t(i)], stepDelta);
            else
                testPair(m_entries[size_t(i)], m_entries[size_t(p)], stepDelta);
        }
    for (size_t oi = 0; oi < m_order.size(); ++oi) {
        const Entry& a = m_entries[size_t(m_order[oi])];
        for (size_t oj = oi + 1; oj < m_order.size(); ++oj) {
            const Entry& b = m_entries[size_t(m_order[oj])];
            if (b.box.min.x > a.box.max.x) break;
            if (b.box.min.y > a.box.max.y || a.box.min.y > b.box.max.y || b.box.min.z > a.box.max.z ||
                a.box.min.z > b.box.max.z)
                continue;
            if (m_order[oi] < m_order[oj])
                testPair(a, b, stepDelta);
            else
                testPair(b, a, stepDelta);
        }
    }
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

bool SimpleCollisionSpace::setContactBudget(size_t maxContacts) {
    if (maxContacts == 0) {
        error(L"iContactBudget::setContactBudget: the budget must be at least 1 contact; unchanged");
        return false;
    }
    m_budget = maxContacts;
    return true;
}

extern "C" iCollisionSpace* CreateSimpleCollisionSpace(size_t samplesPerSecond) {
    return new SimpleCollisionSpace(samplesPerSecond);
}
