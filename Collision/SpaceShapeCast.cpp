// SpaceShapeCast.cpp - the simple space's shape cast (iShapeCast.h): time of impact of a moved body's
// geometry against every other geometry, by conservative advancement.
//
// Conservative advancement (Mirtich; Box2D's time of impact works the same way with a tighter distance):
// each shape pair's separationBound is a gap g along a unit axis a that separates them (for spheres and a
// sphere against a box, the true distance). Along a fixed axis the gap closes no faster than the motion's
// component on a plus how far turning can carry any point (angle * reach, reach = the farthest point from
// the centre of mass), so nothing touches before t + g / closing for every pair; advance to the smallest and
// repeat until a pair is within kTolerance. Each advance is safe, so no obstacle is ever stepped over,
// whatever its thickness or the speed: the guarantee holds along the interpolated path (COM linear,
// orientation slerp), against obstacles moving along their own translation since the last
// populateContactList (the pair's closing speed then uses the relative motion; their turning is not swept).
// Face-on approaches converge in one or two advances; a turning body or an edge-on box pair in more, up to
// kMaxIterations, after which the body is stopped where it is (short of the obstacle: safe, never through). A
// pair moving apart along its axis without turning (sliding along a floor it hovers over) is never a hit, and
// a pair the last populateContactList found touching (at its poses) is left to the contact solve.
// The obstacles a sweep may meet, and the pairs it leaves to the contact solve: SpaceCastObstacles.cpp.
// Cost: one pass over the geometry to find the swept bodies' geometry, where a bound on each body's motion
// from its start and end matrices (motionBound: no quaternions, no poses) clears the slow ones; then, only
// for a body that moved more than a quarter of a shape's smallest dimension, its shapes against the obstacles
// in its swept bounds, a few times.
#include "GrowingArrays.h"
#include "MathEigen.h"
#include "SimpleCollisionSpace.h"
#include "iRigidBody.h"
#include "iUtilities.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace {

using Vec3 = Eigen::Vector3f;
using Mat3 = Eigen::Matrix3f;
using Quat = Eigen::Quaternionf;

// Both in metres, times the space's length unit (iCollisionSpaceScale.h).
constexpr float kTolerance = 1e-4f; // a gap this small is a touch (and a pair this close at the start is
                                    // touching: contact resolution has it)
constexpr float kSkin = 2e-4f;      // how far past the touch the body is left, so that contact detection
                                    // sees the pair; under half of the thinnest wall we promise (1 mm)
constexpr int kMaxIterations = 32;

Vec3 eigen(const Vector& v) { return Vec3(v.x, v.y, v.z); }
Vector vec(const Vec3& v) { return Vector(v.x(), v.y(), v.z()); }
Quat quatOf(const Matrix& rowRotation) {
    return Quat(Mat3(gmath::block3(rowRotation).transpose())).normalized();
}

bool overlaps(const gcol::Aabb& a, const Vec3& lo, const Vec3& hi) {
    return a.min.x <= hi.x() && a.max.x >= lo.x() && a.min.y <= hi.y() && a.max.y >= lo.y() &&
           a.min.z <= hi.z() && a.max.z >= lo.z();
}

// s moved by d.
gcol::WorldShape shifted(gcol::WorldShape s, const Vector& d) {
    s.sphere.centre += d;
    s.box.centre += d;
    s.plane.offset += dot(s.plane.normal, d);
    return s;
}

float maxAbs(const Vector& v) { return std::fmax(std::fabs(v.x), std::fmax(std::fabs(v.y), std::fabs(v.z))); }

} // namespace

// An upper bound on how far a sweep's body moves (its COM) and turns (radians) over the motion, from its
// start and end without quaternions: for rotations R0, R1 an angle theta apart, |R1 - R0| (Frobenius) is 2
// sqrt(2) sin(theta / 2), and asin(x) <= pi x / 2 on [0, 1], so theta <= pi / (2 sqrt(2)) |R1 - R0|. The
// margins cover sweepOne's rounding many times over (its quaternions come from the same matrices). exact: no
// bound (a pose not finite, or so far out that rounding could exceed the margins).
SimpleCollisionSpace::SweepMotion SimpleCollisionSpace::motionBound(const BodySweep& sweep,
                                                                    const RBDynamics& d) {
    SweepMotion m;
    const float reachOut = std::fmax(maxAbs(sweep.startPosition), maxAbs(d.position));
    float diff = 0.0f;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            const float e = d.orientation.data()[4 * r + c] - sweep.startOrientation.data()[4 * r + c];
            diff += e * e;
        }
    const float move = (eigen(d.position) - eigen(sweep.startPosition)).norm();
    m.exact = !(reachOut < 1e30f) || !std::isfinite(diff) || !std::isfinite(move);
    m.move = move * 1.0001f + 1e-6f * (1.0f + reachOut);
    m.turn = 1.1108f * std::sqrt(diff) + 1e-3f;
    m.slack = 1e-6f * (1.0f + reachOut);
    return m;
}

// Whether geometry g of d, a body attached to nothing, may move more than a quarter of its smallest dimension
// over the motion m (sweepOne's test, which it never misses): g's origin is |com| from the COM, so no point
// of it is farther than |com| + its bounding radius.
bool SimpleCollisionSpace::mayPassThrough(const SweepMotion& m, CollisionGeometry& g, const RBDynamics& d) {
    if (m.exact) return true;
    const float reach = (g.asInterface()->getBoundingRadius() + d.com.length()) * 1.001f + m.slack;
    return !(m.move + m.turn * reach <= 0.2499f * g.minDimension());
}

size_t SimpleCollisionSpace::sweepBodies(BodySweep* sweeps, size_t count) {
    settleRemovals();
    if (m_notifying || m_populating) {
        error(L"iShapeCast::sweepBodies: called from inside a listener; ignored");
        return 0;
    }
    if (!sweeps || count == 0) return 0;
    // Each swept body's root, hashed to its sweep (open addressing, at most half full): every geometry finds
    // its sweep, if any, in O(1), with nothing sorted.
    size_t slots = 16;
    while (slots < 2 * count) slots *= 2;
    gcol::assignGrowing(m_sweepIndex, slots, std::pair<const void*, int>(nullptr, -1));
    const auto slotOf = [&](const void* root) {
        std::uint64_t x = std::uint64_t(reinterpret_cast<std::uintptr_t>(root)) * 0x9e3779b97f4a7c15ull;
        size_t slot = size_t(x >> 32) & (slots - 1);
        while (m_sweepIndex[slot].first && m_sweepIndex[slot].first != root) slot = (slot + 1) & (slots - 1);
        return slot;
    };
    m_sweepMotion.resize(count);
    gcol::assignGrowing(m_mayPass, count, (unsigned char)0);
    for (size_t i = 0; i < count; ++i) {
        sweeps[i].fraction = 1.0f;
        sweeps[i].hit = nullptr;
        sweeps[i].carried = Vector();
        if (!sweeps[i].body) continue;
        const RBDynamics& d = sweeps[i].body->getDynamics();
        m_sweepMotion[i] = motionBound(sweeps[i], d);
        std::pair<const void*, int>& slot = m_sweepIndex[slotOf(&d)];
        if (!slot.first) slot = std::make_pair(&d, int(i)); // the first sweep of a body moves it
    }
    // The pairs the last populateContactList found touching at their poses (the contact solve has them):
    // listed by the first sweep that needs them.
    m_touchedAtStartListed = false;
    // Every geometry that takes part and which sweep (if any) moves it. A swept geometry whose body cannot
    // have moved far enough to pass through anything (the bound below) is not posed now; its sweep is not
    // looked at unless another of its geometries might be fast. An obstacle is posed only when some body
    // turns out fast (most steps: none).
    m_cast.clear();
    std::vector<int>& perSweep = m_castOrder; // first used as a count per sweep
    gcol::assignGrowing(perSweep, count + 1, 0);
    for (CollisionGeometry* g : m_members) {
        // Written in place (a copy from the stack was read back before its stores had left), taken back when
        // the geometry takes no part.
        CastGeometry& c = m_cast.emplace_back();
        c.g = g;
        c.sweep = -1;
        c.posed = false;
        if (!c.g->body()) {
            if (!c.g->isPlane()) {
                m_cast.pop_back();
                continue;
            }
        } else {
            const RBDynamics& d = c.g->body()->getDynamics();
            const void* root = d.attachmentRoot();
            const std::pair<const void*, int>& slot = m_sweepIndex[slotOf(root)];
            if (slot.first == root) {
                const size_t sweep = size_t(slot.second);
                if (root != &d || c.g->isPlane() || mayPassThrough(m_sweepMotion[sweep], *c.g, d)) {
                    if (!c.g->currentPose(c.origin, c.rotation)) {
                        m_cast.pop_back();
                        continue;
                    }
                    c.posed = true;
                    m_mayPass[sweep] = 1;
                }
                c.sweep = slot.second;
                ++perSweep[size_t(c.sweep)];
            }
        }
    }
    if (std::find(m_mayPass.begin(), m_mayPass.end(), 1) == m_mayPass.end()) return 0; // nothing fast
    // Each sweep's geometry as one range of m_castOrder (a counting sort, in space order within a sweep).
    m_sweepRange.resize(count);
    int next = 0;
    for (size_t i = 0; i < count; ++i) {
        m_sweepRange[i] = std::make_pair(next, next);
        next += perSweep[i];
    }
    gcol::assignGrowing(m_castOrder, size_t(next), 0);
    for (size_t j = 0; j < m_cast.size(); ++j)
        if (m_cast[j].sweep >= 0)
            m_castOrder[size_t(m_sweepRange[size_t(m_cast[j].sweep)].second++)] = int(j);
    // Each swept body's translation: other bodies' geometry is an obstacle moving that way over the motion.
    m_sweepShift.resize(count);
    for (size_t i = 0; i < count; ++i)
        m_sweepShift[i] =
            sweeps[i].body ? sweeps[i].body->getDynamics().position - sweeps[i].startPosition : Vector();
    size_t hits = 0;
    gcol::assignGrowing(m_sweepHits, count, SweepHit());
    m_obstaclesIndexed = false; // built by the first fast sweep (most calls have none)
    for (size_t i = 0; i < count; ++i) {
        if (!sweeps[i].body || !m_mayPass[i]) continue;
        sweepOne(sweeps[i], int(i));
        if (sweeps[i].hit) ++hits;
    }
    // What each hit obstacle really does after the touch: a body that is not stopped moves on to the end of
    // its motion, and as far as it moves away from the touch it draws what touched it along (so the pair is
    // still touching for the contact solve); one stopped too (two fast bodies meeting) moves on only as far
    // as its own stop is past the touch.
    for (size_t i = 0; i < count; ++i) {
        if (!sweeps[i].hit) continue;
        const SweepHit& h = m_sweepHits[i];
        const float obstacleStop = h.obstacleSweep >= 0 ? sweeps[size_t(h.obstacleSweep)].fraction : 1.0f;
        sweeps[i].carried = h.recede * std::max(0.0f, obstacleStop - h.touch);
    }
    return hits;
}

void SimpleCollisionSpace::castShapesAt(int sweep, const Vector& position, const Matrix& rotation) {
    const Mat3 r = gmath::block3(rotation).transpose();
    m_moving.clear();
    m_movingOwner.clear();
    for (int j = m_sweepRange[size_t(sweep)].first; j < m_sweepRange[size_t(sweep)].second; ++j) {
        const CastGeometry& c = m_cast[size_t(m_castOrder[size_t(j)])];
        if (c.g->isPlane() || c.g->isSensor()) continue; // a sensor stops nothing
        Vector origin = vec(eigen(position) + r * eigen(c.localOrigin));
        Matrix rot = gmath::fromBlock3((r * gmath::block3(c.localRotation).transpose()).transpose());
        c.g->worldShapes(origin, rot, m_moving);
        m_movingOwner.resize(m_moving.size(), c.g);
    }
}

void SimpleCollisionSpace::sweepOne(BodySweep& sweep, int index) {
    const float tolerance = kTolerance * m_lengthUnit, skin = kSkin * m_lengthUnit;
    const RBDynamics& d = sweep.body->getDynamics();
    const Vec3 p0 = eigen(sweep.startPosition), p1 = eigen(d.position);
    const Quat q0 = quatOf(sweep.startOrientation), q1 = quatOf(d.orientation);
    if (!p0.allFinite() || !p1.allFinite() || !q0.coeffs().allFinite() || !q1.coeffs().allFinite()) return;
    const float angle = q0.angularDistance(q1);
    // Whether any geometry moved far enough to pass through something (the test the space's sampling uses).
    bool fast = false;
    const Vec3 dp = p1 - p0;
    const std::pair<int, int> range = m_sweepRange[size_t(index)];
    for (int j = range.first; j < range.second; ++j) { // the ones sweepBodies' bound left unposed
        CastGeometry& c = m_cast[size_t(m_castOrder[size_t(j)])];
        if (!c.posed) c.posed = c.g->currentPose(c.origin, c.rotation); // finite: their body's pose is
    }
    for (int j = range.first; j < range.second && !fast; ++j) {
        const CastGeometry& c = m_cast[size_t(m_castOrder[size_t(j)])];
        if (c.g->isPlane()) continue;
        // The geometry's origin moved by dp plus the turn of its arm from the COM, at most angle * arm.
        const float arm = (eigen(c.origin) - p1).norm();
        const float moved = dp.norm() + angle * (arm + c.g->asInterface()->getBoundingRadius());
        fast = moved > 0.25f * c.g->minDimension();
    }
    if (!fast) return;
    // Each geometry's pose in the root's frame, and how far the farthest point is from the COM.
    const Mat3 r1 = q1.toRotationMatrix();
    float reach = 0.0f, minDim = 3.4e38f;
    for (int j = range.first; j < range.second; ++j) {
        CastGeometry& c = m_cast[size_t(m_castOrder[size_t(j)])];
        if (c.g->isPlane()) continue;
        const Vec3 offset = r1.transpose() * (eigen(c.origin) - p1);
        c.localOrigin = vec(offset);
        c.localRotation =
            gmath::fromBlock3((r1.transpose() * gmath::block3(c.rotation).transpose()).transpose());
        reach = std::max(reach, offset.norm() + c.g->asInterface()->getBoundingRadius());
        minDim = std::min(minDim, c.g->minDimension());
    }
    const float travel = (p1 - p0).norm() + angle * reach; // no point moves farther over the motion
    if (!(travel > 0.0f) || !std::isfinite(travel)) return;
    // Obstacles: the other geometry within the swept bounds (planes are unbounded: always).
    const Vec3 lo = p0.cwiseMin(p1) - Vec3::Constant(reach), hi = p0.cwiseMax(p1) + Vec3::Constant(reach);
    m_obstacles.clear();
    m_obstacleOwner.clear();
    m_obstacleShift.clear();
    if (!m_obstaclesIndexed) indexObstacles();
    gatherCandidates(vec(lo), vec(hi));
    for (int candidate : m_castCandidates) {
        const size_t j = size_t(candidate);
        CastGeometry& c = m_cast[j];
        // A pair found touching when the contacts were found is the contact solve's: the straight-line path
        // (COM linear, orientation slerp) of a body turning about a touch cuts into the surface, and a domino
        // leaning on the next one was put back every step.
        if (c.sweep == index || c.sweep == kUnusableSweep || c.g->isSensor() || touchedAtStart(range, c.g))
            continue;
        const Vector& shift = c.shift;
        const Vec3 half = 0.5f * eigen(shift);
        if (!c.g->isPlane()) { // its bounding sphere against the swept bounds first: most are far
            const Vec3 o = eigen(c.origin) - half, nearest = o.cwiseMax(lo).cwiseMin(hi);
            const float r = c.g->asInterface()->getBoundingRadius() + half.norm();
            if ((o - nearest).squaredNorm() > r * r) continue;
        }
        size_t before = m_obstacles.size();
        c.g->worldShapes(c.origin, c.rotation, m_obstacles);
        bool keep = c.g->isPlane();
        for (size_t k = before; k < m_obstacles.size() && !keep; ++k) {
            gcol::Aabb box;
            gcol::shapeAabb(m_obstacles[k], box);
            const Vec3 extra = half.cwiseAbs();
            keep = overlaps(box, lo + half - extra, hi + half + extra);
        }
        if (!keep) {
            m_obstacles.resize(before);
            continue;
        }
        m_obstacleOwner.resize(m_obstacles.size(), int(j));
        m_obstacleShift.resize(m_obstacles.size(), shift);
    }
    if (m_obstacles.empty()) return;
    m_moving.clear();
    castShapesAt(index, sweep.startPosition, sweep.startOrientation);
    const size_t nm = m_moving.size(), no = m_obstacles.size();
    gcol::assignGrowing(m_ignored, nm * no, (unsigned char)0);
    // Pairs the layer rule filters out never touch (a bullet leaving its shooter).
    for (size_t i = 0; i < nm; ++i)
        for (size_t j = 0; j < no; ++j) {
            const CollisionGeometry *a = m_movingOwner[i], *b = m_cast[size_t(m_obstacleOwner[j])].g;
            if (!layersCollide(a->getLayer(), a->getMask(), b->getLayer(), b->getMask()))
                m_ignored[i * no + j] = 1;
        }
    const float turn = angle * reach; // how far turning can carry any point over the whole motion
    // How fast (per unit of the motion) moving shape i closes on obstacle j along a at fraction t: its point
    // facing the obstacle moves with the COM plus the turn about it (slerp turns at the constant rate w).
    // The COM's motion alone misses an approach carried by the turn (a part on a spinning arm), which then
    // neither counted as a hit at a touch nor was left overlapping for the contact solve to see.
    Quat turned = q1 * q0.conjugate();
    if (turned.w() < 0.0f) turned.coeffs() = -turned.coeffs();
    const Eigen::AngleAxisf turnAxis(turned);
    const Vec3 w = turnAxis.angle() * turnAxis.axis();
    const auto approachOf = [&](size_t i, size_t j, const Vector& a, float at) {
        const Vec3 arm = eigen(gcol::supportPoint(m_moving[i], a)) - (p0 + dp * at);
        return dot(vec(dp + w.cross(arm)) - m_obstacleShift[j], a);
    };
    float t = 0.0f, gap = 0.0f;
    int hit = -1, hitMoving = -1;
    Vector axis;
    for (int iteration = 0; hit < 0; ++iteration) {
        float advance = 3.4e38f; // the largest safe step, as a fraction of the motion
        int nearest = -1;
        for (size_t i = 0; i < nm && hit < 0; ++i)
            for (size_t j = 0; j < no; ++j) {
                if (m_ignored[i * no + j]) continue;
                const Vector& shift = m_obstacleShift[j];
                Vector a;
                float s = gcol::separationBound(m_moving[i], shifted(m_obstacles[j], shift * (t - 1.0f)), a);
                // Overlapping at the start, or touching without closing fast along the normal (resting,
                // sliding): contact resolution's. Touching and closing fast (a head-on hit that began at
                // an exact touch) is a hit at the start.
                if (iteration == 0 && s <= tolerance &&
                    (s < 0.0f || approachOf(i, j, a, t) <= 0.25f * minDim)) {
                    m_ignored[i * no + j] = 1;
                    continue;
                }
                // The gap along a closes no faster than the motion along a plus the turn; a pair moving
                // apart along a without turning never touches.
                const float closing = std::max(0.0f, dot(vec(dp) - shift, a)) + turn;
                if (!(closing > 0.0f)) continue;
                if (s <= tolerance) {
                    hit = int(j);
                    hitMoving = int(i);
                    gap = s;
                    axis = a;
                    break;
                }
                if (s / closing < advance) {
                    advance = s / closing;
                    nearest = int(j);
                    hitMoving = int(i);
                    gap = s;
                    axis = a;
                }
            }
        if (hit >= 0) break;
        if (nearest < 0) return;           // nothing it can reach
        if (iteration == kMaxIterations) { // slow convergence: stop here, short of the obstacle
            hit = nearest;
            gap = -skin;
            break;
        }
        t += advance;
        if (t >= 1.0f) return;
        m_moving.clear();
        Matrix rot = gmath::fromBlock3(Mat3(q0.slerp(t, q1).toRotationMatrix()).transpose());
        castShapesAt(index, vec(p0 + dp * t), rot);
    }
    // A hair past the touch along the approach, so the pair overlaps by about kSkin; never more than a tenth
    // of the body's smallest dimension further (a grazing approach).
    const float approach = approachOf(size_t(hitMoving), size_t(hit), axis, t);
    float extra = approach > 0.0f ? (gap + skin) / approach : 0.0f;
    extra = std::max(0.0f, std::min(extra, 0.1f * minDim / travel));
    sweep.fraction = std::min(1.0f, t + extra);
    const CastGeometry& obstacle = m_cast[size_t(m_obstacleOwner[size_t(hit)])];
    sweep.hit = obstacle.g->asInterface();
    // What of the obstacle's motion takes it away from the touch: along the axis, when it recedes.
    const Vector& shift = m_obstacleShift[size_t(hit)];
    m_sweepHits[size_t(index)] = {obstacle.sweep, sweep.fraction, axis * std::max(0.0f, dot(shift, axis))};
}
