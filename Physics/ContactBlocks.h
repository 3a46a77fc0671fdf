// ContactBlocks.h - the contact solver's hot loop laid out for the cache and for SIMD: a step's manifolds
// packed kLanes to a block (four; eight in an AVX build), one manifold per lane, no two lanes of a block
// sharing a movable body, their rows in structure-of-arrays form; the bodies' velocities in one flat array,
// gathered into lanes for a block and scattered back after it (as Box2D v3's and Jolt's solvers do).
//
// Each lane solves its manifold as a sequential sweep would, operation for operation (Lanes.h; the spins in
// each body's scaled coordinates, BodyFactor), and the packing keeps, for every movable body, the order in
// which its manifolds are solved (pack()): manifolds that share no movable body commute, so the wide sweep
// gives the very bits of the sequential one, at four lanes or eight (the determinism hashes are the same in
// both builds). Immovable bodies (the static world, fixed and kinematic bodies) are read but never written,
// so any number of lanes may share one.
// The rows themselves (directions, arms, effective masses) are worked out by ContactSolver::prepare into
// the lanes pack() gave each manifold, and stay here until the next step's pack() (restitution and shock
// propagation read the normal rows here: normalRow); the impulses live here from pack() to unpack() (the
// sub-steps), then go back to the manifolds for restitution, projection and next step's warm start.
#pragma once

#include "Lanes.h"
#include "SolverData.h"

#include <cstdint>
#include <vector>

namespace physics {

// One constraint row (the normal, or a tangent) of one point slot across the lanes: 10 numbers a lane.
// The angular arms are in each body's scaled spin coordinates (BodyFactor): s = L^T (r x d), where
// L L^T = I^-1. In them an impulse turns the body by s itself, so a row needs no I^-1 (r x d) of its own:
// a row's 16 numbers a lane became 10, a point's 55 became 37 (a block 3,712 -> 2,560 bytes in a four-lane
// build), and the sweeps stream that much less (from memory, at 10,000 bodies).
struct BlockRow {
    Lanes3 dir, armA, armB; // direction, L^T (r x direction) on each body
    Lanes mass;             // effective mass along the row
};

// What the sweeps read and write of a point. Its anchors are apart (BlockAnchors): only measuring the gaps
// reads them, and a sweep streams every block through the cache (at 10,000 bodies, from memory). (The push
// out's normal impulses live in its sweep: ContactBlocks::solve.)
struct BlockPoint {
    BlockRow row[3];  // the normal and the two tangents
    Lanes impulse[3]; // accumulated along the normal and the two tangents
    Lanes maxNormal;  // the most it pushed
    Lanes approach;   // v_n when the solve began
    Lanes gap;        // separation at the sub-step's poses
};

// A block's points' body-local anchors (the normal is row[0].dir).
struct BlockAnchors {
    Lanes3 a[4], b[4];
};

// A body's spin in the sweeps is u = L^-1 w, where L L^T is its world inverse inertia I^-1 (L lower
// triangular, made at pack(): BodyFactor::of): the row speed r x d . w is s . u, with s = L^T (r x d), and
// an impulse p along the row adds s p to u. Restitution and shock propagation, which work on the bodies'
// own w, get r x d = L^-T s and I^-1 (r x d) = L s back (normalRow).
struct BodyFactor {
    Real l00, l10, l11, l20, l21, l22; // L, row by row
    Real r00, r11, r22;                // 1 / its diagonal (0 where it is 0)
    bool turns;                        // movable, with an I^-1 of its own
    static BodyFactor of(const SolverBody& b);
    Vec3 times(const Vec3& u) const;  // L u
    Vec3 solve(const Vec3& w) const;  // L^-1 w
    Vec3 timesT(const Vec3& a) const; // L^T a
    Vec3 solveT(const Vec3& s) const; // L^-T s
};

struct ContactBlock {
    int read[2][kLanes];  // velocity slots of body a and b in each lane
    int write[2][kLanes]; // where they are stored back (a scratch slot for an immovable body or empty lane)
    int manifold[kLanes]; // -1: an empty lane
    int points = 0;       // the most points of any lane
    bool friction = false;
    Lanes invMassA, invMassB, frictionCoefficient, biasRate, massScale, impulseScale;
    // How much a unit impulse along point j's normal row changes point i's normal speed (the normal rows'
    // Delassus matrix, symmetric: 1/m_a + 1/m_b times n_i . n_j plus the arms' products), made with the rows
    // (ContactBlocks::prepare): the sweeps solve the normal rows in their speeds (ContactBlocks::solve).
    Lanes coupling[6], diagonal[4]; // (0,1) (0,2) (0,3) (1,2) (1,3) (2,3); (i,i)
    static int pairIndex(int i, int j) { return i == 0 ? j - 1 : i == 1 ? j + 1 : 5; } // i < j
    const Lanes& couplingOf(int i, int j) const {
        return i == j ? diagonal[i] : coupling[i < j ? pairIndex(i, j) : pairIndex(j, i)];
    }
    BlockPoint p[4];
};

class ContactBlocks {
public:
    // A sub-step's three sweeps (ContactSolver::solve): the velocities; the push out of overlap on top of
    // them (thrown away after the move); and the velocities again at the new poses.
    enum class Pass { Velocity, PushOut, Relax };
    // What a sweep needs of the solver's settings.
    struct Sweep {
        Real h;           // the sub-step
        Pass pass;        // PushOut: overlap pushed out softly (else only approach stopped)
        bool measureGaps; // each point's gap at the bodies' poses first (else the last measured still hold)
        Real touchOverlap, restitutionThreshold, maxPushSpeed;
    };

    // Packs this step's manifolds (their bodies, anchors and impulses), noting each one's block and lane.
    void pack(std::vector<Manifold>& manifolds, const std::vector<SolverBody>& bodies);
    // A manifold's soft contact for this step's sub-step (ContactSolver::contactSoftness), set after pack().
    void setSoftness(const Manifold& m, Real biasRate, Real massScale, Real impulseScale);
    // Every point's rows at the step's start (ContactSolver::prepare, a block at a time): the normal and,
    // with friction, the two tangents; each point keeps its normal row and approach speed too (restitution,
    // shock propagation), and each manifold its load (Manifold::load, at sub-step h).
    void prepare(std::vector<Manifold>& manifolds, const std::vector<SolverBody>& bodies, Real h);
    // The bodies' velocities live in the blocks' flat array through the sub-steps: loaded once after pack()
    // and stored back once after the last sub-step (or around whatever else reads or writes a SolverBody's
    // velocities in between: joints, shock propagation).
    void loadVelocities(const std::vector<SolverBody>& bodies);
    void storeVelocities(std::vector<SolverBody>& bodies) const;
    // A movable body's velocities gain share of what the step's forces add (SolverBody::dv, dw).
    void addForces(const std::vector<SolverBody>& bodies, Real share);
    // Re-applies the accumulated impulses (an impact's only in the first sub-step).
    void warmStart(bool firstSubstep, Real impactSpeed);
    // One sweep: per manifold the normal impulses twice (once in a relax), friction, the normal impulses
    // again (a push out: the normal impulses twice, no friction), each point measured against its gap
    // (measured first, at the bodies' poses, when the sweep says so).
    void solve(const std::vector<SolverBody>& bodies, const Sweep& sweep);
    // The velocities the sub-step solved, kept before the push out and put back after it (the push out's
    // normal impulses are kept apart from the solved ones: BlockPoint::pushed).
    void saveVelocities();
    void restoreVelocities();
    // Body i's velocity now; its velocities as saveVelocities() kept them; how much more it turns now.
    Vec3 velocity(size_t i) const { return vec(m_velocity[i].v); }
    Vec3 savedVelocity(size_t i) const { return vec(m_saved[i].v); }
    Vec3 savedSpin(size_t i) const { return m_factor[i].times(vec(m_saved[i].w)); }
    Vec3 spinSinceSaved(size_t i) const {
        return m_factor[i].times(vec(m_velocity[i].w) - vec(m_saved[i].w));
    }
    // The accumulated normal impulse of a manifold's point (shock propagation adds to it).
    Real normalImpulse(const Manifold& m, int point) const { return at(m).p[point].impulse[0].lane(m.lane); }
    void setNormalImpulse(const Manifold& m, int point, Real value) {
        at(m).p[point].impulse[0].setLane(m.lane, value);
    }
    // A manifold's point's normal row as prepare() made it (restitution and shock propagation use it; kept
    // here rather than copied into every manifold's points, which a step passes over several times).
    NormalRow normalRow(const Manifold& m, int point) const;
    // How much a unit impulse along a manifold's point j's normal changes its point i's normal speed, as
    // prepare() made it (ContactBlock's coupling).
    Real coupling(const Manifold& m, int i, int j) const { return at(m).couplingOf(i, j).lane(m.lane); }
    // A manifold's point's gap as the last sweep that measured gaps found it (ContactBlocks::Sweep).
    Real gap(const Manifold& m, int point) const { return at(m).p[point].gap.lane(m.lane); }
    // The impulses back into the manifolds.
    void unpack(std::vector<Manifold>& manifolds) const;
    size_t blockCount() const { return m_count; }

private:
    const ContactBlock& at(const Manifold& m) const { return m_blocks[size_t(m.block)]; }
    ContactBlock& at(const Manifold& m) { return m_blocks[size_t(m.block)]; }
    int openBlock(int from);             // the first block from this one with a free lane (or the end)
    void openNew(int zero, int scratch); // the next block, every lane empty
    void fill(int block, int lane, Manifold& m, int index, const std::vector<SolverBody>& bodies);
    void loadPoses(const std::vector<SolverBody>& bodies);
    static Vec3 vec(const Real* x) { return Vec3(x[0], x[1], x[2]); }
    static Vec3 laneOf(const Lanes3& v, int lane) {
        return Vec3(v.x.lane(lane), v.y.lane(lane), v.z.lane(lane));
    }
    void measureGaps(ContactBlock& block, const BlockAnchors& anchors) const;
    static void prepareCoupling(ContactBlock& block); // its points' coupling, from their normal rows

    struct alignas(16) Velocity {
        Real v[4], w[4];
    };
    struct alignas(16) Pose {
        Real q[4], origin[4]; // rotation (x, y, z, w) and origin; the static world's is the identity
    };
    std::vector<ContactBlock> m_blocks;  // the first m_count this step's; the rest kept for later steps
    std::vector<BlockAnchors> m_anchors; // per block
    size_t m_count = 0;                  // blocks in use this step
    std::vector<Velocity> m_velocity;    // per solver body, then a zero slot and a scratch slot
    std::vector<Velocity> m_saved;       // m_velocity as saveVelocities() found it
    std::vector<Pose> m_pose;            // per solver body, then the zero slot's identity
    std::vector<BodyFactor> m_factor;    // per solver body, then the zero slot's
    // Packing: each body's last block so far, each block's lanes used, and a skip list to a block with a free
    // lane.
    std::vector<int> m_lastBlock, m_used, m_nextOpen;
};

} // namespace physics
