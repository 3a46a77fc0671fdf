// JointClosing.h - the joints of bodies the step moved alone, closed again by moving positions.
//
// Two corrections at the end of a step move one body without the bodies jointed to it: the solver's
// projection out of a deep overlap (ContactRestitution.cpp) and the continuous stage's put-back at a first
// touch (ContinuousStage.h). A ragdoll's hand put back where it touched the floor, while its arm went on,
// parted the wrist by the rest of the step's motion; a wrecking ball's link pushed out of a box parted from
// its neighbours. Each such body is added; close() then walks the joints out from them through movable
// bodies and closes the ones that hold a point together (ball, hinge, fixed; a distance joint beyond its
// length) by positions only: kSweeps Gauss-Seidel sweeps of mass-weighted corrections that turn bodies as
// their inertia allows (a position-based pass, as the push out is a velocity one). A put-back body is held
// where it was put (it must not go back into what it would have passed through), unless the joint joins
// two such; a projected one moves as any other. Velocities are kept; the next step's joint rows take over.
#pragma once

#include <vector>

namespace physics {

class Joint;
class RigidBody;

class JointClosing {
public:
    static constexpr int kSweeps = 16;
    static constexpr float kSlop = 1e-4f; // m: a joint apart by less is left to the solver
    // Joints out from an added body that the walk goes (a 30-segment rope whole; a cloth of ball joints hit
    // in its middle, at most the few thousand bodies within 32 joints, not all of it).
    static constexpr int kDepth = 32;

    // A body this step moved alone (held: put back at a touch, to stay there). A body without joints, or
    // added twice, costs nothing more.
    void add(RigidBody* b, bool held);
    // Closes the joints within kDepth joints of the bodies added since the last call, and forgets them. Costs
    // nothing in a step that added none.
    void close();

private:
    std::vector<RigidBody*> m_bodies; // added, then the movable bodies jointed to them
    std::vector<int> m_depth;         // per body, joints from the nearest added one
    std::vector<Joint*> m_closing;    // the joints close() closes, each once, in the order reached
};

} // namespace physics
