// Islands.cpp - union-find over the scene's bodies, and sleeping and waking by island (Islands.h).
#include "Islands.h"

#include "RigidBody.h"
#include "iCollisionGeometry.h"
#include "iCollisionSpace.h"

#include <algorithm>

namespace physics {

int Islands::find(int i) const {
    while (m_parent[i] != i) i = m_parent[i] = m_parent[m_parent[i]];
    return i;
}

void Islands::build(const std::vector<RigidBody*>& bodies, const SceneBodyAccess::BodyMap& byDynamics,
                    const CollisionContact* contacts, size_t count) {
    m_index.clear();
    m_parent.clear();
    for (RigidBody* b : bodies) {
        if (b->getDynamics().attachedTo() || b->getDynamics().physicsType == PHYS_FixedInSpace) continue;
        m_index.emplace(b, int(m_parent.size()));
        m_parent.push_back(int(m_parent.size()));
    }
    auto islandOf = [&](iCollisionGeometry* g) -> int {
        iRigidBody* rb = g ? g->getRigidBody() : nullptr;
        if (!rb) return -1;
        RigidBody* const* body = byDynamics.find(rb->getDynamics().attachmentRoot());
        if (!body) return -1;
        const int* index = m_index.find(*body);
        return index ? *index : -1;
    };
    m_pushed.assign(m_parent.size(), 0);
    m_outsidersNext.clear();
    for (size_t i = 0; contacts && i < count; ++i) {
        int a = islandOf(contacts[i].g1), b = islandOf(contacts[i].g2);
        if ((a < 0) != (b < 0)) { // an island member and something outside the islands
            iRigidBody* outside = (a < 0 ? contacts[i].g1 : contacts[i].g2)->getRigidBody();
            if (outside && outsiderMoves(outside->getDynamics())) m_pushed[size_t(a < 0 ? b : a)] = 1;
        }
        if (a < 0 || b < 0) continue;
        a = find(a);
        b = find(b);
        if (a != b) m_parent[std::max(a, b)] = std::min(a, b); // the lower index leads: order, not addresses
    }
}

void Islands::join(const RigidBody* a, const RigidBody* b) {
    const int* ia = a ? m_index.find(a) : nullptr;
    const int* ib = b ? m_index.find(b) : nullptr;
    if (!ia || !ib) return;
    const int x = find(*ia), y = find(*ib);
    if (x != y) m_parent[size_t(std::max(x, y))] = std::min(x, y);
}

bool Islands::outsiderMoves(const RBDynamics& body) {
    const RBDynamics& d = *body.attachmentRoot();
    Pose now{d.position, d.orientation};
    const Pose* before = m_outsiders.find(&d);
    bool moves = d.velocity != Vector() || d.angularVelocity != Vector() || !before ||
                 before->position != now.position || before->orientation != now.orientation;
    m_outsidersNext[&d] = now;
    return moves;
}

void Islands::wakeTouched(const std::vector<RigidBody*>& bodies) {
    m_outsiders.swap(m_outsidersNext);
    std::vector<char>& awake = m_awake;
    awake.assign(m_parent.size(), 0);
    for (size_t i = 0; i < m_pushed.size(); ++i)
        if (m_pushed[i]) awake[find(int(i))] = 1;
    for (RigidBody* b : bodies) {
        const int* it = m_index.find(b);
        if (it && !b->asleep()) awake[find(*it)] = 1;
    }
    for (RigidBody* b : bodies) {
        const int* it = m_index.find(b);
        if (it && b->asleep() && awake[find(*it)]) {
            b->setAsleep(false);
            b->restTime = 0;
        }
    }
}

bool Islands::wakeIslandMates(const std::vector<RigidBody*>& bodies) {
    m_woken.clear();
    for (const RigidBody* b : bodies)
        if (b->sleepIsland != 0 && !b->asleep()) m_woken.push_back(b->sleepIsland);
    if (m_woken.empty()) return false;
    std::sort(m_woken.begin(), m_woken.end());
    bool woke = false;
    for (RigidBody* b : bodies) {
        if (b->sleepIsland == 0 || !std::binary_search(m_woken.begin(), m_woken.end(), b->sleepIsland))
            continue;
        b->sleepIsland = 0;
        if (!b->asleep() || b->dying() || b->pendingRemoval) continue;
        b->setAsleep(false);
        b->restTime = 0;
        woke = true;
    }
    return woke;
}

void Islands::updateSleep(const std::vector<RigidBody*>& bodies, float dt) {
    std::vector<float>& leastRest = m_leastRest;
    leastRest.assign(m_parent.size(), kTimeToSleep * 2);
    for (RigidBody* b : bodies) {
        const int* it = m_index.find(b);
        if (!it || b->asleep()) continue;
        const RBDynamics& d = b->getDynamics();
        bool resting = b->getSleepAllowed() && d.velocity.length() < m_sleepSpeed &&
                       d.angularVelocity.length() < kSleepSpeed; // never resting: its island stays awake
        b->restTime = resting ? b->restTime + dt : 0.0f;
        float& least = leastRest[find(*it)];
        least = std::min(least, b->restTime);
    }
    m_sleepIds.assign(m_parent.size(), 0);
    for (RigidBody* b : bodies) {
        const int* it = m_index.find(b);
        if (!it || b->asleep() || leastRest[find(*it)] < kTimeToSleep) continue;
        unsigned& id = m_sleepIds[size_t(find(*it))];
        if (id == 0) id = ++m_lastSleepId == 0 ? ++m_lastSleepId : m_lastSleepId; // 0 means none
        b->sleepIsland = id;
        RBDynamics& d = b->getDynamics();
        b->setAsleep(true);
        d.velocity = d.angularVelocity = d.angularMomentum = Vector();
        b->writtenOmega = b->writtenMomentum = Vector();
        b->own.omega = b->own.momentum = Vec3::Zero();
    }
}

} // namespace physics
