// JointTethers.cpp - tethers: a chain holds a heavy load at the end of light links, hung from an immovable
// body or from a heavy movable one.
//
// Sequential impulses pass a load down a chain one joint at a time, and a joint between a heavy body and a
// light one converges at about the rate of their mass ratio: a 500 kg ball on ten 0.5 kg ball-jointed links
// stretched them 36 % at 4 sub-steps and, swung, fell off them. A chain whose joints keep their anchors
// within a reach (ball, hinge and fixed joints: together; a distance joint: within its maximum) can never
// hold a body further from where it starts than the sum of those reaches and of the distances between each
// link's two anchors. A tether is that bound as one more one-sided row, from the chain's start straight to
// the body (a distance joint's upper limit): it does nothing while the chain is slack or bent, and when the
// chain is pulled straight it holds the body in one row, whatever the mass ratio, as the chain would. It only
// ever asks what the joints already imply (the long-range attachments of Kim, Chentanez and Mueller, "Long
// Range Attachments", 2012, for cloth). The joints on the way carry the tether's impulse in their reactions
// (Joint::carry): what they report, and what breaks them, is what they would have carried without it.
//
// A chain starts at an immovable body (the world, a fixed, kinematic or sleeping body) or at a movable one
// more than kTetherRatio (4) times heavier than the body its first joint leads to: a crane's arm, whose
// chain from the world bends where the arm ends and so never comes taut, or one ball of a flail, with no
// immovable body at all (a 500 kg ball under a welded 2 t arm stretched its links 144 %; two 50 kg balls
// spun on the links, 3.4 %). Each step a breadth-first search along the solved joints, first from every
// immovable start and then from each movable one, heaviest first, gives each body the first two chains that
// reach it (a bridge pinned at both ends: one from each pin). A body two joints or more down a chain that is
// more than kTetherRatio times heavier than the lightest body above it on that chain, and no heavier than a
// movable start, gets a tether: a chain of like links converges well without (and pays only for a scan of
// its masses), a heavy load is what it cannot hold. Sliders and springs let their anchors part: a chain ends
// at one. A tether too slack to come taut within a sub-step is off for it.
#include "ContactSolver.h"
#include "GrowingStorage.h"
#include "Joint.h"
#include "JointRowsInline.h"
#include "SolverRows.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace physics {

void ContactSolver::tetherJoints() {
    m_tethers.clear();
    if (m_solvedJoints.size() < 2) return;
    // No body on a chain kTetherRatio times heavier than another on one (chains of like links): no tether.
    Real most = 0, least = std::numeric_limits<Real>::infinity(); // inverse masses
    for (const Joint* j : m_solvedJoints)
        for (int slot : {j->slotA, j->slotB}) {
            const Real inverse = m_bodies[size_t(slot)].invMass;
            if (inverse <= 0) continue; // immovable: a root
            most = std::max(most, inverse);
            least = std::min(least, inverse);
        }
    if (!(kTetherRatio * least < most)) return;
    // The jointed bodies, numbered apart (node), each one's joints that keep a reach listed (from
    // m_jointStart[node]): the search costs what the joints do, not what the contacts' bodies do.
    if (m_node.size() < m_bodies.size()) m_node.resize(m_bodies.size(), -1);
    m_nodeSlot.clear();
    auto node = [&](int slot) {
        int& n = m_node[size_t(slot)];
        if (n < 0) {
            n = int(m_nodeSlot.size());
            m_nodeSlot.push_back(slot);
        }
        return n;
    };
    for (const Joint* j : m_solvedJoints)
        if (std::isfinite(j->reach())) {
            node(j->slotA);
            node(j->slotB);
        }
    const size_t nodes = m_nodeSlot.size();
    assignGrowing(m_jointStart, nodes + 1, 0);
    for (const Joint* j : m_solvedJoints)
        if (std::isfinite(j->reach())) {
            ++m_jointStart[size_t(m_node[size_t(j->slotA)]) + 1];
            ++m_jointStart[size_t(m_node[size_t(j->slotB)]) + 1];
        }
    for (size_t i = 0; i < nodes; ++i) m_jointStart[i + 1] += m_jointStart[i];
    m_jointList.resize(size_t(m_jointStart[nodes]));
    m_jointCursor.assign(m_jointStart.begin(), m_jointStart.end() - 1);
    for (size_t k = 0; k < m_solvedJoints.size(); ++k) {
        const Joint* j = m_solvedJoints[k];
        if (!std::isfinite(j->reach())) continue;
        m_jointList[size_t(m_jointCursor[size_t(m_node[size_t(j->slotA)])]++)] = int(k);
        m_jointList[size_t(m_jointCursor[size_t(m_node[size_t(j->slotB)])]++)] = int(k);
    }
    // Breadth first from every chain start (a joint from an immovable body to a movable one): each body keeps
    // the first kTethersPerBody chains that reach it, no chain twice (a bridge pinned at both ends: both).
    constexpr int K = kTethersPerBody;
    assignGrowing(m_reach, nodes * K, Reach{});
    m_reachQueue.clear();
    // r reaches node v, which is heavy when kTetherRatio times heavier than the lightest body above it.
    auto label = [&](int v, Reach r) {
        const int slot = m_nodeSlot[size_t(v)];
        if (slot == r.root) return; // a loop back to a movable root
        const Real inverse = m_bodies[size_t(slot)].invMass, rootInverse = m_bodies[size_t(r.root)].invMass;
        // A movable root tethers only what is no heavier than itself (of two alike, the later slot): the
        // other's chain would give the same row again.
        const bool under = rootInverse < inverse || (rootInverse == inverse && r.root < slot);
        const bool heavy = kTetherRatio * inverse < r.lightest && under;
        r.lightest = std::max(r.lightest, inverse);
        Reach* kept = &m_reach[size_t(v) * K];
        for (int k = 0; k < K; ++k) {
            if (kept[k].chain == r.chain) return; // reached by this chain already
            if (kept[k].chain >= 0) continue;
            kept[k] = r;
            const int at = v * K + k;
            m_reachQueue.push_back(at);
            if (r.depth >= 2 && heavy)
                m_tethers.push_back(Tether{r.root, slot, r.start, r.entry, r.length, at, {}});
            return;
        }
    };
    // The joint via from node u: the node at its other end, where it holds u and where it holds that one.
    struct Across {
        int v;
        Vec3 onU, onV;
    };
    auto across = [&](int u, int via) {
        const Joint* j = m_solvedJoints[size_t(via)];
        const bool uIsA = j->slotA == m_nodeSlot[size_t(u)];
        return Across{m_node[size_t(uIsA ? j->slotB : j->slotA)], (uIsA ? j->frameA() : j->frameB()).point,
                      (uIsA ? j->frameB() : j->frameA()).point};
    };
    // The chains from node u: along each of its joints to a movable body (from a movable u, only to one
    // kTetherRatio times lighter than u).
    auto seed = [&](size_t u) {
        const SolverBody& root = m_bodies[size_t(m_nodeSlot[u])];
        for (int k = m_jointStart[u]; k < m_jointStart[u + 1]; ++k) {
            const int via = m_jointList[size_t(k)];
            const Across x = across(int(u), via);
            const SolverBody& next = m_bodies[size_t(m_nodeSlot[size_t(x.v)])];
            if (!movable(next) || (movable(root) && !(kTetherRatio * root.invMass < next.invMass))) continue;
            Reach r;
            r.chain = r.via = via;
            r.root = m_nodeSlot[u];
            r.depth = 1;
            r.start = x.onU;
            r.entry = x.onV;
            r.length = m_solvedJoints[size_t(via)]->reach();
            label(x.v, r);
        }
    };
    size_t q = 0;
    auto search = [&] {
        for (; q < m_reachQueue.size(); ++q) {
            const int at = m_reachQueue[q], u = at / K;
            for (int k = m_jointStart[size_t(u)]; k < m_jointStart[size_t(u) + 1]; ++k) {
                const int via = m_jointList[size_t(k)];
                const Reach& from = m_reach[size_t(at)];
                if (via == from.via) continue; // back up the chain
                const Across x = across(u, via);
                if (!movable(m_bodies[size_t(m_nodeSlot[size_t(x.v)])])) continue;
                Reach r = from;
                r.via = via;
                r.parent = at;
                r.depth = from.depth + 1;
                r.entry = x.onV;
                r.length = from.length + (x.onU - from.entry).norm() + m_solvedJoints[size_t(via)]->reach();
                label(x.v, r);
            }
        }
    };
    // First the chains from immovable bodies, then those from movable ones, heaviest first (a crane's arm
    // before the ball it holds, whose chain up the links would leave the arm's no way down), each into the
    // places the ones before left: a bridge keeps both its pins.
    for (size_t u = 0; u < nodes; ++u)
        if (!movable(m_bodies[size_t(m_nodeSlot[u])])) seed(u);
    search();
    // The movable starts: a body more than kTetherRatio times heavier than one it is jointed to (a chain of
    // like links has none, and sorts nothing).
    m_heavyFirst.clear();
    for (size_t u = 0; u < nodes; ++u) {
        const SolverBody& body = m_bodies[size_t(m_nodeSlot[u])];
        if (!movable(body)) continue;
        for (int k = m_jointStart[u]; k < m_jointStart[u + 1]; ++k)
            if (kTetherRatio * body.invMass <
                m_bodies[size_t(m_nodeSlot[size_t(across(int(u), m_jointList[size_t(k)]).v)])].invMass) {
                m_heavyFirst.push_back(int(u));
                break;
            }
    }
    std::sort(m_heavyFirst.begin(), m_heavyFirst.end(), [&](int a, int b) {
        const Real ia = m_bodies[size_t(m_nodeSlot[size_t(a)])].invMass,
                   ib = m_bodies[size_t(m_nodeSlot[size_t(b)])].invMass;
        return ia < ib || (ia == ib && a < b);
    });
    for (int u : m_heavyFirst) {
        seed(size_t(u));
        search();
    }
    for (int slot : m_nodeSlot) m_node[size_t(slot)] = -1; // ready for the next step
}

// Along the line from the chain's start to the body, at the poses now (a distance joint's upper limit). A
// tether that cannot come taut within the sub-step (its slack more than twice what the body's outward speed
// and a sub-step's gravity would close) stays off: most of a chain's tethers, most of the time.
void ContactSolver::prepareTethers(Real h) {
    const Real fall = m_settings.gravity * h;
    for (Tether& t : m_tethers) {
        const SolverBody &root = m_bodies[size_t(t.root)], &body = m_bodies[size_t(t.body)];
        const Vec3 pRoot = root.origin + root.rotation * t.start, pBody = body.origin + body.rotation * t.end,
                   d = pBody - pRoot;
        const Real distance = d.norm(), slack = t.length - distance;
        if (!(distance > Real(1e-6) * (t.length + 1))) { // at the start: no direction, and far from taut
            t.row.off();
            continue;
        }
        const Vec3 out = d / distance;
        const Vec3 rRoot = pRoot - root.com, rBody = pBody - body.com;
        const Real outward = out.dot(body.v + body.w.cross(rBody) - root.v - root.w.cross(rRoot));
        if (slack > 2 * h * (std::max(outward, Real(0)) + fall)) {
            t.row.off();
            continue;
        }
        t.row.setLinear(root, body, -out, rRoot, rBody);
        makeLimit(t.row, slack);
    }
}

void ContactSolver::solveTethers(Real h, JointPass pass, const JointSoftness& soft) {
    const bool push = pass == JointPass::PushOut;
    for (Tether& t : m_tethers)
        if (t.row.kind != RowKind::Off)
            t.row.solveLimit(m_bodies[size_t(t.root)], m_bodies[size_t(t.body)], t.row.error, h, push, soft);
}

// Each joint from the root down to a tethered body carries the tether's pull (+ on the joint's b side when
// the body below is its b).
void ContactSolver::carryTethers() const {
    for (const Tether& t : m_tethers) {
        if (t.row.kind == RowKind::Off || t.row.impulse == 0) continue;
        const Vec3 pull = t.row.impulse * t.row.n;
        for (int at = t.reach; at >= 0;) {
            const Reach& r = m_reach[size_t(at)];
            Joint* j = m_solvedJoints[size_t(r.via)];
            j->carry(j->slotB == m_nodeSlot[size_t(at / kTethersPerBody)] ? pull : Vec3(-pull));
            at = r.parent;
        }
    }
}

} // namespace physics
