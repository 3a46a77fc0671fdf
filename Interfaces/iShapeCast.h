// iShapeCast.h - time of impact of moving bodies' geometry against the rest of a collision space: what the
// simulator's continuous stage asks so that a fast body stops at what it hits instead of passing through.
//
// Not part of the seed's iCollisionSpace (a game's own space need not implement it); the simple space
// does, reached with castOf(space). The simulator moves bodies, then asks where along that motion each one
// first touched something; the space knows the shapes, the simulator the motion.
#pragma once

#include <cstddef>

#include "MathDeclarations.h"
#include "iCollisionSpace.h"

class iRigidBody;
class iCollisionGeometry;

// One body's motion over a step: from (startPosition, startOrientation) to its current pose. body is an
// attachment root: the geometry of every body attached to it moves with it.
struct BodySweep {
    const iRigidBody* body = nullptr;
    Vector startPosition;                // its centre of mass at the start (world)
    Matrix startOrientation = Matrix(1); // row-vector rotation (local -> world) at the start
    // Filled in by sweepBodies:
    float fraction = 1.0f;             // where along the motion to stop it (1: it hit nothing)
    iCollisionGeometry* hit = nullptr; // what it hit (nullptr: nothing)
    // How far what it hit moves away from the touch after it (along the touch's normal, over the rest of
    // the motion or up to where its own sweep stops it): the body put back at the touch and moved by this
    // still touches it where that ends up. Zero for a fixed obstacle.
    Vector carried;
};

class iShapeCast {
public:
    // For each sweep whose geometry moved far enough to pass through something (more than a quarter of its
    // smallest dimension), finds the first fraction of the motion at which it touches the geometry of another
    // body (or a bodiless plane), and sets fraction a hair past it, so that the pair overlaps by a fraction
    // of a millimetre there and contact detection at that pose reports it. Positions are interpolated
    // linearly (the centre of mass), orientations by slerp. The other geometry is at its current pose, or,
    // when its body is swept too, moves along that body's translation (its turn is not swept). Pairs
    // overlapping at the start, or touching without closing fast, are left to contact resolution. Other
    // sweeps keep fraction = 1. Returns how many hit.
    virtual size_t sweepBodies(BodySweep* sweeps, size_t count) = 0;

protected:
    ~iShapeCast() = default; // part of a space: Delete() the space
};

// The shape cast of a space that answers it (the simple space); nullptr for one that does not. A cross-cast
// to this public interface, not to the space's class: any implementation may provide it.
inline iShapeCast* castOf(iCollisionSpace* space) { return dynamic_cast<iShapeCast*>(space); }
