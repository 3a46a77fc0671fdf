// SpaceEvents.cpp - which pairs the simple space reports as touching, and when listeners hear of them.
//
// A pair is touching when this call's test found contact, or when it was not tested because both bodies
// rest (fixed or asleep, and not moved) and it touched when last tested: sleeping hides no contact. Listeners
// hear of the touching pairs at the end of each populateContactList, or, with events held (a physics scene
// stepping several times a frame), once per body pair in deliverEvents; contact observers at the same
// moments, after the listeners (SpaceContactEvents.cpp).
#include "SimpleCollisionSpace.h"
#include "iUtilities.h"

#include <algorithm>
#include <functional>
#include <tuple>

namespace {

// Keeps one notice of each geometry pair (the first one listed), in the order they were listed: the order
// listeners hear them in must not depend on where the heap put the objects.
void dropRepeats(std::vector<SimpleCollisionSpace::Notice>& notices) {
    using Notice = SimpleCollisionSpace::Notice;
    auto key = [&notices](size_t i) {
        const Notice& n = notices[i];
        return std::make_tuple(n.g1, n.g2, n.b1, n.b2);
    };
    std::vector<size_t> order(notices.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&key](size_t a, size_t b) {
        return std::less<>()(key(a), key(b)) || (key(a) == key(b) && a < b);
    });
    std::vector<bool> repeat(notices.size(), false);
    for (size_t k = 1; k < order.size(); ++k)
        if (key(order[k]) == key(order[k - 1])) repeat[order[k]] = true;
    size_t kept = 0;
    for (size_t i = 0; i < notices.size(); ++i)
        if (!repeat[i]) notices[kept++] = notices[i];
    notices.resize(kept);
}

} // namespace

void SimpleCollisionSpace::carryRestingPairs() {
    for (const Notice& n : m_touching) {
        const Entry* a = activeEntryOf(n.g1);
        const Entry* b = activeEntryOf(n.g2);
        // Tested this call (its own result stands), or gone, or rebound: not carried.
        if (!a || !b || a->body != n.b1 || b->body != n.b2 || !a->fixed || !b->fixed) continue;
        m_notices.push_back(n);
    }
}

// The notices held since the last delivery: the first held call's are m_touching's until a second call
// comes (a frame of one step, the usual case, copies none), then every held call's are in m_held.
void SimpleCollisionSpace::reportTouching() {
    if (m_heldCalls == 1) m_held.insert(m_held.end(), m_touching.begin(), m_touching.end());
    m_touching.swap(m_notices); // (the next call clears m_notices before it lists anything)
    if (!m_holdEvents) {
        if (m_heldCalls > 0) m_heldCalls = 2; // what is held is no longer what touches now: deliver both
        if (!m_observers.empty()) gatherContactPairs(m_touching);
        notifyListeners(m_touching);
        deliverContactEvents();
        return;
    }
    if (++m_heldCalls > 1) m_held.insert(m_held.end(), m_touching.begin(), m_touching.end());
    // A game that holds events and never delivers them keeps only one notice per pair.
    if (m_held.size() > 8 * (m_touching.size() + 64)) dropRepeats(m_held);
}

void SimpleCollisionSpace::deliverEvents() {
    settleRemovals();
    if (m_notifying || m_populating) {
        error(L"iCollisionEvents::deliverEvents: called from inside a listener; ignored");
        return;
    }
    // The latest contact of a pair still touching first: notifyListeners keeps the first of each body pair.
    // One call held (a frame of one step, the usual case): what it held is what still touches, m_touching
    // itself, delivered as it is (not listed twice, nor copied).
    const bool several = m_heldCalls > 1;
    if (several) {
        m_delivery = m_touching;
        m_delivery.insert(m_delivery.end(), m_held.begin(), m_held.end());
    }
    const std::vector<Notice>& delivery = several ? m_delivery : m_touching;
    m_held.clear();
    m_heldCalls = 0;
    if (!m_observers.empty()) gatherContactPairs(delivery);
    notifyListeners(delivery);
    deliverContactEvents();
}

void SimpleCollisionSpace::forgetEventsOfGone() {
    auto involves = [this](const Notice& n) { return isGone(n.g1) || isGone(n.g2); };
    for (const Notice& n : m_touching) // what slept on removed geometry wakes (SpaceWake.cpp)
        if (!n.sensor && isGone(n.g1) != isGone(n.g2))
            wakeSleeper((isGone(n.g1) ? n.g2 : n.g1)->body(), nullptr);
    m_touching.erase(std::remove_if(m_touching.begin(), m_touching.end(), involves), m_touching.end());
    m_held.erase(std::remove_if(m_held.begin(), m_held.end(), involves), m_held.end());
    forgetContactPairsOfGone();
}
