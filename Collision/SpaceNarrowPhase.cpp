// SpaceNarrowPhase.cpp - the space's narrow phase (step 4 of SimpleCollisionSpace.h), one candidate pair at a
// time: the exact test at the current pose, then (when the pair moved fast since the previous call) an exact
// sweep for spheres and sampling of the motion.
//
// What is guaranteed, with delta > 0 and samplesPerSecond > 0:
//  * a pair touching at the current pose is always reported, with current-pose contacts;
//  * a sphere geometry moving relative to a sphere, box or plane geometry (not a compound) is swept exactly
//    along the straight line between its previous and current centre, the other shape held at its current
//    pose and displaced by its own translation (its rotation over the step is covered by sampling when
//    large): a sphere cannot pass through a sphere or a box at any speed. The contact is reported at the
//    first time of impact: pos = the touching point on the other shape (in its current pose), normal = the
//    contact normal there (from g1 to g2), depth = how far the sphere went on past that touching plane by
//    the end of the step (>= 0);
//  * otherwise the motion is sampled at n - 1 intermediate poses (positions interpolated linearly,
//    orientations by slerp), n = max(ceil(delta * samplesPerSecond), ceil(relative motion / (half the
//    smaller shape's smallest dimension))), at most kMaxSamples; the first sample that touches is reported
//    with the contacts computed at that sample's poses. Below the cap, an overlap along the path deeper than
//    about half a sample step is never missed; grazing overlaps shallower than that may be;
//  * planes need none of this: everything behind a plane is solid, so the current pose catches it.
// A pair the layer rule filters out is not tested; a pair with a sensor is tested at the current pose only,
// for overlap (a notice for contact events, no contacts).
// Only pairs where a geometry moved more than a quarter of its own smallest dimension, and the pair moved
// more than a quarter of the smaller one's, go past the current-pose test (slower ones cannot pass through
// each other). Cost: one exact test per candidate pair; a swept sphere about 70 point-distance
// evaluations more; a sampled pair up to n - 1 more exact tests (plus the shapes rebuilt at each sample).
// With the cap, a box pair whose relative path per step exceeds 64 * (half the smaller box's thinnest
// dimension) is sampled more coarsely than that.
#include "MathEigen.h"
#include "SimpleCollisionSpace.h"

#include <Eigen/Geometry>

#include <cmath>

namespace {

constexpr int kMaxSamples = 64;
constexpr unsigned kContinuousTag = 0x80000000u; // feature-id bit: found by sweep or sampling

Matrix slerpRotation(const Matrix& a, const Matrix& b, float t) {
    Eigen::Quaternionf qa(gmath::block3(a)), qb(gmath::block3(b));
    return gmath::fromBlock3(qa.slerp(t, qb).toRotationMatrix());
}

bool singleSphere(const SimpleCollisionSpace::Entry& e, const std::vector<gcol::WorldShape>& shapes) {
    return e.last - e.first == 1 && shapes[size_t(e.first)].kind == gcol::ShapeKind::Sphere;
}

} // namespace

void SimpleCollisionSpace::emit(const Entry& a, const Entry& b, const gcol::ContactManifold& m,
                                unsigned childPair, unsigned tag) {
    // a and b are this call's entries: their interfaces are kept by index.
    iCollisionGeometry* const ga = m_interfaces[size_t(&a - m_entries.data())];
    iCollisionGeometry* const gb = m_interfaces[size_t(&b - m_entries.data())];
    for (int i = 0; i < m.count; ++i) {
        if (full()) { // the budget: the pair's remaining contacts are dropped
            m_cut = true;
            return;
        }
        const gcol::ContactPoint& p = m.points[i];
        // Written in place: a contact put together on the stack and copied was read back before its
        // fields' stores had left (a stall on every contact).
        CollisionContact& c = m_contacts.emplace_back();
        c.pos = p.pos;
        c.normal = p.normal;
        c.depth = p.depth;
        c.g1 = ga;
        c.g2 = gb;
        m_contactGeoms.emplace_back(a.g, b.g);
        m_features.push_back((p.feature & 0xFFFu) | ((childPair & 0x3FFFFu) << 12) | tag);
    }
}

bool SimpleCollisionSpace::testAtPoses(const Entry& a, const Entry& b, float t, unsigned tag) {
    const std::vector<gcol::WorldShape>* sa = &m_shapes;
    const std::vector<gcol::WorldShape>* sb = &m_shapes;
    int fa = a.first, la = a.last, fb = b.first, lb = b.last;
    if (t < 1.0f) {
        m_scratchA.clear();
        m_scratchB.clear();
        a.g->worldShapes(a.prevOrigin + (a.origin - a.prevOrigin) * t,
                         slerpRotation(a.prevRotation, a.rotation, t), m_scratchA);
        b.g->worldShapes(b.prevOrigin + (b.origin - b.prevOrigin) * t,
                         slerpRotation(b.prevRotation, b.rotation, t), m_scratchB);
        sa = &m_scratchA;
        sb = &m_scratchB;
        fa = fb = 0;
        la = int(m_scratchA.size());
        lb = int(m_scratchB.size());
    }
    bool any = false;
    gcol::ContactManifold m;
    for (int i = fa; i < la; ++i)
        for (int j = fb; j < lb; ++j) {
            if (gcol::collideShapes((*sa)[size_t(i)], (*sb)[size_t(j)], m, m_lengthUnit) == 0) continue;
            emit(a, b, m, unsigned((i - fa) << 9 | (j - fb)), tag);
            any = true;
        }
    return any;
}

bool SimpleCollisionSpace::sweepSpheres(const Entry& a, const Entry& b) {
    bool aSphere = singleSphere(a, m_shapes), bSphere = singleSphere(b, m_shapes);
    if (!aSphere && !bSphere) return false;
    if (b.last - b.first != 1 || a.last - a.first != 1) return false;
    // The sphere is s, the other shape o (held at its current pose; its translation moves the start).
    const bool sIsA = aSphere;
    const Entry& s = sIsA ? a : b;
    const Entry& o = sIsA ? b : a;
    const gcol::SphereShape& sphere = m_shapes[size_t(s.first)].sphere;
    const gcol::WorldShape& other = m_shapes[size_t(o.first)];
    Vector p1 = sphere.centre;
    Vector p0 = s.prevOrigin + (p1 - s.origin) + (o.origin - o.prevOrigin);
    float t;
    if (!gcol::sweepSphere(other, p0, p1, sphere.radius, t)) return false;
    Vector at = p0 + (p1 - p0) * t, q;
    gcol::pointShapeDistance(other, at, q);
    Vector n = (q - at).normalize(); // from the sphere toward the other shape
    if (n.lengthSquared() == 0.0f) n = (p1 - p0).normalize();
    gcol::ContactManifold m;
    m.count = 1;
    m.points[0].pos = q;
    m.points[0].normal = sIsA ? n : -n;
    m.points[0].depth = std::fmax(0.0f, dot(p1 - at, n));
    m.points[0].feature = 0xFFFu;
    emit(a, b, m, 0, kContinuousTag);
    return true;
}

// A sensor pair: overlap at the current pose, reported as a notice only (no contact for the solver, and
// outside the contact budget, which counts contacts).
void SimpleCollisionSpace::testSensorPair(const Entry& a, const Entry& b) {
    gcol::ContactManifold m;
    for (int i = a.first; i < a.last; ++i)
        for (int j = b.first; j < b.last; ++j) {
            if (gcol::collideShapes(m_shapes[size_t(i)], m_shapes[size_t(j)], m) == 0) continue;
            Notice n;
            n.g1 = a.g;
            n.g2 = b.g;
            n.b1 = a.body;
            n.b2 = b.body;
            n.normal = m.points[0].normal;
            Vector sum;
            for (int k = 0; k < m.count; ++k) sum += m.points[k].pos;
            n.pos = sum / float(m.count);
            n.points = m.count;
            n.atPose = true;
            n.sensor = true;
            m_notices.push_back(n);
            return; // one overlap is the answer
        }
}

void SimpleCollisionSpace::testPair(const Entry& a, const Entry& b, float delta) {
    if (a.body && a.body == b.body) return;
    if (!layersCollide(a.layer, a.mask, b.layer, b.mask)) return;
    if (a.fixed && b.fixed) return;
    if (a.sensor || b.sensor) {
        testSensorPair(a, b);
        return;
    }
    if (full()) { // the contact budget is spent: the pair is dropped untested
        ++m_droppedPairs;
        return;
    }
    const size_t before = m_contacts.size();
    m_cut = false;
    bool hit = testAtPoses(a, b, 1.0f, 0);
    const bool touchingNow = hit;
    if (!hit && delta > 0.0f && (a.moved || b.moved) && !a.plane && !b.plane) {
        Vector rel = (a.origin - a.prevOrigin) - (b.origin - b.prevOrigin);
        float aRot = a.motion - (a.origin - a.prevOrigin).length();
        float bRot = b.motion - (b.origin - b.prevOrigin).length();
        float motion = rel.length() + aRot + bRot;
        float size = std::fmin(a.minDim, b.minDim);
        if (motion > 0.25f * size) {
            hit = sweepSpheres(a, b);
            // A swept sphere is exact unless the other shape also turned noticeably.
            bool sweptExactly = (singleSphere(a, m_shapes) || singleSphere(b, m_shapes)) &&
                                a.last - a.first == 1 && b.last - b.first == 1 && aRot + bRot <= 0.25f * size;
            if (!hit && !sweptExactly) {
                float byRate = std::ceil(delta * float(m_samplesPerSecond));
                float bySize = std::ceil(motion / (0.5f * size));
                int n = int(std::fmin(float(kMaxSamples), std::fmax(byRate, bySize)));
                for (int k = 1; k < n && !hit; ++k)
                    hit = testAtPoses(a, b, float(k) / float(n), kContinuousTag);
            }
        }
    }
    if (m_cut) ++m_droppedPairs; // cut off part way, perhaps entirely
    if (!hit || m_contacts.size() == before) return;
    // One notice per geometry pair: the average contact position (the centre of the overlap area). Written
    // in place, as emit writes its contacts.
    Notice& n = m_notices.emplace_back();
    n.g1 = a.g;
    n.g2 = b.g;
    n.b1 = a.body;
    n.b2 = b.body;
    n.normal = m_contacts[before].normal;
    Vector sum;
    for (size_t i = before; i < m_contacts.size(); ++i) sum += m_contacts[i].pos;
    n.points = int(m_contacts.size() - before);
    n.pos = sum / float(n.points);
    n.atPose = touchingNow;
    n.sensor = false;
}
