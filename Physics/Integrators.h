// Integrators.h - advancing one composite body by one fixed step, with the four selectable integrators.
//
// All four share one force evaluation, evaluate(), which takes a trial state so that state-dependent forces
// (drag, force generators) are re-evaluated at every stage: that is what keeps RK4 fourth order and
// velocity Verlet second order. Costs per step: Euler variants 1 evaluation, Verlet 2, RK4 4.
#pragma once

#include "Composite.h"
#include "iPhysicsSettings.h"

namespace physics {

struct Derivative {
    Vec3 acceleration; // dv/dt of C
    Vec3 torque;       // dL/dt about C
    Vec3 omega;        // angular velocity of the state, I_world^-1 L (zero when not asked for and unused)
};

// Forces of the trial state s at time t (s) into the step: gravity, constant forces, drag and generators.
// withOmega false: the caller does not read omega, which is then worked out only when the forces need it
// (drag, generators); the same forces either way.
Derivative evaluate(const Composite& c, const MotionState& s, Real t, bool withOmega = true);

// Advances s by dt. A kinematic composite moves with constant v and w (omega) whatever the integrator.
// turn false leaves the rotation where it was (L still advances): for a body whose velocities do not depend
// on its rotation, and which something else turns (turnsFreely, PhysicsScene::integrateComposite).
void integrate(Integrator which, const Composite& c, MotionState& s, Real dt, const Vec3& kinematicOmega,
               bool turn = true);

// Whether c's rotation changes nothing the forces do to its velocities: one part at the centre of mass, no
// force generator (they read the orientation), and an inertia the same about every axis (R I^-1 R^T = I^-1).
bool rotationIrrelevant(const Composite& c);

// q turned by the rotation vector w * dt (exact exponential map, renormalised).
Quat rotateBy(const Quat& q, const Vec3& omega, Real dt);

} // namespace physics
