// ContactManifold.h - the solver's working data: a body's velocity state, a contact point with its
// accumulated impulses, and a manifold of up to four points between two geometries.
#pragma once

#include "MathBridge.h"

#include <cstddef>
#include <functional>

class iCollisionGeometry;
struct RBDynamics;

namespace physics {

// A body as the solver sees it: velocities about its (composite) centre of mass and its inverse mass
// properties in world axes. Immovable bodies (fixed, infinite mass) have zero inverses but keep their
// velocity, so a moving kinematic body pushes what it touches.
struct SolverBody {
    RBDynamics* root = nullptr;
    Vec3 com = Vec3::Zero();
    Vec3 v = Vec3::Zero();
    Vec3 w = Vec3::Zero();
    float invMass = 0;
    Mat3 invInertia = Mat3::Zero();
    bool settling = false; // still overlapping beyond the slop after position correction: not at rest yet
};

struct ContactPoint {
    Vec3 normal = Vec3::UnitY();                         // from body a toward body b
    Vec3 tangent[2] = {Vec3::UnitX(), Vec3::UnitZ()};    // a fixed basis derived from the normal
    Vec3 anchorA = Vec3::Zero(), anchorB = Vec3::Zero(); // the touching surface points, in each root's frame
    Vec3 rA = Vec3::Zero(), rB = Vec3::Zero();           // from each centre of mass to the contact (world)
    float depth = 0; // overlap; negative for a point kept from last step that has since come apart
    float normalMass = 0, tangentMass[2] = {0, 0};
    float normalImpulse = 0, tangentImpulse[2] = {0, 0}; // accumulated over the step
    float target =
        0; // the v_n to reach: the bounce speed, or -gap/dt for a kept point (it may close the gap)
};

struct Manifold {
    const iCollisionGeometry* g1 = nullptr;
    const iCollisionGeometry* g2 = nullptr;
    int a = -1, b = -1;                            // indices into the solver's bodies; a is g1's root
    RBDynamics *rootA = nullptr, *rootB = nullptr; // the bodies (nullptr: the static world)
    int age = 0; // steps since the detector last reported the pair (a kept manifold lives one step)
    float friction = 0, restitution = 0;
    int count = 0;
    ContactPoint points[4];
};

struct PairKey {
    const iCollisionGeometry* g1;
    const iCollisionGeometry* g2;
    bool operator==(const PairKey& o) const { return g1 == o.g1 && g2 == o.g2; }
};
struct PairKeyHash {
    size_t operator()(const PairKey& k) const {
        return std::hash<const void*>()(k.g1) * 31u ^ std::hash<const void*>()(k.g2);
    }
};

} // namespace physics
