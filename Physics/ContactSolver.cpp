// ContactSolver.cpp - the sub-stepped solve: soft contacts, Coulomb friction, warm starting, restitution.
#include "ContactSolver.h"
#include "Joint.h"
#include "Prefetch.h"
#include "SolverRows.h"

#include "MathEigen.h"
#include "RBDynamics.h"
#include "iCollisionSpace.h"

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

bool immovable(const RBDynamics& d) {
    return d.physicsType == PHYS_FixedInSpace || !(d.mass < INFINITE_MASS) || !(d.mass > 0.0f);
}

SolverSettings withLengthUnit(SolverSettings s, float unitsPerMetre) {
    const SolverSettings metre;
    s.maxPushSpeed = metre.maxPushSpeed * unitsPerMetre;
    s.restitutionThreshold = metre.restitutionThreshold * unitsPerMetre;
    s.deepOverlap = metre.deepOverlap * unitsPerMetre;
    s.touchOverlap = metre.touchOverlap * unitsPerMetre;
    s.matchDistance = metre.matchDistance * unitsPerMetre;
    s.keepDistance = metre.keepDistance * unitsPerMetre;
    s.bounceGap = metre.bounceGap * unitsPerMetre;
    return s;
}

namespace {

// Moves b by dp and turns it about its centre of mass by the rotation vector dtheta (first order), in two
// halves: turnBody() leaves the rotation to be normalised, and where the origin sits from the centre of mass
// (body axes; zero for the usual body, whose origin is its centre of mass); settleBody() normalises it and
// places the origin.
ContactSolver::Turned turnBody(SolverBody& b, const Vec3& dp, const Vec3& dtheta) {
    const bool centred = b.origin == b.com;
    ContactSolver::Turned t{centred ? Vec3(Vec3::Zero()) : Vec3(b.rotation.conjugate() * (b.origin - b.com)),
                            centred};
    Quat spin(0.0f, 0.5f * dtheta.x(), 0.5f * dtheta.y(), 0.5f * dtheta.z());
    b.rotation.coeffs() += (spin * b.rotation).coeffs();
    b.com += dp;
    return t;
}
void settleBody(SolverBody& b, const ContactSolver::Turned& t) {
    b.rotation.normalize();
    b.origin = t.centred ? b.com : Vec3(b.com + b.rotation * t.offset);
}

} // namespace

// --- default body access: one RBDynamics, no attachments ---
SolverBody SolverBodyAccess::enter(RBDynamics* root, int slot) const {
    SolverBody b;
    b.root = root;
    b.slot = slot;
    if (!root) return b; // the static world
    b.origin = b.startOrigin = b.com = toEigen(root->position);
    b.rotation = b.startRotation = toQuat(root->orientation);
    b.v = toEigen(root->velocity);
    b.w = toEigen(root->angularVelocity);
    if (!immovable(*root)) {
        Mat3 r = b.rotation.toRotationMatrix();
        b.dv = m_forceVelocity;
        b.invMass = 1.0f / root->mass;
        b.invInertia = r * tensor(root->getInverseInertiaTensor()) * r.transpose();
    }
    return b;
}

void SolverBodyAccess::storeVelocity(const SolverBody& b) const {
    if (!movable(b)) return; // immovable bodies keep their own (kinematic) velocity
    Mat3 r = b.rotation.toRotationMatrix();
    b.root->velocity = toVector(b.v);
    b.root->angularVelocity = toVector(b.w);
    b.root->angularMomentum = toVector(r * tensor(b.root->getInertiaTensor()) * r.transpose() * b.w);
}

void SolverBodyAccess::prefetch(const SolverBody& b) const {
    if (!movable(b)) return;
    // What storeVelocity and storePose write: position to angular momentum (RBDynamics' state fields).
    const char* from = reinterpret_cast<const char*>(&b.root->position);
    prefetchLines(from, size_t(reinterpret_cast<const char*>(&b.root->angularMomentum + 1) - from));
}

void SolverBodyAccess::storePose(const SolverBody& b) const {
    b.root->position = toVector(b.origin);
    b.root->orientation = toOrientation(b.rotation);
    if (b.projected) b.root->markTeleported();
}

// --- the solve, top to bottom ---
void ContactSolver::collect(const CollisionContact* contacts, size_t count, const SolverBodyAccess& access) {
    m_bodies.clear();
    m_bodyIndex.clear();
    buildManifolds(contacts, count, access);
    enterJoints(access);
}

void ContactSolver::recollect(const CollisionContact* contacts, size_t count,
                              const SolverBodyAccess& access) {
    buildManifolds(contacts, count, access);
}

void ContactSolver::dropManifolds() { m_manifolds.clear(); }

void ContactSolver::solve(Real dt, const SolverBodyAccess& access) {
    for (SolverBody& b : m_bodies)
        if (b.root && !movable(b)) access.refresh(b); // a kinematic body has moved since it entered
    startKinematic(); // ... and goes back to where it started, to move through the sub-steps
    applySwitches();
    const int n = std::max(1, m_settings.substeps);
    const Real h = dt / Real(n);
    m_dt = dt;
    // The soft contact (a damped spring in impulse form, Catto's "Soft Step"): stiff, but never stiffer than
    // a quarter of the sub-step rate can follow (a small shape's contact excepted: contactSoftness).
    m_omega = 2.0f * 3.14159265f * std::min(Real(m_settings.contactHertz), 0.25f / h);
    m_soft = softness(m_omega, m_settings.dampingRatio, h);
    m_h = h;
    m_jointSoft = softness(2.0f * 3.14159265f * std::min(Real(m_settings.jointHertz), 0.25f / h),
                           m_settings.jointDampingRatio, h);
    m_blocks.pack(m_manifolds, m_bodies); // the rows and impulses live in the blocks until unpack
    prepare(h);
    orderByLevel();
    splitForces();
    tetherJoints(); // a chain hung from an immovable body: its far bodies tethered to where it starts
    prepareJoints(h);
    // Through the sub-steps the velocities live in the blocks' flat array; joints and shock propagation (when
    // there are any) work on the bodies, which get them for that and give them back.
    m_blocks.loadVelocities(m_bodies);
    const bool jointed = !m_solvedJoints.empty(), shocked = !m_shock.empty();
    for (int i = 0; i < n; ++i) {
        m_blocks.addForces(m_bodies, 1.0f / Real(n));
        warmStart(i == 0);
        onBodies(jointed, [&] {
            warmStartJoints();
            solveJoints(h, JointPass::Velocity);
        });
        // the velocities: approach stopped, nothing pushed (the gaps measured by the last relax sweep hold:
        // nothing has moved since)
        solveContacts(h, ContactBlocks::Pass::Velocity, i == 0);
        onBodies(shocked, [&] { propagateShock(h); }); // what a light body under a heavy one could not stop
        saveVelocities();
        onBodies(jointed, [&] { solveJoints(h, JointPass::PushOut); });
        solveContacts(h, ContactBlocks::Pass::PushOut, false); // on top (at the same poses and gaps)
        moveBodies(h);                                         // by the velocities plus the push, capped
        moveKinematic(Real(i + 1) / Real(n));                  // along their path, to its end at the last
        restoreVelocities();                                   // the push out's velocity is not kept
        onBodies(jointed, [&] {
            prepareJoints(h); // the joints' rows at the new poses (the next sub-step starts there too)
            solveJoints(h, JointPass::Relax);
        });
        solveContacts(h, ContactBlocks::Pass::Relax, true); // the velocities again, at the new poses
    }
    m_blocks.storeVelocities(m_bodies);
    carryTethers(); // the joints on a tether's way report its pull as theirs
    m_blocks.unpack(m_manifolds);
    findBounces();
    projectDeepOverlaps();
    applyRestitution();
    constexpr size_t kAhead = 4;
    for (size_t i = 0; i < m_bodies.size(); ++i) {
        if (i + kAhead < m_bodies.size()) access.prefetch(m_bodies[i + kAhead]);
        const SolverBody& b = m_bodies[i];
        access.storeVelocity(b);
        if (movable(b)) access.storePose(b);
    }
    storeImpulses();
}

// Friction or restitution switched off (iSceneSwitches): every pair's coefficient is 0. A frictionless
// pair carries no friction impulse to warm-start: its friction rows are neither set up nor solved.
void ContactSolver::applySwitches() {
    for (Manifold& m : m_manifolds) {
        if (!m_settings.frictionOn) m.friction = 0.0f;
        if (!m_settings.restitutionOn) m.restitution = 0.0f;
        if (m.friction == 0.0f)
            for (int i = 0; i < m.count; ++i)
                m.points[i].tangentImpulse[0] = m.points[i].tangentImpulse[1] = 0;
    }
}

ContactSolver::Softness ContactSolver::softness(Real omega, Real dampingRatio, Real h) {
    const Real a1 = 2.0f * dampingRatio + h * omega, a2 = h * omega * a1, a3 = 1.0f / (1.0f + a2);
    return Softness{omega / a1, a2 * a3, a3};
}

// A resting point gives load / (m_eff w^2): |g| / w^2 for a body on the ground, whatever its size, but many
// times that under a stack or a heavy body (the load is last step's impulse, the mass the point's effective
// mass: a 1 t box on a 1 kg one sank 69 mm into it and walked sideways). A pair whose give would be more than
// restingOverlap of its smaller shape's radius gets the stiffness that makes it so, up to maxContactTurn a
// sub-step. Metre-sized shapes under light loads keep the world's softness, bit for bit.
ContactSolver::Softness ContactSolver::contactSoftness(const Manifold& m, Real h) const {
    const Real allowed = m_settings.restingOverlap * m.size;
    // What each unit of the contact's effective mass carries: its own weight at least, or what last step's
    // impulses held up (a stack's lower contacts, a heavy body on a light one).
    const Real load = std::max(Real(m_settings.gravity), m.load);
    if (!(allowed > 0.0f) || !(load > allowed * m_omega * m_omega)) return m_soft;
    const Real omega = std::min(Real(std::sqrt(load / allowed)), Real(m_settings.maxContactTurn / h));
    return omega > m_omega ? softness(omega, m_settings.dampingRatio, h) : m_soft;
}

// Every point's rows at the step's start (the normal and, with friction, the two tangents) in the blocks, a
// block at a time (ContactBlocks::prepare), then each manifold's soft contact from the load found with them.
void ContactSolver::prepare(Real h) {
    m_blocks.prepare(m_manifolds, m_bodies, h);
    for (Manifold& m : m_manifolds) {
        const Softness soft = contactSoftness(m, h);
        m_blocks.setSoftness(m, soft.biasRate, soft.massScale, soft.impulseScale);
    }
}

// Movable bodies start the sub-steps from the velocities they had before the forces acted (and from where
// the step started, where they entered): each sub-step adds its share of what the forces did.
void ContactSolver::splitForces() {
    for (SolverBody& b : m_bodies) {
        if (!movable(b)) continue;
        b.v -= b.dv;
        b.w -= b.dw;
    }
}

// Work on the bodies' own velocities, when there is any (the sub-steps keep them in the blocks).
template <class Work> void ContactSolver::onBodies(bool any, Work work) {
    if (!any) return;
    m_blocks.storeVelocities(m_bodies);
    work();
    m_blocks.loadVelocities(m_bodies);
}

// Every sub-step starts from the impulses the last one ended with (the first from last step's): a resting
// contact needs about the same each sub-step. An impact does not recur: a point that approached faster than
// the restitution threshold starts each later sub-step from nothing, or its impact impulse would be applied
// again and bound friction by it (a box landing at 4 m/s while sliding hopped 0.06 m/s and lost 7 % more
// slide than Coulomb's law allows).
void ContactSolver::warmStart(bool firstSubstep) {
    m_blocks.warmStart(firstSubstep, -m_settings.restitutionThreshold);
}

// One sweep over the manifolds, a block (four or eight) at a time (ContactBlocks.h). Per manifold: the normal
// impulses twice, then friction bounded by mu times the normal impulses just found, then the normal impulses
// again.
//  - Friction bounded by a stale normal impulse would take a warm-started impact's worth again in every
//    sub-step.
//  - Friction last would leave the stack's normal constraints unmet (at 4 sub-steps the 210-box pyramid never
//    came to rest, 0.5 J after 10 s; with a normal pass after friction it sleeps within 2 s).
//  - One normal pass before friction leaves a box that landed flat turning (its first corners are solved
//    first), and friction answers the turning: it bounced off sideways, 0.15 rad/s and 20 cm in 4 s. After
//    two passes, 0.001 rad/s and 1 cm.
//  - The push-out sweep solves the normal impulses twice and no friction: its velocities only move the
//    bodies and are then thrown away. With friction there the awake 210-box pyramid's top walked sideways,
//    11-26 mm in 10 s over eight starts 1 um apart; without, 8-10 mm, most of it the stack's settling (a
//    single normal pass there left the 1,000-box pile overlapping twice as deep).
//  - The relax sweep starts from velocities the sub-step has solved already: one normal pass before friction
//    is enough there (eight pyramid starts 7.9-9.1 mm against 7.8-10.3; the 4,000-box pile at rest sooner),
//    and the velocity sweep's second pass is not (a box dropped flat bounced off sideways, as above).
// Each point's target: a point apart may close its gap within the sub-step, no more. An impact at a touch
// (where the continuous stage leaves a fast body) is stopped rigidly: a soft stop lets a few % of the
// approach through, metres in a sub-step at 10^4 m/s; also in the push-out pass, where the approach is
// already stopped (a soft target there relaxes the impact's accumulated impulse and lets the same few %
// through). Otherwise, in the push out, overlap is pushed out softly at a capped speed; in the velocity and
// relax sweeps only approach is stopped.
void ContactSolver::solveContacts(Real h, ContactBlocks::Pass pass, bool measureGaps) {
    m_blocks.solve(m_bodies, ContactBlocks::Sweep{h, pass, measureGaps, m_settings.touchOverlap,
                                                  m_settings.restitutionThreshold, m_settings.maxPushSpeed});
}

// The velocities the sub-step solved for, and the joints' impulses that produced them, before the push out
// (the contacts' push out keeps its impulses apart: BlockPoint::pushed).
void ContactSolver::saveVelocities() {
    saveJoints();
    m_blocks.saveVelocities();
}

void ContactSolver::restoreVelocities() {
    restoreJoints();
    m_blocks.restoreVelocities();
}

// A kinematic body (immovable, with a velocity) was moved through the whole step before the solve; held at
// its end pose, what is joined to it or touches it met it a step ahead from the first sub-step (a joint to a
// hook carried at 2 m/s trailed it by a steady 1.6 cm, v dt / 2). It starts from its start pose instead and
// moves along the straight path to its end pose with the sub-steps, arriving exactly.
void ContactSolver::startKinematic() {
    m_kinematic.clear();
    for (size_t i = 0; i < m_bodies.size(); ++i) {
        SolverBody& b = m_bodies[i];
        if (!b.root || movable(b) || (b.v == Vec3::Zero() && b.w == Vec3::Zero())) continue;
        m_kinematic.push_back(Kinematic{i, b.startOrigin, b.origin, b.startRotation, b.rotation});
        b.origin = b.com = b.startOrigin;
        b.rotation = b.startRotation;
    }
}

void ContactSolver::moveKinematic(Real done) {
    for (const Kinematic& k : m_kinematic) {
        SolverBody& b = m_bodies[k.slot];
        const bool last = done >= 1;
        b.origin = b.com = last ? k.endOrigin : Vec3(k.startOrigin + (k.endOrigin - k.startOrigin) * done);
        b.rotation = last ? k.endRotation : k.startRotation.slerp(done, k.endRotation);
    }
}

// Semi-implicit Euler over h: the frame turns about the centre of mass. A body moves by its solved velocity
// plus what the push out added, the push's linear part capped at maxPushSpeed (its turning scaled with it).
// Each contact caps its own push, but a body pushed by many (a crowd spawned at one point) gathered theirs:
// a chain of coincident bodies, each pair pushed apart at 3 m/s, spread at 3 m/s per body, and the relax
// that was to take the push's velocity back converged too slowly to do it (1,000 spheres left at 669 m/s).
//
// Two passes: every body turned, then every rotation normalised. Each body's normalisation waits on its turn,
// and its square root and division on each other (a chain of about 75 cycles a body, perf); bodies apart
// overlap. The same operations on each body in the same order: the same bits.
void ContactSolver::moveBodies(Real h) {
    const Real cap = m_settings.maxPushSpeed;
    m_turned.resize(m_bodies.size());
    for (size_t i = 0; i < m_bodies.size(); ++i) {
        SolverBody& b = m_bodies[i];
        if (!movable(b)) continue;
        const Vec3 vSolved = m_blocks.savedVelocity(i), wSolved = m_blocks.savedSpin(i);
        Vec3 push = m_blocks.velocity(i) - vSolved, turn = m_blocks.spinSinceSaved(i);
        const Real speed = push.norm();
        if (speed > cap) {
            const Real scale = cap / speed;
            push *= scale;
            turn *= scale;
        }
        m_turned[i] = turnBody(b, h * (vSolved + push), h * (wSolved + turn));
    }
    for (size_t i = 0; i < m_bodies.size(); ++i)
        if (movable(m_bodies[i])) settleBody(m_bodies[i], m_turned[i]);
}

} // namespace physics
