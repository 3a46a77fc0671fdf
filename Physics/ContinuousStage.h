// ContinuousStage.h - the step's continuous collision stage: a body that moved far enough this step to pass
// through something is put back where its motion first touched it, so that it never tunnels.
//
// Runs after the contact solve, on the poses the step ended with (Box2D v3's time-of-impact pass; its
// speculative contacts are what our soft-contact solver does for points already found). For every awake
// movable root it asks the collision space (iShapeCast.h) where along start pose -> end pose its geometry
// first touched another body's geometry (moving along that body's own motion if it is swept too, else at
// its end pose); on a hit it moves the body back there (a hair into the contact), keeping its velocity, and
// hands it to the step's JointClosing, held there (its joints' partners follow it).
// The next step finds that contact at its starting pose and resolves it like any other: restitution,
// friction, the pair's masses. The remaining time of the step is lost, as in Box2D. The step's start pose is
// taken after the game's edits, so a teleport is never swept. A space without iShapeCast gets no continuous
// stage.
#pragma once

#include "iShapeCast.h"

#include <cstddef>
#include <vector>

namespace physics {

class JointClosing;
class RigidBody;

class ContinuousStage {
public:
    // Sweeps the awake movable unattached bodies' motion of this step in the space's shape cast (nullptr:
    // none); returns how many were put back.
    size_t run(const std::vector<RigidBody*>& bodies, iShapeCast* cast, JointClosing& closing);

private:
    std::vector<BodySweep> m_sweeps; // scratch, reused: a step allocates nothing after warm-up
    std::vector<RigidBody*> m_owners;
};

} // namespace physics
