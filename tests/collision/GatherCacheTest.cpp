// GatherCacheTest.cpp - a space keeps each geometry's world shapes and box between calls and the broadphase
// keeps its pairs (SimpleCollisionSpace.h, step 1); nothing it keeps may outlive what it was made from.
// Over many calls a scene changes in every way a cache could miss: bodies moved, turned, teleported, put to
// sleep, fixed, attached to others and detached, given a centre of mass or a non-finite position; shapes
// resized, compounds given children, geometries rebound, filtered, removed, added, deleted; snapshots put
// back; queries made between calls. After each change the space must answer as a space built afresh on the
// same bodies answers (it has nothing kept): the same candidate pairs (findCandidatePairs) and the same
// contacts, bit for bit (populateContactList with delta 0, so the pose is all that counts), and both as many
// candidate pairs as the brute-force loop over the geometries' world boxes finds.
#include "DefaultSpace.h"
#include "MathEigen.h"
#include "SimpleCollisionSpace.h"
#include "UserBody.h"
#include "iCCompound.h"
#include "iCOBB.h"
#include "iCPlane.h"
#include "iCSphere.h"
#include "iCollisionFilter.h"
#include "iCollisionQueries.h"
#include "iContactFeatures.h"
#include "iOctreeCollisionSpace.h"
#include "iSimpleCollisionSpace.h"
#include "iSnapshots.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <random>
#include <vector>

namespace {

bool sameBits(const Vector& a, const Vector& b) { return std::memcmp(&a, &b, sizeof(Vector)) == 0; }

// A space built afresh with a clone of each geometry of `space` (same shapes, body and filter, in the same
// order), for one call: what `space` must answer.
struct Fresh {
    iCollisionSpace* space;
    std::vector<iCollisionGeometry*> twins, originals;
    Fresh(iCollisionSpace* (*make)(), iCollisionSpace* of) : space(make()) {
        DefaultSpace joins(space);
        for (iCollisionGeometry* g : of->getAttachedGeometry()) {
            twins.push_back(g->clone());
            originals.push_back(g);
        }
    }
    ~Fresh() {
        for (iCollisionGeometry* g : twins) g->Delete();
        space->Delete();
    }
    iCollisionGeometry* original(const iCollisionGeometry* twin) const {
        for (size_t i = 0; i < twins.size(); ++i)
            if (twins[i] == twin) return originals[i];
        return nullptr;
    }
};

// Pairs of geometries whose world boxes (from the public interface: each shape's projection on the world
// axes) overlap, gathered as the space gathers them (a body, a finite pose, at least one shape; a plane
// meets every bounded one).
size_t bruteForceBoxPairs(iCollisionSpace* space) {
    struct Box {
        bool plane;
        float lo[3], hi[3];
    };
    std::vector<Box> boxes;
    for (iCollisionGeometry* g : space->getAttachedGeometry()) {
        const iRigidBody* b = g->getRigidBody();
        const bool plane = g->getCollisionType() == CT_PLANE;
        if (!b && !plane) continue;
        if (b && (!b->getDynamics().getWorldOrigin().isFinite() ||
                  !b->getDynamics().getWorldOrientation().isFinite()))
            continue;
        if (g->getCollisionType() == CT_COMPOUND && static_cast<iCCompound*>(g)->getNumChildren() == 0)
            continue;
        Box box{plane, {}, {}};
        if (!plane)
            for (int k = 0; k < 3; ++k)
                g->getProjectionBounds(Vector(k == 0, k == 1, k == 2), box.lo[k], box.hi[k]);
        boxes.push_back(box);
    }
    size_t n = 0;
    for (size_t i = 0; i < boxes.size(); ++i)
        for (size_t j = i + 1; j < boxes.size(); ++j) {
            const Box &a = boxes[i], &b = boxes[j];
            if (a.plane && b.plane) continue;
            bool overlap = true;
            for (int k = 0; k < 3 && !a.plane && !b.plane; ++k)
                overlap = overlap && a.lo[k] <= b.hi[k] && b.lo[k] <= a.hi[k];
            n += overlap ? 1 : 0;
        }
    return n;
}

void expectSameAsFresh(iCollisionSpace* (*make)(), iCollisionSpace* space, int round) {
    auto* candidates = dynamic_cast<SimpleCollisionSpace*>(space);
    Fresh fresh(make, space);
    auto* freshCandidates = dynamic_cast<SimpleCollisionSpace*>(fresh.space);
    const size_t expected = freshCandidates->findCandidatePairs();
    ASSERT_EQ(candidates->findCandidatePairs(), expected) << "round " << round;
    EXPECT_EQ(expected, bruteForceBoxPairs(space)) << "round " << round;
    fresh.space->populateContactList(0.0f);
    space->populateContactList(0.0f);
    ASSERT_EQ(space->getNumContacts(), fresh.space->getNumContacts()) << "round " << round;
    const CollisionContact* mine = space->getContactList();
    const CollisionContact* theirs = fresh.space->getContactList();
    const unsigned* myFeatures = featuresOf(space)->getContactFeatureIds();
    const unsigned* theirFeatures = featuresOf(fresh.space)->getContactFeatureIds();
    for (size_t i = 0; i < space->getNumContacts(); ++i) {
        EXPECT_EQ(mine[i].g1, fresh.original(theirs[i].g1)) << "round " << round << " contact " << i;
        EXPECT_EQ(mine[i].g2, fresh.original(theirs[i].g2)) << "round " << round << " contact " << i;
        EXPECT_TRUE(sameBits(mine[i].pos, theirs[i].pos) && sameBits(mine[i].normal, theirs[i].normal) &&
                    std::memcmp(&mine[i].depth, &theirs[i].depth, sizeof(float)) == 0 &&
                    myFeatures[i] == theirFeatures[i])
            << "round " << round << " contact " << i;
    }
}

Matrix randomRotation(std::mt19937& rng) {
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    Eigen::Quaternionf q(u(rng), u(rng), u(rng), u(rng));
    return gmath::fromBlock3(q.normalized().toRotationMatrix());
}

void cacheFollowsEveryChange(iCollisionSpace* (*make)()) {
    std::mt19937 rng(7);
    auto pick = [&](int n) { return int(std::uniform_int_distribution<int>(0, n - 1)(rng)); };
    auto uni = [&](float a, float b) { return std::uniform_real_distribution<float>(a, b)(rng); };
    iCollisionSpace* space = make();
    DefaultSpace joins(space);
    const int kBodies = 60;
    std::vector<std::unique_ptr<UserBody>> bodies;
    // Per body: moved since the last populate call (a body that rests must not have, or a space that
    // remembers the previous pose rightly tests pairs a fresh one skips), and what it had before a NaN.
    std::vector<bool> moved(kBodies, false);
    std::vector<Vector> saved(kBodies);
    std::vector<bool> poisoned(kBodies, false);
    auto resting = [&](int i) {
        const RBDynamics& d = *bodies[size_t(i)]->getDynamics().attachmentRoot();
        return d.physicsType == PHYS_FixedInSpace || d.sleeping;
    };
    auto tree = [&](int i) { // attached to another, or with others attached
        const RBDynamics& d = bodies[size_t(i)]->getDynamics();
        return d.attachedTo() != nullptr || d.firstAttached() != nullptr;
    };
    for (int i = 0; i < kBodies; ++i) {
        bodies.emplace_back(new UserBody(Vector(uni(-4, 4), uni(-4, 4), uni(-4, 4))));
        bodies.back()->getDynamics().orientation = randomRotation(rng);
    }
    std::vector<iCollisionGeometry*> geoms, removed;
    auto create = [&](iRigidBody* b) -> iCollisionGeometry* {
        switch (pick(3)) {
        case 0:
            return CreateCSphere(b, uni(0.3f, 1.0f));
        case 1:
            return CreateCOBB(b, Vector(uni(0.2f, 0.9f), uni(0.2f, 0.9f), uni(0.2f, 0.9f)));
        default: {
            auto* c = static_cast<iCCompound*>(CreateCCompound(b));
            c->addSphere(Vector(uni(-0.5f, 0.5f), 0, 0), uni(0.2f, 0.6f));
            return c;
        }
        }
    };
    for (int i = 0; i < kBodies; ++i) geoms.push_back(create(bodies[size_t(i)].get()));
    geoms.push_back(CreateCPlane(nullptr, Vector(0, 1, 0), -6.0f));            // the ground
    geoms.push_back(CreateCPlane(bodies[0].get(), Vector(1, 0, 0.2f), -5.0f)); // a wall on a body
    iSnapshots* snapshots = snapshotsOf(space);
    iSnapshot* snapshot = nullptr;
    for (int round = 0; round < 80; ++round) {
        for (int change = 0; change < 6; ++change) {
            const int i = pick(kBodies);
            RBDynamics& d = bodies[size_t(i)]->getDynamics();
            iCollisionGeometry* g = geoms[size_t(pick(int(geoms.size())))];
            const bool free = !resting(i) && !poisoned[size_t(i)];
            switch (pick(16)) {
            case 0: // a small move, most often inside a fat box
                if (free) d.position += Vector(uni(-0.02f, 0.02f), uni(-0.02f, 0.02f), uni(-0.02f, 0.02f));
                moved[size_t(i)] = moved[size_t(i)] || free;
                break;
            case 1: // a jump
                if (free) d.position = Vector(uni(-4, 4), uni(-4, 4), uni(-4, 4));
                moved[size_t(i)] = moved[size_t(i)] || free;
                break;
            case 2: // a turn
                if (free) d.orientation = randomRotation(rng);
                moved[size_t(i)] = moved[size_t(i)] || free;
                break;
            case 3: // a teleport
                if (free) {
                    d.position += Vector(uni(-1, 1), 0, 0);
                    d.markTeleported();
                }
                moved[size_t(i)] = moved[size_t(i)] || free;
                break;
            case 4: // asleep or awake, fixed or not: only a body that stayed where the last call saw it
                if (!moved[size_t(i)] && !poisoned[size_t(i)] && !tree(i)) d.sleeping = !d.sleeping;
                break;
            case 5:
                if (!moved[size_t(i)] && !poisoned[size_t(i)] && !tree(i))
                    d.physicsType = d.physicsType == PHYS_FixedInSpace ? PHYS_Falling : PHYS_FixedInSpace;
                break;
            case 6: // a new size
                if (g->getCollisionType() == CT_SPHERE) static_cast<iCSphere*>(g)->setRadius(uni(0.2f, 1.2f));
                if (g->getCollisionType() == CT_OBB)
                    static_cast<iCOBB*>(g)->setRadius(
                        Vector(uni(0.2f, 1.0f), uni(0.2f, 1.0f), uni(0.2f, 1.0f)));
                if (g->getCollisionType() == CT_COMPOUND)
                    static_cast<iCCompound*>(g)->addBox(Vector(0, uni(-0.8f, 0.8f), 0), randomRotation(rng),
                                                        Vector(0.3f, 0.2f, 0.4f));
                break;
            case 7: // rebound to another body, or to none
                if (g->getCollisionType() != CT_PLANE)
                    g->attach(pick(8) == 0 ? nullptr : bodies[size_t(pick(kBodies))].get());
                break;
            case 8: // a position that is not finite, and back
                if (poisoned[size_t(i)]) {
                    d.position = saved[size_t(i)];
                    poisoned[size_t(i)] = false;
                } else if (free && !tree(i)) {
                    saved[size_t(i)] = d.position;
                    d.position.x = std::numeric_limits<float>::quiet_NaN();
                    poisoned[size_t(i)] = true;
                }
                break;
            case 9: // attached to another (moving with it), or detached
                if (free) {
                    const int j = pick(kBodies);
                    if (d.attachedTo())
                        d.attachTo(nullptr);
                    else if (j != i && !resting(j) && !poisoned[size_t(j)] &&
                             !bodies[size_t(j)]->getDynamics().attachedTo())
                        d.attachTo(&bodies[size_t(j)]->getDynamics());
                    moved[size_t(i)] = true;
                }
                break;
            case 10: // a parent moves: its children go with it
                if (free && d.firstAttached()) d.position += Vector(0, uni(-0.5f, 0.5f), 0);
                moved[size_t(i)] = moved[size_t(i)] || free;
                break;
            case 11: // a centre of mass off the frame's origin
                if (free) d.com = Vector(uni(-0.2f, 0.2f), 0, uni(-0.2f, 0.2f));
                moved[size_t(i)] = moved[size_t(i)] || free;
                break;
            case 12: // removed, or back
                if (!removed.empty() && pick(2) == 0) {
                    space->add(removed.back());
                    removed.pop_back();
                } else if (g->getSpace() == space) {
                    space->remove(g);
                    removed.push_back(g);
                }
                break;
            case 13: { // deleted, and a new one
                if (g->getCollisionType() == CT_PLANE) break;
                removed.erase(std::remove(removed.begin(), removed.end(), g), removed.end());
                g->Delete();
                *std::find(geoms.begin(), geoms.end(), g) = create(bodies[size_t(i)].get());
                break;
            }
            case 14: // filtered out of layer 1, or in again
                if (auto* f = dynamic_cast<iCollisionFilter*>(g)) f->setMask(f->getMask() ^ 1u);
                break;
            default: // a query between calls (the tree refits proxies for it)
                if (pick(2) == 0) {
                    RayHit hit;
                    queriesOf(space)->rayCast(Vector(uni(-4, 4), -5, uni(-4, 4)), Vector(0, 1, 0), 10.0f,
                                              hit);
                } else {
                    std::vector<iCollisionGeometry*> found;
                    queriesOf(space)->overlapSphere(Vector(uni(-4, 4), uni(-4, 4), uni(-4, 4)), 1.5f, found);
                }
            }
        }
        // Now and then the candidate pairs alone, or a snapshot taken or put back.
        if (pick(3) == 0) dynamic_cast<SimpleCollisionSpace*>(space)->findCandidatePairs();
        if (round % 10 == 3) {
            if (snapshot) snapshot->Delete();
            snapshot = snapshots->takeSnapshot();
        }
        // Put back (refused if members changed), the previous poses are the snapshot's: one call makes them
        // this pose again, as a fresh space has them.
        if (round % 10 == 7 && snapshot && snapshots->restoreSnapshot(snapshot))
            space->populateContactList(0.0f);
        expectSameAsFresh(make, space, round);
        if (::testing::Test::HasFatalFailure()) break;
        std::fill(moved.begin(), moved.end(), false);
    }
    if (snapshot) snapshot->Delete();
    for (iCollisionGeometry* g : geoms) g->Delete();
    space->Delete();
}

} // namespace

TEST(GatherCache, SimpleSpaceAnswersAsAFreshOneAfterEveryChange) {
    cacheFollowsEveryChange([] { return CreateSimpleCollisionSpace(60); });
}
TEST(GatherCache, OctreeSpaceAnswersAsAFreshOneAfterEveryChange) {
    cacheFollowsEveryChange([] { return CreateOctreeCollisionSpace(60); });
}
