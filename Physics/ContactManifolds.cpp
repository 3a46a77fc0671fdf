// ContactManifolds.cpp - this step's manifolds: the detector's contacts grouped per geometry pair (up to 4
// points each), last step's points that came apart by a hair kept, and each point matched with last step's
// point at the same place so that it starts from that point's impulses (warm starting).
#include "ContactSolver.h"
#include "GrowingStorage.h"
#include "Prefetch.h"
#include "SolverRows.h"

#include "MathEigen.h"
#include "RBDynamics.h"
#include "iCollisionGeometry.h"
#include "iCollisionSpace.h"
#include "iRigidBody.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace physics {

namespace {
// Anchors are measured in a root's frame at the step's start, where the detector found the contacts; the
// static world's are world points.
Vec3 localAnchor(const SolverBody& b, const Vec3& world) {
    return b.root ? Vec3(b.startRotation.conjugate() * (world - b.startOrigin)) : world;
}
// The geometries of contacts[i] and their bodies' dynamics, asked for in three stages a few contacts apart
// (each stage reads only what the stage before brought in): at 10,000 bodies they lie in memory apart from
// each other and from the contact list, and waiting for them was 60 % of collecting the manifolds (perf).
void fetchAhead(const CollisionContact* contacts, size_t count, size_t i) {
    constexpr size_t kGeometry = 24, kBody = 16, kDynamics = 8; // contacts ahead; a pair lists about 4
    if (i + kGeometry < count) { // (either may be null: prefetchLines then does nothing)
        prefetchLines(contacts[i + kGeometry].g1, 256);
        prefetchLines(contacts[i + kGeometry].g2, 256);
    }
    // The bodies only where a new pair starts (a pair's contacts follow one another).
    auto startsPair = [&](size_t j) { return j < count && contacts[j].g2 != contacts[j - 1].g2; };
    auto body = [](iCollisionGeometry* g) { return g ? g->getRigidBody() : nullptr; };
    if (startsPair(i + kBody))
        for (iCollisionGeometry* g : {contacts[i + kBody].g1, contacts[i + kBody].g2})
            if (iRigidBody* rb = body(g)) prefetchLines(rb, 128); // (the start pose on the second line)
    if (startsPair(i + kDynamics))
        for (iCollisionGeometry* g : {contacts[i + kDynamics].g1, contacts[i + kDynamics].g2})
            if (iRigidBody* rb = body(g)) prefetchLines(&rb->getDynamics(), 256);
}
} // namespace

int ContactSolver::bodyIndex(RBDynamics* root, const SolverBodyAccess& access) {
    if (const int* known = m_bodyIndex.find(root)) return *known;
    int index = int(m_bodies.size());
    m_bodies.push_back(access.enter(root, index));
    m_bodyIndex.emplace(root, index);
    return index;
}

void ContactSolver::buildManifolds(const CollisionContact* contacts, size_t count,
                                   const SolverBodyAccess& access) {
    m_manifolds.clear();
    // Room to spare (this list and last step's swap every step): a warm scene whose pair count wanders a
    // little above any it had does not allocate each time it does.
    const size_t room = m_last.size() + m_last.size() / 2 + 16;
    reserveGrowing(m_manifolds, room);
    if (m_dormant.capacity() < m_last.size())
        reserveGrowing(m_dormant, room); // last step's that rest, at most all
    FlatMap<PairKey, size_t, PairKeyHash>& current = m_current;
    current.clear();
    assignGrowing(m_lastNow, m_last.size(), -1);
    m_lastCursor = 0;
    m_maxDepthBefore = 0;
    constexpr size_t kNone = ~size_t(0);
    // A space lists a pair's contacts one after another: what holds for the pair is worked out at its first.
    // What holds for each of its geometries (body, root, material, size, solver slot) is kept while the next
    // pair shares it (a space lists a geometry's pairs together, mostly): each is read from the geometry and
    // its body, lying elsewhere in memory, once for them all.
    struct Side {
        iCollisionGeometry* g = nullptr;
        iRigidBody* rb = nullptr;
        RBDynamics* root = nullptr;
        bool fixed = true;
        int index = -1; // its root's solver slot, once a manifold entered it
        Real friction = 0, restitution = 0, radius = 0;
    };
    Side sideA, sideB;
    auto sideOf = [&](iCollisionGeometry* g, Side& side) {
        if (side.g == g) return;
        side.g = g;
        side.rb = g->getRigidBody();
        side.root = side.rb ? side.rb->getDynamics().attachmentRoot() : nullptr;
        side.fixed = !side.root || immovable(*side.root);
        side.index = -1;
        // A bodiless geometry has the default material of a body.
        static const RBDynamics defaults;
        const RBDynamics& material = side.rb ? side.rb->getDynamics() : defaults;
        side.friction = material.friction;
        side.restitution = material.restitution;
        side.radius = g->getBoundingRadius();
    };
    auto indexOf = [&](Side& side) {
        if (side.index < 0) side.index = bodyIndex(side.root, access);
        return side.index;
    };
    struct {
        const iCollisionGeometry *g1 = nullptr, *g2 = nullptr;
        bool skip = true;
        int previous = -1;       // last step's manifold of the pair (m_last)
        size_t manifold = kNone; // its place in m_manifolds, once it has one
    } pair;
    for (size_t i = 0; contacts && i < count; ++i) {
        fetchAhead(contacts, count, i);
        const CollisionContact& c = contacts[i];
        if (!c.g1 || !c.g2) continue;
        if (c.g1 != pair.g1 || c.g2 != pair.g2) {
            pair.g1 = c.g1;
            pair.g2 = c.g2;
            sideOf(c.g1, sideA);
            sideOf(c.g2, sideB);
            pair.skip = sideA.root == sideB.root || (sideA.fixed && sideB.fixed) ||
                        joinedWithoutContact(sideA.root, sideB.root);
            if (pair.skip) continue;
            // Its manifold, if its contacts came earlier in the list too: a pair that had one last step is
            // known by that one (no table), a new pair by the table of new pairs.
            pair.previous = previousManifold(c.g1, c.g2);
            pair.manifold = kNone;
            if (pair.previous >= 0) {
                const int now = m_lastNow[size_t(pair.previous)];
                if (now >= 0) pair.manifold = size_t(now);
            } else if (const size_t* known = current.find(PairKey{c.g1, c.g2})) {
                pair.manifold = *known;
            }
        }
        if (pair.skip) continue;
        Vec3 n = toEigen(c.normal);
        if (!n.allFinite() || n.squaredNorm() < 0.5f || !std::isfinite(c.depth)) continue;
        n.normalize();

        if (pair.manifold == kNone) {
            pair.manifold = m_manifolds.size();
            if (pair.previous >= 0)
                m_lastNow[size_t(pair.previous)] = int(pair.manifold);
            else
                current.emplace(PairKey{c.g1, c.g2}, pair.manifold);
            Manifold& m = m_manifolds.emplace_back();
            m.g1 = c.g1;
            m.g2 = c.g2;
            m.rootA = sideA.root;
            m.rootB = sideB.root;
            m.a = indexOf(sideA);
            m.b = indexOf(sideB);
            m.friction = combine(m_settings.friction, sideA.friction, sideB.friction);
            m.restitution = combine(m_settings.restitution, sideA.restitution, sideB.restitution);
            m.size = std::fmin(sideA.radius, sideB.radius);
            m.previous = pair.previous;
        }
        Manifold& m = m_manifolds[pair.manifold];
        ManifoldPoint p;
        p.normal = n;
        p.depth = std::max(0.0f, c.depth);
        // The two touching surface points: a's reaches depth/2 past the contact point along n, b's as far
        // back.
        Vec3 pos = toEigen(c.pos);
        Vec3 onA = pos + 0.5f * p.depth * n, onB = pos - 0.5f * p.depth * n;
        p.anchorA = localAnchor(m_bodies[m.a], onA);
        p.anchorB = localAnchor(m_bodies[m.b], onB);
        p.point = pos;
        m_maxDepthBefore = std::max(m_maxDepthBefore, p.depth);
        if (m.count < 4) {
            m.points[m.count++] = p;
        } else { // keep the four deepest
            ManifoldPoint* shallowest =
                std::min_element(m.points, m.points + 4, [](auto& x, auto& y) { return x.depth < y.depth; });
            if (shallowest->depth < p.depth) *shallowest = p;
        }
    }
    carryOver(access);
}

int ContactSolver::previousManifold(const iCollisionGeometry* g1, const iCollisionGeometry* g2) {
    // A space lists its pairs in much the same order step after step: last step's manifold of this pair is
    // most often the one after the last one found, known without the table.
    size_t i = m_lastCursor;
    if (i >= m_last.size() || m_last[i].g1 != g1 || m_last[i].g2 != g2) {
        const size_t* known = m_lastIndex.find(PairKey{g1, g2});
        if (!known) return -1;
        i = *known;
    }
    m_lastCursor = i + 1;
    return int(i);
}

// What carries over from a pair's manifold of last step, read once for both (at 10,000 bodies it comes from
// memory; asked for two manifolds ahead):
//  - A collision detector reports only touching points, so a resting box that rocks by a hair loses the
//    corners that lifted, stands on the others for a step, and rocks back: the contacts flicker and the warm
//    start is lost with them. Like a persistent manifold (Bullet's contact breaking threshold), a pair still
//    touching keeps last step's points that came apart by less than keepDistance, each with its impulses.
//    Such a point is speculative: it holds only once its gap closes (see solveContacts), so it never pulls
//    and never stops a body short of touching.
//  - Each point starts from the impulses of last step's point at the same place (matchImpulses).
void ContactSolver::carryOver(const SolverBodyAccess& access) {
    const bool keeping = m_settings.keepDistance > 0.0f, warm = m_settings.warmStart;
    const Real keep = m_settings.keepDistance, match2 = m_settings.matchDistance * m_settings.matchDistance;
    // Appends to m the points of old that m lacks and that are apart by less than keep.
    auto keepFrom = [&](const Manifold& old, Manifold& m) {
        const SolverBody &a = m_bodies[m.a], &b = m_bodies[m.b];
        const Vec3 n = m.count ? m.points[0].normal : old.points[0].normal;
        const int reportedCount = m.count;
        for (int j = 0; j < old.count && m.count < 4; ++j) {
            const ManifoldPoint& o = old.points[j];
            if (o.bounced) continue; // it left the surface
            bool known = false;
            for (int i = 0; i < reportedCount && !known; ++i)
                known = (m.points[i].anchorA - o.anchorA).squaredNorm() <= match2;
            if (known) continue;
            Vec3 onA = startPoint(a, o.anchorA), onB = startPoint(b, o.anchorB), gap = onB - onA;
            Real separation = n.dot(gap);
            if (separation <= 0.0f || separation > keep || (gap - separation * n).norm() > keep)
                continue; // touching again is the detector's to report; too far apart or slid off: broken
            ManifoldPoint p = o;
            p.normal = n;
            p.point = 0.5f * (onA + onB);
            m.points[m.count++] = p;
        }
    };
    for (size_t j = 0; j < m_manifolds.size(); ++j) {
        if (j + 2 < m_manifolds.size() && m_manifolds[j + 2].previous >= 0)
            prefetchLines(&m_last[size_t(m_manifolds[j + 2].previous)], sizeof(Manifold));
        Manifold& m = m_manifolds[j];
        if (m.previous < 0) continue;
        const Manifold& old = m_last[size_t(m.previous)];
        if (keeping) keepFrom(old, m);
        if (warm) matchImpulses(old, m);
    }
    if (!keeping) return;
    // A pair the detector no longer reports at all (lifted by a hair) keeps its points for one step; a pair
    // at rest (an island asleep: the detector skips it) keeps its manifold unsolved until it wakes.
    m_dormant.clear();
    for (size_t i = 0; i < m_last.size(); ++i) {
        const Manifold& old = m_last[i];
        if (m_lastNow[i] >= 0 || !access.alive(old.rootA) || !access.alive(old.rootB)) continue;
        if (access.resting(old.rootA) && access.resting(old.rootB)) {
            if (old.age == 0 || old.dormant) {
                m_dormant.push_back(old);
                m_dormant.back().dormant = true;
            }
            continue;
        }
        if (old.age > 0 || old.dormant) continue;
        Manifold m = old;
        m.age = 1;
        m.count = 0;
        m.a = bodyIndex(old.rootA, access);
        m.b = bodyIndex(old.rootB, access);
        m.previous = int(i);
        keepFrom(old, m);
        if (warm) matchImpulses(old, m);
        if (m.count > 0) m_manifolds.push_back(m);
    }
}

// The old point at the same place on body a gives each point of m its impulses (warm starting).
void ContactSolver::matchImpulses(const Manifold& old, Manifold& m) const {
    const Real best0 = m_settings.matchDistance * m_settings.matchDistance;
    // Tangent bases are a function of the normal's bits alone, and a pair's points mostly share one normal
    // (last step's one, this step's another): each is built once for the run of points that share it (a box
    // pair's face contact built eight for two normals).
    struct KnownBasis {
        Vec3 normal, t[2];
        bool known = false;
        void of(const Vec3& n, Vec3 out[2]) {
            if (!known || std::memcmp(normal.data(), n.data(), sizeof(n)) != 0) {
                tangentBasis(n, t);
                normal = n;
                known = true;
            }
            out[0] = t[0];
            out[1] = t[1];
        }
    } oldBasis, newBasis;
    for (int i = 0; i < m.count; ++i) {
        ManifoldPoint& p = m.points[i];
        // The old point at the same place on body a.
        const ManifoldPoint* match = nullptr;
        Real best = best0;
        for (int j = 0; j < old.count; ++j) {
            Real d2 = (old.points[j].anchorA - p.anchorA).squaredNorm();
            if (d2 <= best) {
                best = d2;
                match = &old.points[j];
            }
        }
        // A point that bounced left the surface: its impulse was an impact's, not a load to start from
        // (warm-started, it threw a ball chased by a kinematic paddle back at the paddle).
        if (!match || match->bounced) continue;
        p.normalImpulse = match->normalImpulse;
        // The old friction impulse, in the new point's tangent basis (each basis is its normal's).
        Vec3 was[2], now[2];
        oldBasis.of(match->normal, was);
        newBasis.of(p.normal, now);
        const Vec3 friction = was[0] * match->tangentImpulse[0] + was[1] * match->tangentImpulse[1];
        p.tangentImpulse[0] = friction.dot(now[0]);
        p.tangentImpulse[1] = friction.dot(now[1]);
    }
}

void ContactSolver::setMemory(const Memory& memory) {
    m_manifolds = memory.last;
    storeImpulses(); // indexes them as last step's
    m_maxDepthBefore = memory.depthBefore;
    m_maxDepthAfter = memory.depthAfter;
}

// This step's manifolds become last step's, moved rather than copied (every one has a point).
void ContactSolver::storeImpulses() {
    m_last.swap(m_manifolds);
    m_manifolds.clear();
    for (Manifold& m : m_last) m.dormant = false;
    m_last.insert(m_last.end(), m_dormant.begin(), m_dormant.end());
    m_dormant.clear();
    m_lastIndex.clear();
    for (size_t i = 0; i < m_last.size(); ++i) m_lastIndex.emplace(PairKey{m_last[i].g1, m_last[i].g2}, i);
}

} // namespace physics
