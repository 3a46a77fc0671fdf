// SpaceWake.cpp - a sleeping body whose support changed wakes: what it touched when last tested moved, was
// reshaped (iCPlane::setPlane, a new radius), was given another body or a new filter (iCollisionFilter.h),
// lost its body or left the space. So does a sleeping body whose own geometry changed or left the space.
//
// A pair of two resting things is not tested (SimpleCollisionSpace::testPair), so nothing else would notice:
// a crate asleep on a bridge the game deleted, on a platform it moved away or on a floor it lowered hung in
// the air, since nothing touching it was moving. The rule is Box2D's (a contact that stops touching wakes
// both bodies), applied where the space sees it: to the last call's touching pairs (m_touching), before this
// call's pairs are tested, so that the woken body's pairs are tested in this call. The walk is made only in
// a call where something that may hold a sleeping body changed (m_restChanged): a resting scene pays nothing.
// A resting geometry added into a body asleep there before it (a wall, a plane) wakes that body too, before
// any pair is tested, so the contacts do not depend on the broadphase's order. Bodies added asleep together
// with what they rest on (a level loaded settled) stay asleep.
// Only the simulator's bodies sleep; they are woken through iRigidBodyMotion::wake.
#include "Narrowphase.h"
#include "RBDynamics.h"
#include "SimpleCollisionSpace.h"
#include "iRigidBody.h"
#include "iRigidBodyMotion.h"

SimpleCollisionSpace::Entry* SimpleCollisionSpace::activeEntryOf(const CollisionGeometry* g) {
    const int i = g->spaceState().entry; // its entry, if it took part in this call
    return i >= 0 && size_t(i) < m_entries.size() && m_entries[size_t(i)].g == g &&
                   m_entries[size_t(i)].active
               ? &m_entries[size_t(i)]
               : nullptr;
}

// entry: the body's entry in this call, if gathered already (its pairs are then tested now, not skipped as
// resting); nullptr when the wake comes before the entries are gathered (a removal settled).
void SimpleCollisionSpace::wakeSleeper(iRigidBody* body, Entry* entry) {
    if (!body || !body->getDynamics().attachmentRoot()->sleeping) return;
    if (iRigidBodyMotion* motion = motionOf(body)) motion->wake();
    if (entry) entry->fixed = false;
}

void SimpleCollisionSpace::wakeDisturbedSleepers() {
    for (const Notice& n : m_touching) {
        if (n.sensor) continue; // an overlap with a sensor holds nothing up
        Entry* a = activeEntryOf(n.g1);
        Entry* b = activeEntryOf(n.g2);
        const bool aStays = a && a->body == n.b1, bStays = b && b->body == n.b2;
        if (aStays && bStays && !a->disturbed && !b->disturbed) continue; // the pair is as it was
        if (aStays) wakeSleeper(a->body, a);
        if (bStays) wakeSleeper(b->body, b);
    }
}

void SimpleCollisionSpace::wakeSleepersUnderNewcomers(const std::pair<int, int>* pairs, size_t count) {
    const auto overlap = [this](const Entry& a, const Entry& b) {
        for (int i = a.first; i < a.last; ++i)
            for (int j = b.first; j < b.last; ++j)
                if (gcol::shapesOverlap(m_shapes[size_t(i)], m_shapes[size_t(j)])) return true;
        return false;
    };
    for (size_t k = 0; k < count; ++k) {
        Entry& a = m_entries[size_t(pairs[k].first)];
        Entry& b = m_entries[size_t(pairs[k].second)];
        if (a.sensor || b.sensor || !layersCollide(a.layer, a.mask, b.layer, b.mask)) continue;
        Entry* sleeper = a.newcomer && a.fixed && b.asleep && !b.newcomer   ? &b
                         : b.newcomer && b.fixed && a.asleep && !a.newcomer ? &a
                                                                            : nullptr;
        if (sleeper && sleeper->body && sleeper->body->getDynamics().attachmentRoot()->sleeping &&
            overlap(a, b))
            wakeSleeper(sleeper->body, sleeper);
    }
}
