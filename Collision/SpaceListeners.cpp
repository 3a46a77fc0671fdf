// SpaceListeners.cpp - HitWall notifications (of the pairs SpaceEvents.cpp says touch), and the deferred
// removals and deletions listeners ask for.
//
// Each touching body pair gets one call per notification on each side (the normal points toward
// `other`, so g1's body gets the contact normal and g2's body its negation). Listeners may detach listeners,
// remove or delete geometry, or delete bodies during the calls: the listener list is iterated from a
// snapshot (a listener detached meanwhile is not called), a body whose geometry was unbound (it died) gets
// no further calls and is not passed as `other`, and geometry removal/deletion waits until the calls end.
// Then contacts whose geometry was removed or deleted, or whose body changed, are dropped.
#include "GrowingArrays.h"
#include "SimpleCollisionSpace.h"
#include "iCollisionListener.h"
#include "iRigidBody.h"

#include <algorithm>
#include <cstdint>

void SimpleCollisionSpace::notifyListeners(const std::vector<Notice>& notices) {
    // Nobody listening (a scene of many bodies, most often): nothing to sort or tell. (A body is asked only
    // while its geometry is bound to it: a deleted one was unbound.)
    bool anyone = false;
    for (size_t i = 0; i < notices.size() && !anyone; ++i) {
        const Notice& n = notices[i];
        anyone = !n.sensor && ((n.b1 && n.g1->stillBoundTo(n.b1) && !n.b1->getListeners().empty()) ||
                               (n.b2 && n.g2->stillBoundTo(n.b2) && !n.b2->getListeners().empty()));
    }
    if (!anyone) {
        finishNotifications();
        return;
    }
    // One notice per body pair, the first one listed. Sensor overlaps are not HitWalls (contact events only).
    // Sorted by (body pair, place in the list): the keys are computed once (this sort ran 12 % of an awake
    // pyramid's frame when each comparison computed them).
    m_bodyPairs.clear();
    for (size_t i = 0; i < notices.size(); ++i) {
        if (notices[i].sensor) continue;
        const auto x = reinterpret_cast<std::uintptr_t>(notices[i].b1);
        const auto y = reinterpret_cast<std::uintptr_t>(notices[i].b2);
        m_bodyPairs.push_back({std::min(x, y), std::max(x, y), i});
    }
    std::sort(m_bodyPairs.begin(), m_bodyPairs.end(), [](const BodyPair& a, const BodyPair& b) {
        return a.lo != b.lo ? a.lo < b.lo : a.hi != b.hi ? a.hi < b.hi : a.index < b.index;
    });
    gcol::assignGrowing(m_repeat, notices.size(), decltype(m_repeat)::value_type(0));
    for (size_t i = 1; i < m_bodyPairs.size(); ++i) {
        const BodyPair &p = m_bodyPairs[i], &q = m_bodyPairs[i - 1];
        if (p.lo == q.lo && p.hi == q.hi) m_repeat[p.index] = 1; // a repeat: the first one listed stays
    }
    m_notifying = true;
    for (size_t i = 0; i < notices.size(); ++i) {
        const Notice& n = notices[i];
        if (n.points == 0 || m_repeat[i] || n.sensor) continue;
        for (int side = 0; side < 2; ++side) {
            iRigidBody* self = side == 0 ? n.b1 : n.b2;
            iRigidBody* other = side == 0 ? n.b2 : n.b1;
            CollisionGeometry* selfGeom = side == 0 ? n.g1 : n.g2;
            CollisionGeometry* otherGeom = side == 0 ? n.g2 : n.g1;
            Vector normal = side == 0 ? n.normal : -n.normal;
            // Bound-ness first: it compares pointers only, and a body deleted by an earlier call must not be
            // touched.
            if (!self || !selfGeom->stillBoundTo(self) || !otherGeom->stillBoundTo(other)) continue;
            if (self->getListeners().empty()) continue; // nobody to tell
            m_listenerSnapshot = self->getListeners();
            for (iCollisionListener* l : m_listenerSnapshot) {
                if (!selfGeom->stillBoundTo(self) || !otherGeom->stillBoundTo(other)) break;
                const std::vector<iCollisionListener*>& now = self->getListeners();
                if (std::find(now.begin(), now.end(), l) == now.end()) continue;
                l->HitWall(other, normal, n.pos);
            }
        }
    }
    m_notifying = false;
    finishNotifications();
}

void SimpleCollisionSpace::finishNotifications() {
    if (m_pendingRemove.empty() && m_pendingDelete.empty()) {
        // Bodies may still have died or been rebound: binding resets hasPrevious, which populate set. (The
        // contacts name only geometry still here; this call's entries may be stale when events are delivered
        // later.)
        bool changed = false;
        for (const auto& [g1, g2] : m_contactGeoms)
            changed = changed || !g1->spaceState().hasPrevious || !g2->spaceState().hasPrevious;
        if (!changed) return;
    }
    auto alive = [](const CollisionGeometry* g) {
        const CollisionGeometry::SpaceState& st = g->spaceState();
        return st.hasPrevious && !st.pendingDelete && !st.pendingRemove;
    };
    keepContacts(
        [&alive](const CollisionGeometry* a, const CollisionGeometry* b) { return alive(a) && alive(b); });
    for (CollisionGeometry* g : m_pendingRemove)
        if (!g->spaceState().pendingDelete) removeNow(g);
    m_pendingRemove.clear();
    std::vector<CollisionGeometry*> doomed;
    doomed.swap(m_pendingDelete);
    for (CollisionGeometry* g : doomed) {
        removeNow(g);
        delete g;
    }
}
