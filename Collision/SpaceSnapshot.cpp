// SpaceSnapshot.cpp - a space's state saved and put back (iSnapshots.h): what the next populateContactList
// reads from the calls before it. Each geometry's previous pose (the start of its swept motion), the pairs
// touching at the last call (the continuous stage treats them as touching at the start; listeners hear them
// carried over), and the events held for delivery. The broadphase keeps nothing the pairs depend on but the
// boxes (its pairs follow the entries' boxes, whatever calls made them), and the entries' cache holds only
// what a pose gives (shapes, boxes): its note that the previous pose is the current one is dropped here.
#include "CollisionGeometry.h"
#include "SimpleCollisionSpace.h"

#include "iUtilities.h"

namespace {

class SpaceSnapshot final : public iSnapshot {
public:
    void Delete() const override { delete this; }

    const SimpleCollisionSpace* owner = nullptr;
    unsigned long long membership = 0;
    struct Member {
        CollisionGeometry* geometry;
        iRigidBody* body; // bound then: a geometry rebound since refuses the restore
        CollisionGeometry::SpaceState state;
    };
    std::vector<Member> members;
    std::vector<SimpleCollisionSpace::Notice> touching, held;
    int heldCalls = 0;
    unsigned long long call = 0;
};

} // namespace

iSnapshot* SimpleCollisionSpace::takeSnapshot() const {
    settle();
    if (m_notifying) {
        error(L"iSnapshots::takeSnapshot: the space is notifying listeners; take it after the update");
        return nullptr;
    }
    SpaceSnapshot* s = new SpaceSnapshot();
    s->owner = this;
    s->membership = m_membership;
    s->members.reserve(m_members.size());
    for (CollisionGeometry* g : m_members) s->members.push_back({g, g->body(), g->spaceState()});
    s->touching = m_touching;
    s->held = m_held;
    s->heldCalls = m_heldCalls;
    s->call = m_call;
    return s;
}

bool SimpleCollisionSpace::restoreSnapshot(const iSnapshot* snapshot) {
    settleRemovals();
    const SpaceSnapshot* s = dynamic_cast<const SpaceSnapshot*>(snapshot);
    if (!s || s->owner != this) {
        error(L"iSnapshots::restoreSnapshot: not a snapshot of this space; refused");
        return false;
    }
    if (m_notifying) {
        error(L"iSnapshots::restoreSnapshot: the space is notifying listeners; refused");
        return false;
    }
    bool same = s->membership == m_membership && s->members.size() == m_members.size();
    for (size_t i = 0; same && i < m_members.size(); ++i)
        same = s->members[i].geometry == m_members[i] && s->members[i].body == m_members[i]->body();
    if (!same) {
        error(L"iSnapshots::restoreSnapshot: geometry was added, removed or rebound since the snapshot; "
              L"refused");
        return false;
    }
    for (const SpaceSnapshot::Member& m : s->members) {
        CollisionGeometry::SpaceState& st = m.geometry->spaceState();
        const int proxy = st.proxy, entry = st.entry; // the broadphase's and the entries', as they are now
        st = m.state;
        st.proxy = proxy;
        st.entry = entry;
    }
    for (Entry& e : m_entries) { // the previous poses are the snapshot's now, and the space states are
        e.cache.prevIsPose = false;
        e.cache.mirrored = false;
    }
    m_touching = s->touching;
    m_held = s->held;
    m_heldCalls = s->heldCalls;
    m_call = s->call;
    m_contacts.clear(); // the list of the call before the snapshot's is not this state's
    m_features.clear();
    m_contactGeoms.clear();
    return true;
}
