// ContactSolver.cpp - sequential impulses with warm starting, then non-linear Gauss-Seidel position
// correction.
#include "ContactSolver.h"

#include "RBDynamics.h"
#include "iCollisionGeometry.h"
#include "iCollisionSpace.h"
#include "iRigidBody.h"

#include <algorithm>
#include <cmath>

namespace physics {

float combine(CombineRule rule, float a, float b) {
    switch (rule) {
    case COMBINE_Sum:
        return a + b;
    case COMBINE_Average:
        return 0.5f * (a + b);
    case COMBINE_Max:
        return std::max(a, b);
    case COMBINE_Min:
        return std::min(a, b);
    case COMBINE_Product:
        return a * b;
    case COMBINE_GeometricMean:
        return std::sqrt(std::max(0.0f, a * b));
    }
    return a + b;
}

namespace {

bool immovable(const RBDynamics& d) {
    return d.physicsType == PHYS_FixedInSpace || !(d.mass < INFINITE_MASS) || !(d.mass > 0.0f);
}

// A tangent basis that depends on the normal alone, so last step's friction impulses still apply.
void tangentBasis(const Vec3& n, Vec3 t[2]) {
    Vec3 axis = std::fabs(n.x()) < 0.57f ? Vec3::UnitX() : Vec3::UnitY();
    t[0] = n.cross(axis).normalized();
    t[1] = n.cross(t[0]);
}

Vec3 velocityAt(const SolverBody& b, const Vec3& r) { return b.v + b.w.cross(r); }

void applyImpulse(SolverBody& b, const Vec3& r, const Vec3& p) {
    b.v += b.invMass * p;
    b.w += b.invInertia * r.cross(p);
}

float effectiveMass(const SolverBody& a, const SolverBody& b, const Vec3& rA, const Vec3& rB,
                    const Vec3& dir) {
    Vec3 ra = rA.cross(dir), rb = rB.cross(dir);
    float k = a.invMass + b.invMass + ra.dot(a.invInertia * ra) + rb.dot(b.invInertia * rb);
    return k > 0.0f ? 1.0f / k : 0.0f;
}

// A null root is the static world (a geometry without a body, such as a world-space plane): its anchors are
// world points.
Vec3 worldPoint(const RBDynamics* root, const Vec3& anchor) {
    return root ? Vec3(toRotation(root->orientation) * anchor + toEigen(root->position)) : anchor;
}
Vec3 localAnchor(const RBDynamics* root, const Vec3& world) {
    return root ? Vec3(toRotation(root->orientation).transpose() * (world - toEigen(root->position))) : world;
}

} // namespace

// --- default body access: one RBDynamics, no attachments ---
SolverBody SolverBodyAccess::load(RBDynamics* root) const {
    SolverBody b;
    b.root = root;
    if (!root) return b; // the static world
    b.com = toEigen(root->position);
    b.v = toEigen(root->velocity);
    b.w = toEigen(root->angularVelocity);
    if (!immovable(*root)) {
        Mat3 r = toRotation(root->orientation);
        b.invMass = 1.0f / root->mass;
        b.invInertia = r * tensor(root->getInverseInertiaTensor()) * r.transpose();
    }
    return b;
}

void SolverBodyAccess::storeVelocity(const SolverBody& b) const {
    if (!b.root || b.invMass == 0.0f) return; // immovable bodies keep their own (kinematic) velocity
    Mat3 r = toRotation(b.root->orientation);
    b.root->velocity = toVector(b.v);
    b.root->angularVelocity = toVector(b.w);
    b.root->angularMomentum = toVector(r * tensor(b.root->getInertiaTensor()) * r.transpose() * b.w);
}

void SolverBodyAccess::movePose(SolverBody& b, const Vec3& dp, const Vec3& dtheta) const {
    RBDynamics& d = *b.root;
    Vec3 offset = toEigen(d.position) - b.com;
    float angle = dtheta.norm();
    Mat3 turn = angle > 0.0f ? Eigen::AngleAxisf(angle, dtheta / angle).toRotationMatrix() : Mat3::Identity();
    b.com += dp;
    d.position = toVector(b.com + turn * offset);
    d.orientation = toOrientation(Mat3(turn * toRotation(d.orientation)));
}

// --- the solver ---
int ContactSolver::bodyIndex(RBDynamics* root, const SolverBodyAccess& access) {
    auto it = m_bodyIndex.find(root);
    if (it != m_bodyIndex.end()) return it->second;
    m_bodies.push_back(access.load(root));
    int index = int(m_bodies.size()) - 1;
    m_bodyIndex.emplace(root, index);
    return index;
}

void ContactSolver::buildManifolds(const CollisionContact* contacts, size_t count,
                                   const SolverBodyAccess& access) {
    m_bodies.clear();
    m_bodyIndex.clear();
    m_manifolds.clear();
    std::unordered_map<PairKey, size_t, PairKeyHash> current;
    m_maxDepthBefore = 0;
    for (size_t i = 0; contacts && i < count; ++i) {
        const CollisionContact& c = contacts[i];
        if (!c.g1 || !c.g2) continue;
        iRigidBody* rb1 = c.g1->getRigidBody();
        iRigidBody* rb2 = c.g2->getRigidBody();
        RBDynamics* rootA = rb1 ? rb1->getDynamics().attachmentRoot() : nullptr;
        RBDynamics* rootB = rb2 ? rb2->getDynamics().attachmentRoot() : nullptr;
        bool fixedA = !rootA || immovable(*rootA), fixedB = !rootB || immovable(*rootB);
        if (rootA == rootB || (fixedA && fixedB)) continue;
        Vec3 n = toEigen(c.normal);
        if (!n.allFinite() || n.squaredNorm() < 0.5f || !std::isfinite(c.depth)) continue;
        n.normalize();

        PairKey key{c.g1, c.g2};
        auto found = current.find(key);
        if (found == current.end()) {
            Manifold m;
            m.g1 = c.g1;
            m.g2 = c.g2;
            m.rootA = rootA;
            m.rootB = rootB;
            m.a = bodyIndex(rootA, access);
            m.b = bodyIndex(rootB, access);
            // A bodiless geometry has the default material of a body.
            static const RBDynamics defaults;
            const RBDynamics& matA = rb1 ? rb1->getDynamics() : defaults;
            const RBDynamics& matB = rb2 ? rb2->getDynamics() : defaults;
            m.friction = combine(m_settings.friction, matA.friction, matB.friction);
            m.restitution = combine(m_settings.restitution, matA.restitution, matB.restitution);
            found = current.emplace(key, m_manifolds.size()).first;
            m_manifolds.push_back(m);
        }
        Manifold& m = m_manifolds[found->second];
        ContactPoint p;
        p.normal = n;
        tangentBasis(n, p.tangent);
        p.depth = std::max(0.0f, c.depth);
        // The two touching surface points: a's reaches depth/2 past the contact point along n, b's as far
        // back.
        Vec3 pos = toEigen(c.pos);
        Vec3 onA = pos + 0.5f * p.depth * n, onB = pos - 0.5f * p.depth * n;
        p.anchorA = localAnchor(rootA, onA);
        p.anchorB = localAnchor(rootB, onB);
        p.rA = pos - m_bodies[m.a].com;
        p.rB = pos - m_bodies[m.b].com;
        m_maxDepthBefore = std::max(m_maxDepthBefore, p.depth);
        if (m.count < 4) {
            m.points[m.count++] = p;
        } else { // keep the four deepest
            ContactPoint* shallowest =
                std::min_element(m.points, m.points + 4, [](auto& x, auto& y) { return x.depth < y.depth; });
            if (shallowest->depth < p.depth) *shallowest = p;
        }
    }
    keepPoints(access, current);
}

// A collision detector reports only touching points, so a resting box that rocks by a hair loses the
// corners that lifted, stands on the others for a step, and rocks back: the contacts flicker and the warm
// start is lost with them. Like a persistent manifold (Bullet's contact breaking threshold), a pair still
// touching keeps last step's points that came apart by less than keepDistance, each with its impulses. Such
// a point holds only once the gap would close within the step (its target v_n is -gap/dt), so it never
// pulls and never stops a body short of touching.
void ContactSolver::keepPoints(const SolverBodyAccess& access,
                               const std::unordered_map<PairKey, size_t, PairKeyHash>& reported) {
    if (m_settings.keepDistance <= 0.0f) return;
    const float keep = m_settings.keepDistance, match2 = m_settings.matchDistance * m_settings.matchDistance;
    // Appends to m the points of old that m lacks and that are apart by less than keep; rA, rB hold the
    // world contact point until the bodies are known.
    auto keepFrom = [&](const Manifold& old, Manifold& m, const RBDynamics* rootA, const RBDynamics* rootB) {
        const Vec3 n = m.count ? m.points[0].normal : old.points[0].normal;
        const int reportedCount = m.count;
        for (int j = 0; j < old.count && m.count < 4; ++j) {
            const ContactPoint& o = old.points[j];
            bool known = false;
            for (int i = 0; i < reportedCount && !known; ++i)
                known = (m.points[i].anchorA - o.anchorA).squaredNorm() <= match2;
            if (known) continue;
            Vec3 onA = worldPoint(rootA, o.anchorA), onB = worldPoint(rootB, o.anchorB), gap = onB - onA;
            float separation = n.dot(gap);
            if (separation <= 0.0f || separation > keep || (gap - separation * n).norm() > keep)
                continue; // touching again is the detector's to report; too far apart or slid off: broken
            ContactPoint p = o;
            p.normal = n;
            tangentBasis(n, p.tangent);
            p.depth = -separation;
            p.rA = p.rB = 0.5f * (onA + onB);
            m.points[m.count++] = p;
        }
        return reportedCount;
    };
    auto toArms = [&](Manifold& m, int from) {
        for (int i = from; i < m.count; ++i) {
            m.points[i].rA -= m_bodies[m.a].com;
            m.points[i].rB -= m_bodies[m.b].com;
        }
    };
    for (Manifold& m : m_manifolds) {
        auto it = m_previous.find(PairKey{m.g1, m.g2});
        if (it != m_previous.end())
            toArms(m, keepFrom(it->second, m, m_bodies[m.a].root, m_bodies[m.b].root));
    }
    // A pair the detector no longer reports at all (lifted by a hair) keeps its points for one step.
    for (const Manifold& old : m_previousList) {
        if (old.age > 0 || reported.count(PairKey{old.g1, old.g2}) || !access.alive(old.rootA) ||
            !access.alive(old.rootB))
            continue;
        Manifold m = old;
        m.age = 1;
        m.count = 0;
        keepFrom(old, m, old.rootA, old.rootB);
        if (m.count == 0) continue;
        m.a = bodyIndex(old.rootA, access);
        m.b = bodyIndex(old.rootB, access);
        toArms(m, 0);
        m_manifolds.push_back(m);
    }
}

void ContactSolver::prepare(float dt) {
    for (Manifold& m : m_manifolds) {
        const SolverBody &a = m_bodies[m.a], &b = m_bodies[m.b];
        const Manifold* old = nullptr;
        if (m_settings.warmStart) {
            auto it = m_previous.find(PairKey{m.g1, m.g2});
            if (it != m_previous.end()) old = &it->second;
        }
        for (int i = 0; i < m.count; ++i) {
            ContactPoint& p = m.points[i];
            p.normalMass = effectiveMass(a, b, p.rA, p.rB, p.normal);
            p.tangentMass[0] = effectiveMass(a, b, p.rA, p.rB, p.tangent[0]);
            p.tangentMass[1] = effectiveMass(a, b, p.rA, p.rB, p.tangent[1]);
            float vn = p.normal.dot(velocityAt(b, p.rB) - velocityAt(a, p.rA));
            if (p.depth < 0.0f)
                p.target = p.depth / dt; // apart by -depth: may approach that far this step, no further
            else
                p.target = vn < -m_settings.restitutionThreshold ? -m.restitution * vn : 0.0f;
            // Warm start from the old point at the same place on body a.
            const ContactPoint* match = nullptr;
            float best = m_settings.matchDistance * m_settings.matchDistance;
            for (int j = 0; old && j < old->count; ++j) {
                float d2 = (old->points[j].anchorA - p.anchorA).squaredNorm();
                if (d2 <= best) {
                    best = d2;
                    match = &old->points[j];
                }
            }
            if (match) {
                p.normalImpulse = match->normalImpulse;
                Vec3 friction = match->tangent[0] * match->tangentImpulse[0] +
                                match->tangent[1] * match->tangentImpulse[1];
                p.tangentImpulse[0] = friction.dot(p.tangent[0]);
                p.tangentImpulse[1] = friction.dot(p.tangent[1]);
            }
        }
    }
}

void ContactSolver::warmStart() {
    for (Manifold& m : m_manifolds) {
        SolverBody &a = m_bodies[m.a], &b = m_bodies[m.b];
        for (int i = 0; i < m.count; ++i) {
            const ContactPoint& p = m.points[i];
            Vec3 impulse = p.normal * p.normalImpulse + p.tangent[0] * p.tangentImpulse[0] +
                           p.tangent[1] * p.tangentImpulse[1];
            applyImpulse(a, p.rA, -impulse);
            applyImpulse(b, p.rB, impulse);
        }
    }
}

// One sweep over the manifolds, forward or backward. Within a manifold, friction for every point first (each
// bounded by its normal impulse of the last sweep), then the normal impulses (Box2D's order). Interleaving
// the two point by point never settles a tall stack: at 200 iterations a 10-box tower still swayed at
// 0.17 m/s, with the manifold order it comes to rest.
void ContactSolver::solveOnce(bool backward) {
    const size_t n = m_manifolds.size();
    for (size_t k = 0; k < n; ++k) {
        Manifold& m = m_manifolds[backward ? n - 1 - k : k];
        SolverBody &a = m_bodies[m.a], &b = m_bodies[m.b];
        for (int i = 0; i < m.count; ++i) {
            ContactPoint& p = m.points[i];
            float limit = m.friction * p.normalImpulse; // Coulomb's cone as a box
            for (int t = 0; t < 2; ++t) {
                float vt = p.tangent[t].dot(velocityAt(b, p.rB) - velocityAt(a, p.rA));
                float total = std::clamp(p.tangentImpulse[t] - vt * p.tangentMass[t], -limit, limit);
                Vec3 impulse = p.tangent[t] * (total - p.tangentImpulse[t]);
                p.tangentImpulse[t] = total;
                applyImpulse(a, p.rA, -impulse);
                applyImpulse(b, p.rB, impulse);
            }
        }
        for (int i = 0; i < m.count; ++i) {
            ContactPoint& p = m.points[i];
            // Push only, never pull; aim for the target speed.
            float vn = p.normal.dot(velocityAt(b, p.rB) - velocityAt(a, p.rA));
            float total = std::max(0.0f, p.normalImpulse - (vn - p.target) * p.normalMass);
            Vec3 impulse = p.normal * (total - p.normalImpulse);
            p.normalImpulse = total;
            applyImpulse(a, p.rA, -impulse);
            applyImpulse(b, p.rB, impulse);
        }
    }
}

void ContactSolver::storeImpulses() {
    m_previous.clear();
    m_previousList.clear();
    for (const Manifold& m : m_manifolds) {
        if (m.count == 0) continue;
        m_previous.emplace(PairKey{m.g1, m.g2}, m);
        m_previousList.push_back(m);
    }
}

void ContactSolver::solveVelocities(const CollisionContact* contacts, size_t count, float dt,
                                    const SolverBodyAccess& access) {
    buildManifolds(contacts, count, access);
    prepare(dt);
    if (m_settings.warmStart) warmStart();
    // Sweeps alternate in direction (symmetric Gauss-Seidel): support travels both up and down a stack
    // within a step, and no manifold is always solved last. Measured on the 10-box tower: KE at 10 s
    // 0.0186 J one-way, 0.0012 J alternating; the 210-box pyramid drifts 9 cm one-way.
    for (int i = 0; i < m_settings.velocityIterations; ++i) solveOnce(i % 2 == 1);
    for (const SolverBody& b : m_bodies) access.storeVelocity(b);
    storeImpulses();
}

void ContactSolver::correctPositions(const SolverBodyAccess& access) {
    m_maxDepthAfter = 0;
    bool moved = true;
    for (int iteration = 0; moved && iteration < m_settings.positionIterations; ++iteration) {
        moved = false; // stop early once nothing overlaps beyond the slop
        for (Manifold& m : m_manifolds) {
            SolverBody &a = m_bodies[m.a], &b = m_bodies[m.b];
            for (int i = 0; i < m.count; ++i) {
                const ContactPoint& p = m.points[i];
                Vec3 onA = worldPoint(a.root, p.anchorA), onB = worldPoint(b.root, p.anchorB);
                float separation = p.normal.dot(onB - onA); // negative: overlap
                float c = std::clamp(m_settings.positionFraction * (separation + m_settings.slop),
                                     -m_settings.maxCorrection, 0.0f);
                if (c >= 0.0f) continue;
                moved = true;
                Vec3 mid = 0.5f * (onA + onB), rA = mid - a.com, rB = mid - b.com;
                float mass = effectiveMass(a, b, rA, rB, p.normal);
                Vec3 push = p.normal * (-c * mass);
                if (a.invMass > 0.0f) access.movePose(a, -a.invMass * push, -(a.invInertia * rA.cross(push)));
                if (b.invMass > 0.0f) access.movePose(b, b.invMass * push, b.invInertia * rB.cross(push));
            }
        }
    }
    for (const Manifold& m : m_manifolds) {
        for (int i = 0; i < m.count; ++i) {
            const ContactPoint& p = m.points[i];
            Vec3 onA = worldPoint(m_bodies[m.a].root, p.anchorA),
                 onB = worldPoint(m_bodies[m.b].root, p.anchorB);
            float overlap = -p.normal.dot(onB - onA);
            m_maxDepthAfter = std::max(m_maxDepthAfter, overlap);
            // Still being pushed out (by more than the resting tolerance): not at rest, whatever its speed.
            if (overlap > m_settings.slop + 0.001f) m_bodies[m.a].settling = m_bodies[m.b].settling = true;
        }
    }
}

void ContactSolver::clear() {
    m_previous.clear();
    m_previousList.clear();
    m_manifolds.clear();
    m_bodies.clear();
    m_bodyIndex.clear();
}

} // namespace physics
