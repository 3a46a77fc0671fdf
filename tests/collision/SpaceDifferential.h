// SpaceDifferential.h - the differential test every collision space must pass: random scenes (sparse,
// dense, mixed sizes, fixed bodies, shared bodies, planes, bodiless geometry) where the space's contact
// list must name exactly the geometry pairs a brute-force loop over the pure pair functions finds: every
// overlapping pair, none twice, none false. Reusable: pass any space factory.
// checkAgainstReference runs a space beside a reference space (the simple one) over many calls on twin
// geometries of the same bodies, with moves, teleports, sleeping, fixing, adds and removes between calls:
// each call's contacts (per pair, in order, bit for bit) and ray and overlap queries (every other call in a
// batch) must be the same; with filters, twins get the same random layer, mask and sensor flag, changed now
// and then between calls; with rebinds, twins are also bound to another body (or none), resized, and their
// bodies deleted under them.
#pragma once

#include "DefaultSpace.h"
#include "MathEigen.h"
#include "Narrowphase.h"
#include "SimpleCollisionSpace.h"
#include "UserBody.h"
#include "iCOBB.h"
#include "iCPlane.h"
#include "iCSphere.h"
#include "iCollisionFilter.h"
#include "iCollisionQueries.h"
#include "iCollisionSpace.h"
#include "iContactFeatures.h"
#include "iUtilities.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <vector>

namespace spacediff {

enum class Scene { Sparse, Dense, Mixed, MostlyFixed };

// The shape a geometry has at its body's pose, built from the public interfaces only.
inline bool referenceShape(iCollisionGeometry* g, gcol::WorldShape& s) {
    iRigidBody* b = g->getRigidBody();
    Vector origin;
    Matrix r(1);
    if (b) {
        origin = b->getDynamics().getWorldOrigin();
        r = b->getDynamics().getWorldOrientation();
    }
    switch (g->getCollisionType()) {
    case CT_SPHERE:
        s.kind = gcol::ShapeKind::Sphere;
        s.sphere.centre = origin;
        s.sphere.radius = static_cast<iCSphere*>(g)->getRadius();
        return b != nullptr;
    case CT_OBB:
        s.kind = gcol::ShapeKind::Box;
        s.box.centre = origin;
        for (int i = 0; i < 3; ++i) s.box.axis[i] = r.direction(char('x' + i));
        s.box.halfExtents = static_cast<iCOBB*>(g)->getRadius();
        return b != nullptr;
    case CT_PLANE: {
        auto* p = static_cast<iCPlane*>(g);
        s.kind = gcol::ShapeKind::Plane;
        s.plane.normal = r.direction(p->getNormal()).normalize();
        s.plane.offset = p->getOffset() + dot(s.plane.normal, origin);
        return true;
    }
    }
    return false;
}

inline bool fixedBody(const iRigidBody* b) {
    return !b || b->getDynamics().attachmentRoot()->physicsType == PHYS_FixedInSpace;
}

// Builds a random scene in `space`, populates it with delta 0, and checks the contact list. With moveBy > 0
// the scene is populated once (delta 1/60), every movable body then jumps by up to moveBy, and it is
// populated again: the contacts must still include every pair touching now (the current pose is always
// tested), and any further pair must be marked as found by continuous sampling (feature id bit 31).
inline void checkAgainstBruteForce(const std::function<iCollisionSpace*()>& makeSpace, Scene scene,
                                   unsigned seed, int count, float moveBy = 0.0f) {
    std::mt19937 gen(seed);
    auto uni = [&](float a, float b) { return std::uniform_real_distribution<float>(a, b)(gen); };
    auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(gen); };
    iCollisionSpace* space = makeSpace();
    DefaultSpace joins(space); // new geometry joins it
    std::vector<std::unique_ptr<UserBody>> bodies;
    std::vector<iCollisionGeometry*> geoms;
    const float extent = scene == Scene::Sparse ? 60.0f : scene == Scene::Dense ? 6.0f : 20.0f;
    for (int i = 0; i < count; ++i) {
        UserBody* body = nullptr;
        if (!bodies.empty() && pick(10) == 0) {
            body = bodies[size_t(pick(int(bodies.size())))].get(); // shares a body: never collides with it
        } else if (pick(40) != 0) {
            bool fixed = scene == Scene::MostlyFixed ? pick(10) < 7 : pick(10) == 0;
            bodies.emplace_back(
                new UserBody(Vector(uni(-extent, extent), uni(-extent, extent), uni(-extent, extent)),
                             fixed ? PHYS_FixedInSpace : PHYS_Falling));
            Eigen::Quaternionf q(uni(-1, 1), uni(-1, 1), uni(-1, 1), uni(-1, 1));
            q.normalize();
            bodies.back()->getDynamics().orientation = gmath::fromBlock3(q.toRotationMatrix());
            if (pick(5) == 0)
                bodies.back()->getDynamics().com = Vector(uni(-0.3f, 0.3f), 0, uni(-0.3f, 0.3f));
            body = bodies.back().get();
        } // else: no body at all (never collides)
        float size = scene == Scene::Mixed && pick(4) == 0 ? uni(2.0f, 6.0f) : uni(0.2f, 1.5f);
        iCollisionGeometry* g;
        int kind = pick(20);
        if (kind == 0)
            g = CreateCPlane(pick(2) ? body : nullptr, Vector(uni(-0.3f, 0.3f), 1, uni(-0.3f, 0.3f)),
                             uni(-extent, 0));
        else if (kind < 10)
            g = CreateCSphere(body, size);
        else
            g = CreateCOBB(body, Vector(size, uni(0.2f, 1.0f) * size, uni(0.2f, 1.0f) * size));
        ASSERT_NE(g, nullptr);
        if (g->getSpace() != space) space->add(g);
        geoms.push_back(g);
    }
    if (moveBy > 0.0f) {
        space->populateContactList(1.0f / 60.0f);
        for (auto& b : bodies)
            if (b->getDynamics().physicsType != PHYS_FixedInSpace)
                b->getDynamics().position +=
                    Vector(uni(-moveBy, moveBy), uni(-moveBy, moveBy), uni(-moveBy, moveBy));
        space->populateContactList(1.0f / 60.0f);
    } else {
        space->populateContactList(0.0f);
    }

    // Brute force: every pair, the documented filters, the pure pair function.
    std::set<std::pair<iCollisionGeometry*, iCollisionGeometry*>> expected;
    for (size_t i = 0; i < geoms.size(); ++i)
        for (size_t j = i + 1; j < geoms.size(); ++j) {
            iCollisionGeometry *a = geoms[i], *b = geoms[j];
            iRigidBody *ba = a->getRigidBody(), *bb = b->getRigidBody();
            if (ba && ba == bb) continue;
            if (fixedBody(ba) && fixedBody(bb)) continue;
            gcol::WorldShape sa, sb;
            if (!referenceShape(a, sa) || !referenceShape(b, sb)) continue;
            gcol::ContactManifold m;
            if (gcol::collideShapes(sa, sb, m) > 0) expected.insert(std::minmax(a, b));
        }
    std::map<std::pair<iCollisionGeometry*, iCollisionGeometry*>, int> seen;
    std::map<std::pair<iCollisionGeometry*, iCollisionGeometry*>, std::pair<iCollisionGeometry*, size_t>>
        firstAt;
    const CollisionContact* c = space->getContactList();
    for (size_t k = 0; k < space->getNumContacts(); ++k) {
        auto key = std::minmax(c[k].g1, c[k].g2);
        ASSERT_NE(c[k].g1, c[k].g2);
        const unsigned* ids = featuresOf(space)->getContactFeatureIds();
        if (moveBy > 0.0f && !expected.count(key)) {
            ASSERT_TRUE(ids && (ids[k] & 0x80000000u)) << "false contact (not from sampling)";
        } else {
            ASSERT_TRUE(expected.count(key)) << "false contact";
        }
        auto it = firstAt.find(key);
        if (it == firstAt.end()) {
            firstAt[key] = {c[k].g1, k};
        } else {
            // One run of contacts per pair (a manifold), always in the same order: not found twice.
            ASSERT_EQ(it->second.first, c[k].g1) << "pair reported twice (both orders)";
            ASSERT_EQ(it->second.second + size_t(seen[key]), k) << "pair reported twice";
        }
        ++seen[key];
        ASSERT_LE(seen[key], gcol::kMaxManifoldPoints);
        ASSERT_TRUE(c[k].normal.isFinite() && c[k].pos.isFinite());
        ASSERT_NEAR(c[k].normal.length(), 1.0f, 1e-3f);
        ASSERT_GE(c[k].depth, 0.0f);
    }
    for (const auto& e : expected) {
        EXPECT_TRUE(seen.count(e)) << "missed pair";
    }
    if (moveBy == 0.0f) {
        EXPECT_EQ(seen.size(), expected.size());
    }
    for (iCollisionGeometry* g : geoms) g->Delete();
    space->Delete();
}

// One geometry per space of the same shape on the same body; slot i of each twin list names the same one.
struct Twins {
    std::vector<iCollisionGeometry*> tested, reference;
};

// Contacts by the twin slots of their geometry pair (as reported: g1's slot first), each pair's contacts in
// the order listed, with their feature ids.
using ContactsByPair = std::map<std::pair<int, int>, std::vector<std::vector<float>>>;
inline ContactsByPair contactsByPair(iCollisionSpace* space, const std::vector<iCollisionGeometry*>& slots) {
    std::map<iCollisionGeometry*, int> slotOf;
    for (size_t i = 0; i < slots.size(); ++i)
        if (slots[i]) slotOf[slots[i]] = int(i);
    ContactsByPair out;
    const CollisionContact* c = space->getContactList();
    const unsigned* ids = featuresOf(space)->getContactFeatureIds();
    for (size_t k = 0; k < space->getNumContacts(); ++k)
        out[{slotOf.at(c[k].g1), slotOf.at(c[k].g2)}].push_back(
            {c[k].pos.x, c[k].pos.y, c[k].pos.z, c[k].normal.x, c[k].normal.y, c[k].normal.z, c[k].depth,
             float(ids[k] & 0xFFFFu), float(ids[k] >> 16)});
    return out;
}

inline std::vector<int> slotsOf(const std::vector<iCollisionGeometry*>& found,
                                const std::vector<iCollisionGeometry*>& slots) {
    std::vector<int> out;
    for (iCollisionGeometry* g : found)
        out.push_back(int(std::find(slots.begin(), slots.end(), g) - slots.begin()));
    return out;
}

inline void checkAgainstReference(const std::function<iCollisionSpace*()>& makeSpace,
                                  const std::function<iCollisionSpace*()>& makeReference, Scene scene,
                                  unsigned seed, int count, int calls, bool filters = false,
                                  bool rebinds = false) {
    std::mt19937 gen(seed);
    auto uni = [&](float a, float b) { return std::uniform_real_distribution<float>(a, b)(gen); };
    auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(gen); };
    iCollisionSpace* tested = makeSpace();
    iCollisionSpace* reference = makeReference();
    DefaultSpace joins(reference);
    std::vector<std::unique_ptr<UserBody>> bodies;
    Twins twins;
    const float extent = scene == Scene::Sparse ? 60.0f : scene == Scene::Dense ? 6.0f : 20.0f;
    auto addGeometry = [&]() {
        UserBody* body = nullptr;
        if (!bodies.empty() && pick(10) == 0) {
            body = bodies[size_t(pick(int(bodies.size())))].get();
        } else if (pick(40) != 0) {
            bool fixed = scene == Scene::MostlyFixed ? pick(10) < 7 : pick(10) == 0;
            bodies.emplace_back(
                new UserBody(Vector(uni(-extent, extent), uni(-extent, extent), uni(-extent, extent)),
                             fixed ? PHYS_FixedInSpace : PHYS_Falling));
            body = bodies.back().get();
        }
        float size = scene == Scene::Mixed && pick(4) == 0 ? uni(2.0f, 6.0f) : uni(0.2f, 1.5f);
        int kind = pick(20);
        Vector n(uni(-0.3f, 0.3f), 1, uni(-0.3f, 0.3f)),
            h(size, uni(0.2f, 1.0f) * size, uni(0.2f, 1.0f) * size);
        float offset = uni(-extent, 0);
        bool planeBody = pick(2) != 0;
        const std::uint32_t layer = filters ? 1u << pick(4) : 1u, mask = filters ? unsigned(pick(16)) : ~0u;
        const bool sensor = filters && pick(6) == 0;
        for (int twin = 0; twin < 2; ++twin) {
            iCollisionGeometry* g;
            if (kind == 0)
                g = CreateCPlane(planeBody ? body : nullptr, n, offset);
            else if (kind < 10)
                g = CreateCSphere(body, size);
            else
                g = CreateCOBB(body, h);
            filterOf(g)->setLayer(layer);
            filterOf(g)->setMask(mask);
            filterOf(g)->setSensor(sensor);
            (twin ? reference : tested)->add(g);
            (twin ? twins.reference : twins.tested).push_back(g);
        }
    };
    for (int i = 0; i < count; ++i) addGeometry();
    // Queries: the same geometry found, in the same order (before a call: bodies moved since the last one).
    auto compareQueries = [&](int call) {
        iCollisionQueries *qt = queriesOf(tested), *qr = queriesOf(reference);
        // Every other call the tested space answers in a batch (iCollisionQueries.h; nothing moves inside
        // it): the same answers, and its end finds nothing moved.
        const unsigned long errorsBefore = errorCount();
        std::unique_ptr<QueryBatch> batch(call % 2 ? new QueryBatch(qt) : nullptr);
        for (int k = 0; k < 4; ++k) {
            Vector origin(uni(-extent, extent), uni(-extent, extent), uni(-extent, extent));
            Vector dir(uni(-1, 1), uni(-1, 1), uni(-1, 1));
            RayHit ht, hr;
            bool hitT = qt->rayCast(origin, dir, 2.0f * extent, ht),
                 hitR = qr->rayCast(origin, dir, 2.0f * extent, hr);
            ASSERT_EQ(hitT, hitR) << "ray, call " << call;
            if (hitT) {
                EXPECT_EQ(slotsOf({ht.geometry}, twins.tested), slotsOf({hr.geometry}, twins.reference));
                EXPECT_EQ(ht.distance, hr.distance);
            }
            std::vector<iCollisionGeometry*> ot, orf;
            float r = uni(0.5f, 0.3f * extent);
            qt->overlapSphere(origin, r, ot);
            qr->overlapSphere(origin, r, orf);
            EXPECT_EQ(slotsOf(ot, twins.tested), slotsOf(orf, twins.reference)) << "sphere, call " << call;
            qt->overlapBox(origin, Matrix(1), Vector(r, 0.5f * r, r), ot);
            qr->overlapBox(origin, Matrix(1), Vector(r, 0.5f * r, r), orf);
            EXPECT_EQ(slotsOf(ot, twins.tested), slotsOf(orf, twins.reference)) << "box, call " << call;
        }
        batch.reset();
        EXPECT_EQ(errorCount(), errorsBefore) << "call " << call;
    };
    for (int call = 0; call < calls; ++call) {
        // What happens between two calls.
        const int what = call == 0 ? -1 : pick(rebinds ? 12 : 8);
        for (auto& b : bodies) {
            RBDynamics& d = b->getDynamics();
            // 0: every movable body a little (within the margins); 1: some far, fast and turning.
            if (what == 0 && d.physicsType != PHYS_FixedInSpace)
                d.position += Vector(uni(-0.02f, 0.02f), uni(-0.02f, 0.02f), uni(-0.02f, 0.02f));
            if (what == 1 && pick(4) == 0 && d.physicsType != PHYS_FixedInSpace) {
                d.position += Vector(uni(-2, 2), uni(-2, 2), uni(-2, 2));
                Eigen::Quaternionf q(uni(-1, 1), uni(-1, 1), uni(-1, 1), uni(-1, 1));
                d.orientation = gmath::fromBlock3(q.normalized().toRotationMatrix());
            }
            if (what == 2 && pick(20) == 0) { // teleported: not swept
                d.position = Vector(uni(-extent, extent), uni(-extent, extent), uni(-extent, extent));
                d.markTeleported();
            }
            if (what == 3 && pick(5) == 0) d.sleeping = !d.sleeping;
            if (what == 4 && pick(10) == 0)
                d.physicsType = d.physicsType == PHYS_FixedInSpace ? PHYS_Falling : PHYS_FixedInSpace;
        }
        if (what == 5) // some geometry leaves both spaces (and is deleted)
            for (size_t i = 0; i < twins.tested.size(); ++i)
                if (twins.tested[i] && pick(15) == 0) {
                    twins.tested[i]->Delete();
                    twins.reference[i]->Delete();
                    twins.tested[i] = twins.reference[i] = nullptr;
                }
        if (what == 6)
            for (int k = 0; k < 1 + pick(count / 10 + 1); ++k) addGeometry();
        // what == 7: nothing changes (the persistent pairs stand as they are); or, with filters, some
        // filters.
        if (what == 7 && filters)
            for (size_t i = 0; i < twins.tested.size(); ++i)
                if (twins.tested[i] && pick(10) == 0) {
                    const std::uint32_t mask = unsigned(pick(16));
                    const bool sensor = pick(6) == 0;
                    for (iCollisionGeometry* g : {twins.tested[i], twins.reference[i]}) {
                        filterOf(g)->setMask(mask);
                        filterOf(g)->setSensor(sensor);
                    }
                }
        if (what == 8) // some twins bound to another body, or to none
            for (size_t i = 0; i < twins.tested.size(); ++i)
                if (twins.tested[i] && twins.tested[i]->getCollisionType() != CT_PLANE && pick(10) == 0) {
                    UserBody* to = bodies.empty() || pick(5) == 0
                                       ? nullptr
                                       : bodies[size_t(pick(int(bodies.size())))].get();
                    twins.tested[i]->attach(to);
                    twins.reference[i]->attach(to);
                }
        if (what == 9) // some twins resized
            for (size_t i = 0; i < twins.tested.size(); ++i)
                if (twins.tested[i] && pick(8) == 0) {
                    const float scale = uni(0.5f, 1.5f);
                    if (twins.tested[i]->getCollisionType() == CT_SPHERE) {
                        const float r = static_cast<iCSphere*>(twins.tested[i])->getRadius() * scale;
                        static_cast<iCSphere*>(twins.tested[i])->setRadius(r);
                        static_cast<iCSphere*>(twins.reference[i])->setRadius(r);
                    } else if (twins.tested[i]->getCollisionType() == CT_OBB) {
                        const Vector h = static_cast<iCOBB*>(twins.tested[i])->getRadius() * scale;
                        static_cast<iCOBB*>(twins.tested[i])->setRadius(h);
                        static_cast<iCOBB*>(twins.reference[i])->setRadius(h);
                    }
                }
        if (what == 10 && bodies.size() > 1) { // a body deleted under its geometry (which stays, unbound)
            const size_t k = size_t(pick(int(bodies.size())));
            bodies.erase(bodies.begin() + std::ptrdiff_t(k));
        }
        if (what == 11) // teleported where they are (the previous pose is not swept from)
            for (auto& b : bodies)
                if (pick(4) == 0) b->getDynamics().markTeleported();
        // The candidate stage alone now and then (a call that keeps no previous pose), then the whole call.
        if (rebinds && pick(3) == 0)
            for (iCollisionSpace* s : {tested, reference})
                if (auto* simple = dynamic_cast<SimpleCollisionSpace*>(s)) simple->findCandidatePairs();
        compareQueries(call);
        tested->populateContactList(1.0f / 60.0f);
        reference->populateContactList(1.0f / 60.0f);
        ASSERT_EQ(tested->getNumContacts(), reference->getNumContacts())
            << "call " << call << " after " << what;
        ASSERT_EQ(contactsByPair(tested, twins.tested), contactsByPair(reference, twins.reference))
            << "call " << call << " after " << what;
        compareQueries(call);
    }
    for (auto* list : {&twins.tested, &twins.reference})
        for (iCollisionGeometry* g : *list)
            if (g) g->Delete();
    tested->Delete();
    reference->Delete();
}

} // namespace spacediff
