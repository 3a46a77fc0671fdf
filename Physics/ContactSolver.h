// ContactSolver.h - resolves one step's contacts and joints: sub-stepped sequential impulses with soft
// contacts.
//
// The solve replaces the step's motion of every body it touches (Catto's "soft step", Box2D v3):
//   build manifolds per geometry pair (up to 4 points; points that came apart by a hair are kept), match each
//   point with last step's at the same body-local anchor to start from its impulses; then, for each of n
//   sub-steps of h = dt/n: add 1/n of what the forces did to the velocities, re-apply the accumulated
//   impulses (warm start; an impact's only in the first), solve (per manifold: the normal impulses,
//   accumulated and clamped >= 0, twice, then two Coulomb friction impulses per point, then the normal
//   impulses again), push out (the normal impulses twice, no friction), move the bodies by h, and relax
//   (solve again without the push out, one normal pass before friction). Last, overlap
//   deeper than any resting contact reaches (a fast body found late) is projected out, and the points that
//   approached faster than a threshold bounce, returning e^2 of the energy the impact brought
//   (ContactRestitution.cpp).
// A point's separation is measured anew in every sub-step from its anchors on both bodies. Overlap is pushed
// out by a soft constraint (a stiff, heavily damped spring at a capped speed) and the relax removes the
// push's velocity, so no energy is added. There is no slop: a dead band of allowed overlap let a 10-box tower
// lean 5 cm within it, while kept points are what keeps a resting contact alive. A point still apart (a kept
// point) may close its gap within the sub-step and no more (speculative). The resting overlap is the spring's
// give, load / (effective mass * (2 pi f)^2): 1.2 mm under nine boxes at 4 sub-steps (f = 60 Hz).
// A sub-step solves 11 rows a point (5 + 2 + 4) and sub-steps are the accuracy knob.
// Joints (Joint.h, JointStage.cpp) are solved in the same sub-steps, before the contacts in each pass: rigid
// rows in the velocity and relax passes, their drift corrected in the push out (forgotten with it); a heavy
// body down a chain hung from an immovable one is tethered to the chain's start (JointTethers.cpp).
// References: Catto, "Iterative Dynamics with Temporal Coherence" (GDC 2005), "Solver2D" (2024) and
// "Soft Step" (Box2D v3); Bullet's persistent manifold (contact breaking threshold).
#pragma once

#include "ContactBlocks.h"
#include "FlatMap.h"
#include "JointRows.h"
#include "MathBridge.h"
#include "SolverData.h"
#include "iContactSettings.h"

#include <cstddef>
#include <utility>
#include <vector>

struct CollisionContact;
struct RBDynamics;

namespace physics {

class Joint; // Joint.h
enum class JointPass;

// Lengths and speeds are in the world's length unit (units per metre: lengthUnitsPerMetre, default 1); the
// figures below are the metre defaults, and withLengthUnit() scales them all for another unit.
struct SolverSettings {
    int substeps = 4;                  // the iterations knob: each is a solve, a move and a relax
    float contactHertz = 100.0f;       // stiffness of the push out (capped at a quarter of the sub-step rate)
    float dampingRatio = 10.0f;        // heavily damped: an overlap is pushed out, never bounced out
    float maxPushSpeed = 3.0f;         // m/s at most to push an overlap out
    float restitutionThreshold = 1.0f; // m/s of approach below which a contact does not bounce
    float deepOverlap = 0.01f;         // m: overlap beyond this is projected out at once (a late-found hit)
    float touchOverlap = 0.001f;       // m: an impact into overlap shallower than this is stopped rigidly
    float matchDistance = 0.05f;       // m: a point within this of last step's anchor inherits its impulses
    float keepDistance = 0.01f;        // m: a point that came apart by less than this is kept (0: never)
    float bounceGap = 1e-4f;           // m: a bouncing pair is left this far apart
    bool warmStart = true;             // start from last step's impulses
    CombineRule friction = COMBINE_Sum;    // the seed's rule: the two bodies' values added
    CombineRule restitution = COMBINE_Max; // a superball bounces off anything
    // What follows a body's own size and load: a resting contact's overlap is the soft contact's give, load
    // / (m_eff w^2), about |g| / w^2 (0.07 mm at 60 Hz) for a body on the ground, the same for a 1 mm cube
    // and a 1 km rock, but a thousand times that for a 1 t box on a 1 kg one. A pair whose give exceeds
    // restingOverlap of its smaller shape's bounding radius (load per unit mass: |g| at least, or what last
    // step's impulses carried) gets a stiffer contact, w = sqrt(load / (restingOverlap r)), at most
    // maxContactTurn radians a sub-step (w h <= 2 pi: the soft step still moves less than a quarter of the
    // gap a sub-step, no overshoot). With the default 4 sub-steps at 60 Hz, the world's own stiffness serves
    // every shape of radius over 14 mm on the ground, and a body down to 0.9 mm across rests within 0.5 % of
    // its size.
    float gravity = 9.81f;         // |g|, in length units per s^2 (the scene's gravity)
    Vec3 up = Vec3::UnitY();       // against gravity, unit (zero in a world without gravity)
    float restingOverlap = 0.005f; // of the smaller shape's bounding radius
    float maxContactTurn = 6.2831853f;
    bool frictionOn = true, restitutionOn = true; // off: every pair's coefficient is 0 (iSceneSwitches)
    // Joints (Joint.h): rigid in the velocity passes, swept jointIterations times in each; their drift
    // corrected in the push out at the bias rate of a soft constraint of this frequency (capped at a quarter
    // of the sub-step rate) and damping ratio (JointStage.cpp).
    int jointIterations = 2;
    float jointHertz = 60.0f;
    float jointDampingRatio = 1.0f;
};

// s with every length and speed of the metre defaults (SolverSettings{}) scaled to unitsPerMetre.
SolverSettings withLengthUnit(SolverSettings s, float unitsPerMetre);

float combine(CombineRule rule, float a, float b);
// Fixed in space, infinite or invalid mass: contacts never move it.
bool immovable(const RBDynamics& d);

// How the solver reads and writes a body. The default works on a single RBDynamics whose forces already
// acted, all of them the same uniform field: forceVelocity is what they added to every movable body's
// velocity this step (gravity: g dt). The scene enters a body it will move before its forces act, and
// completes it once they did (SceneBodyAccess).
class SolverBodyAccess {
public:
    explicit SolverBodyAccess(const Vec3& forceVelocity = Vec3::Zero()) : m_forceVelocity(forceVelocity) {}
    virtual ~SolverBodyAccess() = default;
    // A body as it enters the solver (slot: its index among the solver's bodies; nullptr: the static world).
    virtual SolverBody enter(RBDynamics* root, int slot) const;
    // An immovable body's pose and velocities as the step left them, just before the solve.
    virtual void refresh(SolverBody&) const {}
    // Writes back v and w (and the angular momentum that goes with w).
    virtual void storeVelocity(const SolverBody& b) const;
    // Writes back the frame (origin, rotation) the sub-steps moved a movable body to.
    virtual void storePose(const SolverBody& b) const;
    // Asks for what storeVelocity and storePose of b will write to be loaded (a hint: the bodies lie apart in
    // memory, in no order the caches can guess; a few bodies ahead, they arrive while others are written).
    virtual void prefetch(const SolverBody& b) const;
    // Whether a body of last step is still there to be touched (nullptr: the static world).
    virtual bool alive(const RBDynamics* root) const { return !root; }
    // Whether a body rests outside the solve, asleep or fixed (nullptr, the static world, does): a pair of
    // two such keeps its manifold, unsolved, for when it wakes.
    virtual bool resting(const RBDynamics* root) const { return !root; }

private:
    Vec3 m_forceVelocity;
};

class ContactSolver {
public:
    // A body turned by moveBodies' first pass, for its second: where its origin sits from its centre of mass
    // (body axes), or that it sits on it.
    struct Turned {
        Vec3 offset;
        bool centred;
    };

    void setSettings(const SolverSettings& s) { m_settings = s; }
    const SolverSettings& settings() const { return m_settings; }

    // The two stages of a step's contact resolution:
    //  1. collect, at the step's starting poses, before any force acts: this step's manifolds, last step's
    //     points kept, impulses matched for the warm start; the bodies they touch enter through access.
    //  2. solve, once the forces acted (each movable body's velocities and what the forces added, written
    //     into body(i) by whoever entered it): moves those bodies through the step, from where it started.
    void collect(const CollisionContact* contacts, size_t count, const SolverBodyAccess& access);
    // This step's joints, before collect (JointStage.cpp): their bodies enter the solve with the contacts'
    // (a joint whose two bodies both rest is left out), and contacts between bodies they join without
    // collideConnected are dropped. The pointers are only read until solve returns.
    void setJoints(const std::vector<Joint*>& joints);
    // The joints solved in the last solve, and the length of its sub-steps (for their reactions).
    const std::vector<Joint*>& joints() const { return m_solvedJoints; }
    Real substepLength() const { return m_h; }
    SolverBody& body(int slot) { return m_bodies[size_t(slot)]; }
    // Between the stages, when the contacts changed (a geometry deleted, the space gone): the manifolds again
    // from what is left, or none; the bodies that entered stay and are still moved.
    void recollect(const CollisionContact* contacts, size_t count, const SolverBodyAccess& access);
    void dropManifolds();
    void solve(Real dt, const SolverBodyAccess& access);
    // Both stages at once, for an access whose bodies are complete as they enter.
    void solve(const CollisionContact* contacts, size_t count, Real dt, const SolverBodyAccess& access) {
        collect(contacts, count, access);
        solve(dt, access);
    }

    // What the next step reads of the last (snapshots): its manifolds with their impulses, and its overlaps.
    struct Memory {
        std::vector<Manifold> last;
        float depthBefore = 0, depthAfter = 0;
    };
    Memory memory() const { return Memory{m_last, m_maxDepthBefore, m_maxDepthAfter}; }
    void setMemory(const Memory& m);

    // Deepest overlap reported to the last solve / left after it.
    float maxPenetrationBefore() const { return m_maxDepthBefore; }
    float maxPenetrationAfter() const { return m_maxDepthAfter; }
    // The manifolds of the last solve, with their impulses.
    const std::vector<Manifold>& manifolds() const { return m_last; }
    // The bodies of the last solve.
    const std::vector<SolverBody>& bodies() const { return m_bodies; }

private:
    // ContactManifolds.cpp
    int bodyIndex(RBDynamics* root, const SolverBodyAccess& access);
    void buildManifolds(const CollisionContact* contacts, size_t count, const SolverBodyAccess& access);
    // Last step's manifold of a pair (an index into m_last; -1: none).
    int previousManifold(const iCollisionGeometry* g1, const iCollisionGeometry* g2);
    void carryOver(const SolverBodyAccess& access); // kept points and warm-start impulses from m_last
    void matchImpulses(const Manifold& old, Manifold& m) const;
    void storeImpulses();
    // JointStage.cpp
    bool joinedWithoutContact(const RBDynamics* a, const RBDynamics* b) const;
    void enterJoints(const SolverBodyAccess& access);
    void prepareJoints(Real h);
    void warmStartJoints();
    void solveJoints(Real h, JointPass pass);
    void saveJoints();
    void restoreJoints();
    // JointTethers.cpp
    void tetherJoints();
    void prepareTethers(Real h);
    void solveTethers(Real h, JointPass pass, const JointSoftness& soft);
    void carryTethers() const;
    // ContactSolver.cpp
    void applySwitches();
    void prepare(Real h);
    void splitForces();
    template <class Work> void onBodies(bool any, Work work);
    void warmStart(bool firstSubstep);
    void solveContacts(Real h, ContactBlocks::Pass pass, bool measureGaps);
    void saveVelocities();
    void moveBodies(Real h);
    void startKinematic();
    void moveKinematic(Real done); // done: the share of the step behind them
    void restoreVelocities();
    // ShockPropagation.cpp
    void orderByLevel();
    void propagateShock(Real h);
    // ContactRestitution.cpp
    static void prepareBounce(const SolverBody& a, const SolverBody& b, ManifoldPoint& p,
                              const NormalRow& row, Real dt);
    void findBounces();
    void applyRestitution();
    void projectDeepOverlaps(); // and measures the overlap left (m_maxDepthAfter)

    SolverSettings m_settings;
    std::vector<SolverBody> m_bodies;
    FlatMap<const RBDynamics*, int> m_bodyIndex;
    std::vector<Manifold> m_manifolds; // this step's, while solving
    ContactBlocks m_blocks;            // their rows and impulses during the sub-steps
    std::vector<Manifold> m_last;      // last step's, in solving order (for warm starting and keeping)
    std::vector<Manifold> m_dormant;   // this step's pairs at rest (both asleep or fixed), carried unsolved
    FlatMap<PairKey, size_t, PairKeyHash> m_lastIndex; // into m_last
    std::vector<int> m_lastNow; // per m_last: this step's manifold of its pair (-1: the pair is not reported)
    size_t m_lastCursor = 0;    // where previousManifold looks first
    FlatMap<PairKey, size_t, PairKeyHash> m_current; // a new pair's manifold, while they are built
    float m_maxDepthBefore = 0, m_maxDepthAfter = 0;
    Real m_dt = 0;                                // the step being solved
    Real m_h = 0;                                 // its sub-step
    std::vector<Joint*> m_joints, m_solvedJoints; // set for the step; entered (both bodies not resting)
    std::vector<std::pair<const RBDynamics*, const RBDynamics*>> m_noContact; // joined roots, sorted
    // Tethers (JointTethers.cpp): a body two joints or more down a chain from an immovable body or a heavy
    // movable one, kept within the chain's length of where the chain starts on it (two chains at most).
    static constexpr int kTethersPerBody = 2;
    static constexpr Real kTetherRatio = 4; // a body this many times the lightest above it is tethered
    struct Tether {
        int root, body;  // solver slots
        Vec3 start, end; // where the chain starts on the root and holds the body (root frames)
        Real length;     // the most the chain allows between the two
        int reach;       // the body's reach (m_reach) this tether follows back up the chain
        JointRow row;    // pulls the body toward start, at length
    };
    // How a chain from its start (JointTethers.cpp) reached a body (kTethersPerBody a body). Points in root
    // frames.
    struct Reach {
        int chain = -1;            // the chain's first joint (m_solvedJoints): -1, not reached
        int root = -1, via = -1;   // the chain's start; the joint from the parent
        int parent = -1;           // the parent's reach, -1 at the root
        int depth = 0;             // joints from the root
        Vec3 start = Vec3::Zero(); // the chain's start on its root
        Vec3 entry = Vec3::Zero(); // where the joint from the parent holds it
        Real length = 0;           // the most the chain allows between start and entry
        Real lightest = 0;         // the largest inverse mass on the chain down to it (it included)
    };
    std::vector<Tether> m_tethers;
    std::vector<Reach> m_reach;  // kTethersPerBody per node
    std::vector<int> m_node;     // per solver slot: its node in the search (-1 between searches)
    std::vector<int> m_nodeSlot; // per node: its solver slot
    std::vector<int> m_jointStart, m_jointList, m_jointCursor, m_reachQueue, m_heavyFirst;
    static constexpr int kProjectionIterations = 4;
    static constexpr int kRestitutionSweeps = 8;
    std::vector<std::pair<size_t, int>> m_bouncing; // (manifold, point) of the points that bounce this step
    // projectDeepOverlaps: each manifold's deepest overlap and when it was measured, each body's last move.
    std::vector<float> m_pairDeepest;
    std::vector<unsigned> m_pairMeasured, m_bodyMoved;
    // Shock propagation: each body's contact distance from the immovable world, the manifolds each body is
    // in, and the manifolds between levels, lowest first, with whether b is the upper body.
    std::vector<int> m_level;
    std::vector<int> m_touchStart, m_touching; // each body's manifolds: m_touching[m_touchStart[i] ..]
    std::vector<int> m_scratch;
    std::vector<char> m_carries, m_keep;
    std::vector<Turned> m_turned; // moveBodies' first pass, for its second
    struct Kinematic {
        size_t slot;
        Vec3 startOrigin, endOrigin;
        Quat startRotation, endRotation;
    };
    std::vector<Kinematic> m_kinematic; // this step's kinematic bodies and their paths
    std::vector<std::pair<size_t, bool>> m_shock;
    // Four per m_shock entry: its points' normal rows, read out of the lanes once a step.
    std::vector<NormalRow> m_shockRows;
    static constexpr Real kHeavyRatio = 10.0f; // shock propagation acts under a body this much heavier
    static constexpr Real kSupportCos = 0.5f;  // ... that rests on it: their normal within 60 degrees of up
    // The soft contact for the current sub-step length: the world's, and a manifold's own (stiffer for a
    // small shape; SolverSettings::restingOverlap).
    struct Softness {
        Real biasRate = 0, massScale = 1, impulseScale = 0;
    };
    static Softness softness(Real omega, Real dampingRatio, Real h);
    Softness contactSoftness(const Manifold& m, Real h) const;
    Softness m_soft;
    Softness m_jointSoft; // the joints' push out
    Real m_omega = 0;
};

} // namespace physics
