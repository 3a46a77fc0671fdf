// JointClosing.cpp - the joints of bodies the step moved alone, closed by positions (JointClosing.h).
#include "JointClosing.h"

#include "ContactSolver.h"
#include "Joint.h"
#include "MathBridge.h"
#include "RigidBody.h"

#include <cmath>

namespace physics {

void JointClosing::add(RigidBody* b, bool held) {
    if (b->joints.empty()) return;
    b->closingHeld = b->closingHeld || held;
    if (b->closingQueued) return;
    b->closingQueued = true;
    m_bodies.push_back(b);
    m_depth.push_back(0);
}

namespace {

// A body the joints' closing may move: awake, movable, a root without attachments.
bool projectable(const RigidBody* b) {
    const RBDynamics& d = b->getDynamics();
    return !b->dying() && !b->pendingRemoval && !b->asleep() && !immovable(d) && !d.attachedTo() &&
           !d.firstAttached();
}

// Moves b by the positional impulse `push` (kg m) at world point p, about its centre of mass.
void shove(RigidBody* b, const Vec3& push, const Vec3& p) {
    RBDynamics& d = b->getDynamics();
    const Vec3 com = toEigen(d.position);
    d.position = toVector(com + push / Real(d.mass));
    const Vec3 turn = tensor(d.getWorldInverseInertiaTensor()) * (p - com).cross(push);
    Quat q = b->rotation;
    q.coeffs() += (Quat(0, turn.x(), turn.y(), turn.z()) * q).coeffs() * Real(0.5);
    q.normalize();
    b->rotation = q;
    d.orientation = toOrientation(q);
    b->writtenOrientation = d.orientation;
    b->hasComposite = false;
}

} // namespace

void JointClosing::close() {
    m_closing.clear();
    // The joints reachable from the bodies added through movable bodies, each once (from the end walked
    // first), in the order they are reached.
    for (size_t k = 0; k < m_bodies.size(); ++k) {
        RigidBody* body = m_bodies[k];
        const int depth = m_depth[k];
        body->closingWalked = true;
        for (Joint* j : body->joints) {
            RigidBody* other = j->bodyA() == body ? j->bodyB() : j->bodyA();
            if (!j->acting() || !std::isfinite(j->reach()) || (other && other->closingWalked)) continue;
            m_closing.push_back(j);
            if (other && projectable(other) && !other->closingHeld && !other->closingQueued &&
                depth + 1 < kDepth) {
                other->closingQueued = true;
                m_bodies.push_back(other); // walked for its joints, not held
                m_depth.push_back(depth + 1);
            }
        }
    }
    for (int sweep = 0; sweep < kSweeps && !m_closing.empty(); ++sweep)
        for (Joint* j : m_closing) {
            RigidBody *a = j->bodyA(), *b = j->bodyB();
            JointFrame fa, fb;
            j->worldFrames(fa, fb); // at the poses now
            const Vec3 pa = fa.point, pb = fb.point, e = pb - pa;
            const Real length = e.norm(), error = length - Real(j->reach());
            if (!(error > kSlop)) continue;
            const Vec3 n = e / length;
            // A held body stays where it was put, unless the joint joins two (each put back to its own touch:
            // the ragdoll's forearm and upper arm, 2.2 cm apart after 16 sweeps when both held).
            const bool bothHeld = a && b && a->closingHeld && b->closingHeld;
            auto weight = [&](RigidBody* x, const Vec3& p) -> Real {
                if (!x || !projectable(x) || (x->closingHeld && !bothHeld)) return 0;
                const RBDynamics& d = x->getDynamics();
                const Vec3 arm = (p - toEigen(d.position)).cross(n);
                return Real(1) / Real(d.mass) + arm.dot(tensor(d.getWorldInverseInertiaTensor()) * arm);
            };
            const Real wa = weight(a, pa), wb = weight(b, pb);
            if (!(wa + wb > 0)) continue;
            const Vec3 push = n * (error / (wa + wb));
            if (wa > 0) shove(a, push, pa);
            if (wb > 0) shove(b, -push, pb);
        }
    for (RigidBody* b : m_bodies) b->closingHeld = b->closingWalked = b->closingQueued = false;
    m_bodies.clear();
    m_depth.clear();
}

} // namespace physics
