// SpaceContactEvents.cpp - contact begin, persist and end per body pair for the observers attached to the
// space (iContactEvents.h).
//
// At each delivery (the moment listeners hear HitWall: SpaceEvents.cpp) the touching notices become one
// pair per (side, side, sensor), a side being a body or a bodiless geometry; compared with the pairs of the
// last delivery, a new pair begins, a pair in both persists, and a pair only in the last one (or whose side
// went: a body destroyed, a bodiless geometry removed) ends. Nothing is kept while no observer is attached.
// Delivery order does not depend on addresses: ends in the order their pairs were found at the last
// delivery, then begins and persists in the order of this one's notices.
#include "SimpleCollisionSpace.h"
#include "iRigidBody.h"
#include "iUtilities.h"

#include <algorithm>
#include <cstdint>
#include <tuple>

namespace {

// A side of a pair: its body, or a geometry that has none (a plane).
std::uintptr_t sideOf(const CollisionGeometry* g, const iRigidBody* b) {
    return b ? reinterpret_cast<std::uintptr_t>(b) : reinterpret_cast<std::uintptr_t>(g);
}

template <class Pair> auto keyOf(const Pair& p) { return std::make_tuple(p.lo, p.hi, p.sensor); }

} // namespace

bool SimpleCollisionSpace::addObserver(ContactObserver* observer) {
    if (!observer) {
        error(L"iContactEvents::addObserver: null observer refused");
        return false;
    }
    for (const ObserverSlot& s : m_observers)
        if (s.observer == observer) {
            error(L"iContactEvents::addObserver: the observer is already attached; refused");
            return false;
        }
    // The first observer starts from nothing: what was kept for earlier ones is stale.
    if (m_observers.empty() && !m_deliveringContacts) m_active.clear();
    m_observers.push_back({observer, true});
    ContactObserverLinks::linked(observer, this);
    return true;
}

bool SimpleCollisionSpace::removeObserver(ContactObserver* observer) {
    auto it = std::find_if(m_observers.begin(), m_observers.end(),
                           [observer](const ObserverSlot& s) { return s.observer == observer; });
    if (it == m_observers.end()) return false;
    m_observers.erase(it);
    ContactObserverLinks::unlinked(observer, this);
    return true;
}

void SimpleCollisionSpace::gatherContactPairs(const std::vector<Notice>& notices) {
    m_current.clear();
    for (size_t i = 0; i < notices.size(); ++i) {
        const Notice& n = notices[i];
        if (!n.g1->stillBoundTo(n.b1) || !n.g2->stillBoundTo(n.b2)) continue; // a body died or was rebound
        const std::uintptr_t a = sideOf(n.g1, n.b1), b = sideOf(n.g2, n.b2);
        ActivePair p;
        p.lo = std::min(a, b);
        p.hi = std::max(a, b);
        p.sensor = n.sensor;
        p.gone = false;
        p.announced = false;
        p.order = i;
        p.pair.bodyA = n.b1;
        p.pair.bodyB = n.b2;
        p.pair.geometryA = n.g1->asInterface();
        p.pair.geometryB = n.g2->asInterface();
        p.pair.sensor = n.sensor;
        p.pair.normal = n.normal;
        p.pair.point = n.pos;
        p.gA = n.g1;
        p.gB = n.g2;
        m_current.push_back(p);
    }
    // One per pair, the first listed (with events held, the latest contact comes first).
    std::sort(m_current.begin(), m_current.end(), [](const ActivePair& x, const ActivePair& y) {
        return keyOf(x) != keyOf(y) ? keyOf(x) < keyOf(y) : x.order < y.order;
    });
    m_current.erase(
        std::unique(m_current.begin(), m_current.end(),
                    [](const ActivePair& x, const ActivePair& y) { return keyOf(x) == keyOf(y); }),
        m_current.end());
    m_gathered = true;
}

void SimpleCollisionSpace::deliverContactEvents() {
    settleDeadBodies(); // a listener may have deleted a body since the last call began
    if (!m_gathered) return;
    m_gathered = false;
    // Match this delivery's pairs with the last one's (both sorted by sides).
    m_contactEvents.clear();
    size_t i = 0, j = 0;
    while (i < m_active.size() || j < m_current.size()) {
        const bool lastOnly =
            j == m_current.size() || (i < m_active.size() && keyOf(m_active[i]) < keyOf(m_current[j]));
        const bool currentOnly =
            i == m_active.size() || (j < m_current.size() && keyOf(m_current[j]) < keyOf(m_active[i]));
        if (lastOnly) {
            m_contactEvents.push_back({0, i++});
        } else if (currentOnly) {
            m_contactEvents.push_back({1, j++});
        } else if (m_active[i].gone) { // the same addresses, but a side went: a new pair
            m_contactEvents.push_back({0, i++});
            m_contactEvents.push_back({1, j++});
        } else {
            m_current[j].announced = m_active[i].announced;
            m_contactEvents.push_back({m_active[i].announced ? 2 : 1, j++});
            ++i;
        }
    }
    // Ends first; within each list the orders are distinct (one pair per notice at most): a total order.
    std::sort(m_contactEvents.begin(), m_contactEvents.end(),
              [this](const ContactEvent& x, const ContactEvent& y) {
                  if ((x.kind == 0) != (y.kind == 0)) return x.kind == 0;
                  const auto& list = x.kind == 0 ? m_active : m_current;
                  return list[x.index].order < list[y.index].order;
              });
    m_observerSnapshot = m_observers;
    m_notifying = true;
    m_deliveringContacts = true;
    for (const ContactEvent& e : m_contactEvents) {
        ActivePair& p = e.kind == 0 ? m_active[e.index] : m_current[e.index];
        if (e.kind == 0 && !p.announced) continue; // nobody heard it begin
        if (e.kind != 0 && p.gone) continue;       // a side went during these calls: it ends next time
        if (e.kind != 0) p.announced = true;
        for (const ObserverSlot& was : m_observerSnapshot) {
            // Still attached (a destroyed observer detached itself), and not attached during these calls.
            auto now = std::find_if(m_observers.begin(), m_observers.end(),
                                    [&was](const ObserverSlot& s) { return s.observer == was.observer; });
            if (now == m_observers.end() || (now->fresh && !was.fresh)) continue;
            const ContactPair pair = p.pair; // a copy: a body dying during the call nulls p.pair
            if (e.kind == 0) {
                if (!was.fresh) was.observer->onEnd(pair);
            } else if (e.kind == 1 || was.fresh) {
                was.observer->onBegin(pair);
            } else {
                was.observer->onPersist(pair);
            }
        }
    }
    m_deliveringContacts = false;
    m_notifying = false;
    for (ObserverSlot& s : m_observers)
        for (const ObserverSlot& was : m_observerSnapshot)
            if (s.observer == was.observer && was.fresh == s.fresh) s.fresh = false;
    m_active.swap(m_current);
    m_current.clear();
    if (m_observers.empty()) m_active.clear();
    finishNotifications();
}

void SimpleCollisionSpace::forgetContactPairsOfGone() {
    for (auto* list : {&m_active, &m_current})
        for (ActivePair& p : *list) {
            if (isGone(p.gA)) {
                p.gA = nullptr;
                p.pair.geometryA = nullptr;
            }
            if (isGone(p.gB)) {
                p.gB = nullptr;
                p.pair.geometryB = nullptr;
            }
            // A bodiless side is the geometry itself: it went.
            if (isGone(reinterpret_cast<const void*>(p.lo)) || isGone(reinterpret_cast<const void*>(p.hi)))
                p.gone = true;
        }
}

// A body's death names no pair at once (each death would walk every pair: quadratic when a scene with an
// observer is torn down): its address is kept and the pairs are walked once, at the next call that reads
// them (settleDeadBodies), before any new body could appear in a pair. While the pairs are being delivered
// an observer may delete a body: the pairs are walked at once then, so no later call of that delivery is
// handed the dead body.
void SimpleCollisionSpace::onBodyDestroyed(const iRigidBody* dying, void* self) {
    auto* space = static_cast<SimpleCollisionSpace*>(self);
    if (space->m_active.empty() && space->m_current.empty()) return;
    space->m_deadBodies.push_back(dying);
    if (space->m_deliveringContacts) space->settleDeadBodies();
}

void SimpleCollisionSpace::settleDeadBodies() {
    if (m_deadBodies.empty()) return;
    std::sort(m_deadBodies.begin(), m_deadBodies.end());
    auto dead = [this](const iRigidBody* b) {
        return b && std::binary_search(m_deadBodies.begin(), m_deadBodies.end(), b);
    };
    for (auto* list : {&m_active, &m_current})
        for (ActivePair& p : *list) {
            if (dead(p.pair.bodyA)) {
                p.pair.bodyA = nullptr;
                p.gone = true;
            }
            if (dead(p.pair.bodyB)) {
                p.pair.bodyB = nullptr;
                p.gone = true;
            }
        }
    m_deadBodies.clear();
}
