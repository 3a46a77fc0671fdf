// FilterDifferential.h - collision filters and contact events against brute force: random scenes where
// geometries get random layers, masks and sensor flags. A space's contacts must name exactly the pairs a
// brute-force loop over all pairs finds overlapping and the layer rule lets through, minus those with a
// sensor; its contact events (per body pair, a sensor overlap a pair of its own) must begin, persist and end
// exactly as the brute-force pair sets of two calls say. Reusable: pass any space factory.
#pragma once

#include "SpaceDifferential.h"
#include "iCollisionFilter.h"
#include "iContactEvents.h"

#include <cstdint>
#include <tuple>

namespace spacediff {

// A pair as contact events name it: its two sides (a body, or a bodiless geometry) in address order, and
// whether a sensor is involved.
using EventKey = std::tuple<std::uintptr_t, std::uintptr_t, bool>;

inline std::uintptr_t sideOf(iCollisionGeometry* g) {
    iRigidBody* b = g->getRigidBody();
    return b ? reinterpret_cast<std::uintptr_t>(b) : reinterpret_cast<std::uintptr_t>(g);
}

inline EventKey eventKey(std::uintptr_t a, std::uintptr_t b, bool sensor) {
    return EventKey(std::min(a, b), std::max(a, b), sensor);
}

struct EventLog final : ContactObserver {
    std::set<EventKey> begun, persisted, ended;
    int calls = 0;
    void record(std::set<EventKey>& into, const ContactPair& p) {
        ++calls;
        auto side = [](iRigidBody* b, iCollisionGeometry* g) {
            return b ? reinterpret_cast<std::uintptr_t>(b) : reinterpret_cast<std::uintptr_t>(g);
        };
        EXPECT_TRUE(
            into.insert(eventKey(side(p.bodyA, p.geometryA), side(p.bodyB, p.geometryB), p.sensor)).second)
            << "a pair reported twice in one delivery";
    }
    void onBegin(const ContactPair& p) override { record(begun, p); }
    void onPersist(const ContactPair& p) override { record(persisted, p); }
    void onEnd(const ContactPair& p) override { record(ended, p); }
    void clear() {
        begun.clear();
        persisted.clear();
        ended.clear();
    }
};

// Brute force: the solid geometry pairs (contacts) and the event pairs of the scene as it is now.
inline void bruteForcePairs(const std::vector<iCollisionGeometry*>& geoms,
                            std::set<std::pair<iCollisionGeometry*, iCollisionGeometry*>>& solid,
                            std::set<EventKey>& events) {
    solid.clear();
    events.clear();
    for (size_t i = 0; i < geoms.size(); ++i)
        for (size_t j = i + 1; j < geoms.size(); ++j) {
            iCollisionGeometry *a = geoms[i], *b = geoms[j];
            iRigidBody *ba = a->getRigidBody(), *bb = b->getRigidBody();
            if (ba && ba == bb) continue;
            if (fixedBody(ba) && fixedBody(bb)) continue;
            const iCollisionFilter *fa = filterOf(a), *fb = filterOf(b);
            if (!layersCollide(fa->getLayer(), fa->getMask(), fb->getLayer(), fb->getMask())) continue;
            gcol::WorldShape sa, sb;
            if (!referenceShape(a, sa) || !referenceShape(b, sb)) continue;
            gcol::ContactManifold m;
            if (gcol::collideShapes(sa, sb, m) == 0) continue;
            const bool sensor = fa->isSensor() || fb->isSensor();
            if (!sensor) solid.insert(std::minmax(a, b));
            events.insert(eventKey(sideOf(a), sideOf(b), sensor));
        }
}

inline std::set<std::pair<iCollisionGeometry*, iCollisionGeometry*>> contactPairs(iCollisionSpace* space) {
    std::set<std::pair<iCollisionGeometry*, iCollisionGeometry*>> out;
    const CollisionContact* c = space->getContactList();
    for (size_t k = 0; k < space->getNumContacts(); ++k) out.insert(std::minmax(c[k].g1, c[k].g2));
    return out;
}

// Four layers; each geometry in one, colliding with a random subset; one in six a sensor.
inline void randomFilter(iCollisionGeometry* g, const std::function<int(int)>& pick) {
    iCollisionFilter* f = filterOf(g);
    ASSERT_NE(f, nullptr);
    f->setLayer(1u << pick(4));
    f->setMask(std::uint32_t(pick(16)) | (pick(3) == 0 ? 0u : 0xFFFFFFF0u));
    f->setSensor(pick(6) == 0);
}

inline void checkFiltersAgainstBruteForce(const std::function<iCollisionSpace*()>& makeSpace, Scene scene,
                                          unsigned seed, int count) {
    std::mt19937 gen(seed);
    auto uni = [&](float a, float b) { return std::uniform_real_distribution<float>(a, b)(gen); };
    std::function<int(int)> pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(gen); };
    iCollisionSpace* space = makeSpace();
    DefaultSpace joins(space);
    EventLog log;
    ASSERT_TRUE(contactEventsOf(space)->addObserver(&log));
    std::vector<std::unique_ptr<UserBody>> bodies;
    std::vector<iCollisionGeometry*> geoms;
    const float extent = scene == Scene::Sparse ? 60.0f : scene == Scene::Dense ? 6.0f : 20.0f;
    auto somewhere = [&] { return Vector(uni(-extent, extent), uni(-extent, extent), uni(-extent, extent)); };
    for (int i = 0; i < count; ++i) {
        UserBody* body = nullptr;
        if (!bodies.empty() && pick(10) == 0) {
            body = bodies[size_t(pick(int(bodies.size())))].get(); // a compound: its geometries count once
        } else if (pick(40) != 0) {
            bool fixed = scene == Scene::MostlyFixed ? pick(10) < 7 : pick(10) == 0;
            bodies.emplace_back(new UserBody(somewhere(), fixed ? PHYS_FixedInSpace : PHYS_Falling));
            body = bodies.back().get();
        }
        float size = scene == Scene::Mixed && pick(4) == 0 ? uni(2.0f, 6.0f) : uni(0.2f, 1.5f);
        int kind = pick(20);
        iCollisionGeometry* g =
            kind == 0 ? CreateCPlane(pick(2) ? body : nullptr, Vector(uni(-0.3f, 0.3f), 1, uni(-0.3f, 0.3f)),
                                     uni(-extent, 0))
            : kind < 10 ? CreateCSphere(body, size)
                        : CreateCOBB(body, Vector(size, uni(0.2f, 1.0f) * size, uni(0.2f, 1.0f) * size));
        randomFilter(g, pick);
        geoms.push_back(g);
    }
    std::set<std::pair<iCollisionGeometry*, iCollisionGeometry*>> solid;
    std::set<EventKey> before, after;
    // Call 1: every touching pair begins.
    space->populateContactList(0.0f);
    bruteForcePairs(geoms, solid, before);
    EXPECT_EQ(contactPairs(space), solid) << "contacts, call 1";
    EXPECT_EQ(log.begun, before) << "begin, call 1";
    EXPECT_TRUE(log.persisted.empty() && log.ended.empty());
    size_t sensors = 0;
    for (const EventKey& k : before) sensors += std::get<2>(k) ? 1 : 0;
    EXPECT_GT(sensors, 0u) << "the scene must have sensor overlaps to test";
    // Call 2: half the movable bodies jump (teleported: the current poses only).
    for (auto& b : bodies)
        if (b->getDynamics().physicsType != PHYS_FixedInSpace && pick(2) == 0) {
            b->getDynamics().position = somewhere();
            b->getDynamics().markTeleported();
        }
    log.clear();
    space->populateContactList(0.0f);
    bruteForcePairs(geoms, solid, after);
    EXPECT_EQ(contactPairs(space), solid) << "contacts, call 2";
    std::set<EventKey> begun, persisted, ended;
    for (const EventKey& k : after) (before.count(k) ? persisted : begun).insert(k);
    for (const EventKey& k : before)
        if (!after.count(k)) ended.insert(k);
    EXPECT_EQ(log.begun, begun) << "begin, call 2";
    EXPECT_EQ(log.persisted, persisted) << "persist, call 2";
    EXPECT_EQ(log.ended, ended) << "end, call 2";
    EXPECT_GT(ended.size() * begun.size() * persisted.size(), 0u) << "every kind of event must be tested";
    for (iCollisionGeometry* g : geoms) g->Delete();
    space->Delete(); // detaches the observer: its destructor must not reach the space
}

} // namespace spacediff
