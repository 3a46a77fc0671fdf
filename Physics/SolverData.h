// SolverData.h - the solver's working data: a body's velocity state and frames, a contact point of a manifold
// (ManifoldPoint) with its accumulated impulses, and a manifold of up to four points between two geometries.
#pragma once

#include "MathBridge.h"

#include <cmath>
#include <cstddef>
#include <cstdint>

class iCollisionGeometry;
struct RBDynamics;

namespace physics {

// A body as the solver sees it: velocities about its (composite) centre of mass and its inverse mass
// properties in world axes. Immovable bodies (fixed, infinite mass) have zero inverses but keep their
// velocity, so a moving kinematic body pushes what it touches.
struct SolverBody {
    RBDynamics* root = nullptr;
    // The root's frame when the contacts were found: contact anchors are measured in it.
    Vec3 startOrigin = Vec3::Zero();
    Quat startRotation = Quat::Identity();
    // The root's frame now. A movable body starts the solve at its start frame and moves with each sub-step;
    // an immovable one stays where the step put it (a kinematic body moved by its velocity).
    Vec3 origin = Vec3::Zero();
    Quat rotation = Quat::Identity();
    Vec3 com = Vec3::Zero(); // world centre of mass, at the step's start on loading
    Vec3 v = Vec3::Zero();   // velocities after this step's forces, on loading
    Vec3 w = Vec3::Zero();
    // What this step's forces added to v and w: the sub-steps add it a share at a time.
    Vec3 dv = Vec3::Zero(), dw = Vec3::Zero();
    Real invMass = 0;
    Mat3 invInertia = Mat3::Zero();
    // Projected out of a deep overlap this step: a correction, not motion, so a collision space must not
    // sweep along it (the pose is stored as a teleport, RBDynamics::teleports); the move it made.
    bool projected = false;
    Vec3 projection = Vec3::Zero();
    int slot = -1; // its index in the solver's bodies (what a body access keeps per body is kept by it)
};

struct ManifoldPoint {
    Vec3 normal = Vec3::UnitY();                         // from body a toward body b
    Vec3 anchorA = Vec3::Zero(), anchorB = Vec3::Zero(); // the touching surface points, in each root's frame
    Vec3 point = Vec3::Zero(); // the contact point (world) at the step's start, midway between the two
    float depth = 0;           // overlap as the detector reported it (the four deepest are kept)
    // (Its rows - the normal and the tangents, which tangentBasis makes from the normal: arms, turns,
    // effective masses - are the contact blocks', from the solve's start to the next step's:
    // ContactBlocks::normalRow.)
    Real normalImpulse = 0, tangentImpulse[2] = {0, 0}; // accumulated, per sub-step
    Real approachSpeed = 0;    // v_n when the solve began (negative: approaching), for restitution
    Real forceSpeed = 0;       // what this step's forces added to v_n (a_n dt)
    Real touchSpeed2 = 0;      // v_n^2 at the moment the point touched (the energy a bounce returns)
    Real maxNormalImpulse = 0; // over the sub-steps: a point that never pushed does not bounce
    Real gap = 0;              // separation at the solve's end (the last relax sweep measured it there)
    bool bounced = false;      // it bounced: it left the surface and is not kept next step
};

struct Manifold {
    const iCollisionGeometry* g1 = nullptr;
    const iCollisionGeometry* g2 = nullptr;
    int a = -1, b = -1;                            // indices into the solver's bodies; a is g1's root
    RBDynamics *rootA = nullptr, *rootB = nullptr; // the bodies (nullptr: the static world)
    int age = 0; // steps since the detector last reported the pair (a kept manifold lives one step)
    // Carried unsolved while both bodies rest (asleep or fixed): an island that wakes starts from its
    // impulses, as it would have had it stayed awake.
    bool dormant = false;
    Real friction = 0, restitution = 0;
    // The smaller shape's bounding radius (infinite for two planes' worth): what a resting overlap is
    // measured against (SolverSettings::restingOverlap). Known when the pair is reported, kept with it.
    Real size = 0;
    bool bounces = false; // a point bounces this step: its overlap is projected out entirely
    Real projectable = 0; // how much further its overlap may still be projected out this step
    // The most any point carried last step per unit of its effective mass (normalImpulse / (h m_eff) over
    // the points with a mass; lowest() with none), found with the rows (ContactSolver::contactSoftness).
    Real load = 0;
    int count = 0;
    ManifoldPoint points[4];
    int block = -1, lane = 0; // where the solver's wide rows hold it during a solve (ContactBlocks.h)
    int previous = -1;        // last step's manifold of the pair (ContactSolver's m_last), while collecting
};

// A point's row along its normal, as the contact blocks hold it (ContactBlocks::normalRow): r x n on each
// body, I^-1 (r x n) (how an impulse along n turns each body), and the effective mass along n.
struct NormalRow {
    Vec3 armA, armB, turnA, turnB;
    Real mass;
};

struct PairKey {
    const iCollisionGeometry* g1;
    const iCollisionGeometry* g2;
    bool operator==(const PairKey& o) const { return g1 == o.g1 && g2 == o.g2; }
};
struct PairKeyHash {
    size_t operator()(const PairKey& k) const {
        // Addresses are aligned (low bits alike): mix them, as FlatMap's open addressing needs.
        std::uint64_t x = std::uint64_t(reinterpret_cast<std::uintptr_t>(k.g1)) * 0x9e3779b97f4a7c15ull ^
                          std::uint64_t(reinterpret_cast<std::uintptr_t>(k.g2));
        x ^= x >> 29;
        x *= 0xbf58476d1ce4e5b9ull;
        x ^= x >> 32;
        return size_t(x);
    }
};

// A tangent basis that depends on the normal alone, so last step's friction impulses still apply.
inline void tangentBasis(const Vec3& n, Vec3 t[2]) {
    Vec3 axis = std::fabs(n.x()) < 0.57f ? Vec3::UnitX() : Vec3::UnitY();
    t[0] = n.cross(axis).normalized();
    t[1] = n.cross(t[0]);
}

} // namespace physics
