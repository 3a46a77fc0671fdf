// ShockPropagation.cpp - heavy on light: each sub-step, after the velocities are solved, stop what is still
// approaching along the stack, from the ground up, moving only the upper body of each pair.
//
// Gauss-Seidel passes an impulse through a light body under a heavy one at the ratio of their masses: a
// 1 t box on a 1 kg box loses 1/1000 of its approach per pass, so at 4 sub-steps it sank 1.05 m, through
// the light box, before the accumulated impulses caught up (1:100 held). Shock propagation (Guendelman,
// Bridson and Fedkiw, "Nonconvex rigid bodies with stacking", 2003; Erleben's thesis, 2004) orders the
// bodies by their contact distance from the immovable world (level 0: fixed bodies and the static world;
// level k + 1: touching a body of level k) and, lowest pairs first, treats the lower body of each pair on
// which the upper one rests (their normal within 60 degrees of up: a stack, not a side hit) as immovable: the
// upper one alone is pushed until it no longer approaches (a point apart may close its gap within the
// sub-step). The pass does not conserve momentum (the lower body feels no reaction), so it acts
// only on what the momentum-conserving solve left approaching; its impulses are not accumulated or warm
// started, and friction does not see them. On the immovable world (where the ground must stop the light box
// before the heavy one is stopped on it) the impulse is an ordinary one, and is accumulated. Pairs on one
// level (two boxes side by side on the floor) and bodies that touch nothing immovable (a crowd in the air,
// two spheres meeting) are left alone.
#include "ContactSolver.h"
#include "GrowingStorage.h"
#include "SolverRows.h"

#include <algorithm>
#include <climits>

namespace physics {

void ContactSolver::orderByLevel() {
    m_shock.clear();
    // Only a pair of movable bodies, one kHeavyRatio times the other's mass (either way up), can be kept
    // below (an upper body is never immovable: those are level 0): with none, the levels are not worked out
    // at all.
    const auto outweighs = [](const SolverBody& upper, const SolverBody& lower) {
        return movable(upper) && movable(lower) && upper.invMass * kHeavyRatio < lower.invMass;
    };
    if (std::none_of(m_manifolds.begin(), m_manifolds.end(), [&](const Manifold& m) {
            const SolverBody &a = m_bodies[size_t(m.a)], &b = m_bodies[size_t(m.b)];
            return outweighs(a, b) || outweighs(b, a);
        }))
        return;
    const int n = int(m_bodies.size());
    assignGrowing(m_level, size_t(n), INT_MAX);
    // Each body's manifolds, as one list per body in one array (m_touching[m_touchStart[i] ..]).
    assignGrowing(m_touchStart, size_t(n) + 1, 0);
    for (const Manifold& m : m_manifolds) {
        ++m_touchStart[size_t(m.a) + 1];
        ++m_touchStart[size_t(m.b) + 1];
    }
    for (int i = 0; i < n; ++i) m_touchStart[size_t(i) + 1] += m_touchStart[size_t(i)];
    m_touching.resize(2 * m_manifolds.size());
    reserveGrowing(m_scratch, m_touchStart.size() - 1);
    m_scratch.assign(m_touchStart.begin(), m_touchStart.end() - 1); // next free place per body
    for (size_t k = 0; k < m_manifolds.size(); ++k) {
        m_touching[size_t(m_scratch[size_t(m_manifolds[k].a)]++)] = int(k);
        m_touching[size_t(m_scratch[size_t(m_manifolds[k].b)]++)] = int(k);
    }
    std::vector<int>& queue = m_scratch;
    queue.clear();
    for (int i = 0; i < n; ++i)
        if (!movable(m_bodies[size_t(i)])) {
            m_level[size_t(i)] = 0;
            queue.push_back(i);
        }
    for (size_t q = 0; q < queue.size(); ++q) { // breadth first from the immovable world
        const int body = queue[q];
        for (int t = m_touchStart[size_t(body)]; t < m_touchStart[size_t(body) + 1]; ++t) {
            const Manifold& m = m_manifolds[size_t(m_touching[size_t(t)])];
            const int other = m.a == body ? m.b : m.a;
            if (m_level[size_t(other)] != INT_MAX) continue;
            m_level[size_t(other)] = m_level[size_t(body)] + 1;
            queue.push_back(other);
        }
    }
    for (size_t k = 0; k < m_manifolds.size(); ++k) {
        const Manifold& m = m_manifolds[k];
        const int la = m_level[size_t(m.a)], lb = m_level[size_t(m.b)];
        if (la == lb || la == INT_MAX || lb == INT_MAX) continue;
        // Only where the upper body rests on the lower: hit from the side (a wrecking ball into a wall of
        // boxes), the lower body is not held by what it stands on, and treated as immovable it stopped a
        // 500 kg ball dead against 10 kg boxes.
        const Real up = m.points[0].normal.dot(m_settings.up); // the normal runs from a to b
        if ((lb > la ? up : -up) < kSupportCos) continue;
        m_shock.push_back({k, lb > la}); // (manifold, whether b is the upper body)
    }
    // Only under a heavy body (below): with no heavy pair at all, nothing is kept, and the sort is skipped.
    const auto heavyPair = [&](const std::pair<size_t, bool>& shock) {
        const Manifold& m = m_manifolds[shock.first];
        return outweighs(m_bodies[size_t(shock.second ? m.b : m.a)],
                         m_bodies[size_t(shock.second ? m.a : m.b)]);
    };
    if (std::none_of(m_shock.begin(), m_shock.end(), heavyPair)) {
        m_shock.clear();
        return;
    }
    // By level, and in manifold order within a level (a stable order without stable_sort's buffer).
    std::sort(m_shock.begin(), m_shock.end(), [this](const auto& x, const auto& y) {
        const Manifold &mx = m_manifolds[x.first], &my = m_manifolds[y.first];
        const int lx = std::max(m_level[size_t(mx.a)], m_level[size_t(mx.b)]);
        const int ly = std::max(m_level[size_t(my.a)], m_level[size_t(my.b)]);
        return lx < ly || (lx == ly && x.first < y.first);
    });
    // Only under a heavy body: a pair whose upper body outweighs the lower kHeavyRatio times, and every pair
    // below one down to the world. Elsewhere the pass's nudges (no reaction on the lower body) kept the
    // 210-box pyramid jittering above the sleep speed: awake for 10 s instead of asleep within 2.
    std::vector<char>& carries = m_carries;
    std::vector<char>& keep = m_keep;
    assignGrowing(carries, m_bodies.size(), char(0));
    assignGrowing(keep, m_shock.size(), char(0));
    for (size_t j = m_shock.size(); j-- > 0;) { // from the top down
        const Manifold& m = m_manifolds[m_shock[j].first];
        const int upper = m_shock[j].second ? m.b : m.a, lower = m_shock[j].second ? m.a : m.b;
        if (!heavyPair(m_shock[j]) && !carries[size_t(upper)]) continue;
        keep[j] = 1;
        carries[size_t(lower)] = 1;
    }
    size_t kept = 0;
    for (size_t j = 0; j < m_shock.size(); ++j)
        if (keep[j]) m_shock[kept++] = m_shock[j];
    m_shock.resize(kept);
    // Their points' normal rows, read out of the lanes once: the sub-steps' passes all use them.
    m_shockRows.resize(4 * kept);
    for (size_t j = 0; j < kept; ++j) {
        const Manifold& m = m_manifolds[m_shock[j].first];
        for (int i = 0; i < m.count; ++i) m_shockRows[4 * j + size_t(i)] = m_blocks.normalRow(m, i);
    }
}

void ContactSolver::propagateShock(Real h) {
    for (size_t j = 0; j < m_shock.size(); ++j) {
        const auto& [k, upperIsB] = m_shock[j];
        Manifold& m = m_manifolds[k];
        SolverBody &a = m_bodies[size_t(m.a)], &b = m_bodies[size_t(m.b)];
        SolverBody& upper = upperIsB ? b : a;
        if (!movable(upper)) continue;
        // On the immovable world the impulse is the ordinary one (momentum is not at stake): it is
        // accumulated, so that friction is bounded by it.
        const bool onWorld = !movable(upperIsB ? a : b);
        // Each point's gap at these poses, as the velocity sweep just used it (nothing has moved since, and
        // the pass moves no body: it holds for both passes).
        Real gaps[4];
        for (int i = 0; i < m.count; ++i) gaps[i] = std::max(Real(0), m_blocks.gap(m, i));
        const NormalRow* rows = &m_shockRows[4 * j];
        for (int pass = 0; pass < 2; ++pass) // a box's corners: twice, like the normal passes
            for (int i = 0; i < m.count; ++i) {
                ManifoldPoint& p = m.points[i];
                const Real gap = gaps[i];
                const Real vn = normalSpeed(a, b, p, rows[i]);
                if (vn >= -gap / h) continue;
                const Vec3& arm = upperIsB ? rows[i].armB : rows[i].armA;
                const Vec3& turn = upperIsB ? rows[i].turnB : rows[i].turnA;
                const Real k = upper.invMass + arm.dot(turn);
                if (!(k > 0.0f)) continue;
                const Real impulse = (-gap / h - vn) / k; // raises v_n to -gap / h
                const Real sign = upperIsB ? 1.0f : -1.0f;
                upper.v += (sign * upper.invMass * impulse) * p.normal;
                upper.w += (sign * impulse) * turn;
                if (onWorld) m_blocks.setNormalImpulse(m, i, m_blocks.normalImpulse(m, i) + impulse);
            }
    }
}

} // namespace physics
