// iPhysicsSettings.h - the simulator's tunable knobs that a game picks per scene: the integrator.
//
// Set with iPhysicsScene::setIntegrator or the context key GF_PHYS_INTEGRATOR (0 = the default).
#pragma once

enum Integrator : int {           // a fixed type: any int is a value, so a bad one is refused, not undefined
    INTEGRATOR_Default = 0,       // = INTEGRATOR_SemiImplicitEuler
    INTEGRATOR_SemiImplicitEuler, // v += a dt, then x += v dt: symplectic, one force evaluation (default)
    INTEGRATOR_ExplicitEuler,     // x += v dt with the old v: first order, gains energy; for comparison only
    INTEGRATOR_VelocityVerlet,    // second order, symplectic for position-only forces, two force evaluations
    INTEGRATOR_RK4, // classical Runge-Kutta: fourth order, four force evaluations, not symplectic
    INTEGRATOR_Count
};
// Why semi-implicit Euler is the default: it is the usual game choice (Box2D, Bullet, Jolt). It is
// symplectic, so a spring or an orbit keeps its energy bounded instead of blowing up, it costs one force
// evaluation a step, and a contact solver that changes velocities before positions are integrated fits it
// directly. Its error is first order in dt (a projectile lands dt*g*t/2 off); pick Verlet or RK4 when
// trajectories must be exact (both are exact for constant acceleration), at 2x or 4x the force evaluations.
