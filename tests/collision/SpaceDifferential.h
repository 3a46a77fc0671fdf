// SpaceDifferential.h - the differential test every collision space must pass: random scenes (sparse,
// dense, mixed sizes, fixed bodies, shared bodies, planes, bodiless geometry) where the space's contact
// list must name exactly the geometry pairs a brute-force loop over the pure pair functions finds: every
// overlapping pair, none twice, none false. Reusable: pass any space factory.
#pragma once

#include "DefaultSpace.h"
#include "MathEigen.h"
#include "Narrowphase.h"
#include "UserBody.h"
#include "iCOBB.h"
#include "iCPlane.h"
#include "iCSphere.h"
#include "iCollisionSpace.h"
#include "iContactFeatures.h"

#include <gtest/gtest.h>

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

} // namespace spacediff
