// SpaceCastObstacles.cpp - what a swept body may meet in the simple space's shape cast (SpaceShapeCast.cpp):
// the pairs the last populateContactList found touching (the contact solve's, not the cast's), and an index
// of every other geometry's sphere around its motion, sorted by low x, so that a fast body's obstacles are
// found in O(log N + nearby) instead of by a pass over all.
#include "SimpleCollisionSpace.h"
#include "iCollisionGeometry.h"

#include <algorithm>
#include <cmath>

bool SimpleCollisionSpace::touchedAtStart(std::pair<int, int> range, const CollisionGeometry* obstacle) {
    if (!m_touchedAtStartListed) {
        m_touchedAtStartListed = true;
        m_touchedAtStart.clear();
        for (const Notice& n : m_touching)
            if (n.atPose && !n.sensor) m_touchedAtStart.push_back(pairOf(n.g1, n.g2));
        std::sort(m_touchedAtStart.begin(), m_touchedAtStart.end());
    }
    if (m_touchedAtStart.empty()) return false;
    for (int j = range.first; j < range.second; ++j) {
        const CollisionGeometry* mine = m_cast[size_t(m_castOrder[size_t(j)])].g;
        if (std::binary_search(m_touchedAtStart.begin(), m_touchedAtStart.end(), pairOf(mine, obstacle)))
            return true;
    }
    return false;
}

void SimpleCollisionSpace::indexObstacles() {
    m_obstaclesIndexed = true;
    m_byLowX.clear();
    m_unbounded.clear();
    m_maxSpan = 0.0f;
    for (size_t j = 0; j < m_cast.size(); ++j) {
        CastGeometry& c = m_cast[j];
        if (!c.posed) {
            c.posed = true;
            if (!c.g->currentPose(c.origin, c.rotation)) c.sweep = kUnusableSweep;
        }
        if (c.sweep == kUnusableSweep) continue;
        // Another swept body's geometry moves from its start (current pose - shift) to its current pose; so
        // does any other that moved since the contacts were found (a kinematic paddle, a slower body): held
        // at its end pose, a paddle chasing a ball it just sent off stood in the ball's path.
        const CollisionGeometry::SpaceState& st = c.g->spaceState();
        c.shift = c.sweep >= 0                                       ? m_sweepShift[size_t(c.sweep)]
                  : st.hasPrevious && st.previousBody == c.g->body() ? c.origin - st.previousOrigin
                                                                     : Vector();
        // The sphere around it over its motion (sweepOne tests the same one against a body's swept bounds).
        const float r = c.g->asInterface()->getBoundingRadius() + 0.5f * c.shift.length();
        const float lowX = c.origin.x - 0.5f * c.shift.x - r;
        if (c.g->isPlane() || !std::isfinite(lowX) || !std::isfinite(r)) {
            m_unbounded.push_back(int(j));
            continue;
        }
        m_byLowX.push_back({lowX, int(j), c.origin.y - 0.5f * c.shift.y, c.origin.z - 0.5f * c.shift.z, r});
        m_maxSpan = std::max(m_maxSpan, 2.0f * r);
    }
    std::sort(m_byLowX.begin(), m_byLowX.end());
}

// Every geometry whose sphere can reach [lo, hi], and the unbounded ones, in m_cast order (the order a pass
// over all would meet them: ties in the time of impact resolve the same way). The x order narrows the search
// to a slab; y and z drop most of the slab (in a pile of 4,000 boxes the slab held a quarter of them, sorted
// for every fast body). The test is looser than sweepOne's exact sphere test by a rounding margin, so it
// never drops a sphere that test keeps.
void SimpleCollisionSpace::gatherCandidates(const Vector& lo, const Vector& hi) {
    m_castCandidates.assign(m_unbounded.begin(), m_unbounded.end());
    auto it =
        std::lower_bound(m_byLowX.begin(), m_byLowX.end(), ObstacleSphere{lo.x - m_maxSpan, -1, 0, 0, 0});
    for (; it != m_byLowX.end() && it->lowX <= hi.x; ++it) {
        const float r = it->r * 1.001f + 1e-6f * m_lengthUnit;
        if (it->y + r < lo.y || it->y - r > hi.y || it->z + r < lo.z || it->z - r > hi.z) continue;
        m_castCandidates.push_back(it->cast);
    }
    std::sort(m_castCandidates.begin(), m_castCandidates.end());
}
