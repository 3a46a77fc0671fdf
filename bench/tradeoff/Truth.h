// Truth.h - the independently computed answers bench_tradeoff measures the engine against: closed-form
// solutions of each scene's physics, written from the textbook formulas, never from the engine's code.
// Header-only and engine-free (plain doubles), so that a unit test can check each against a hand value.
#pragma once

#include <algorithm>
#include <cmath>

namespace tradeoff {

constexpr double kPi = 3.14159265358979323846;

struct Vec3d {
    double x = 0, y = 0, z = 0;
};

inline double distance(const Vec3d& a, const Vec3d& b) {
    return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

// A projectile in uniform gravity g: x0 + v0 t + g t^2 / 2.
inline Vec3d projectileAt(const Vec3d& x0, const Vec3d& v0, const Vec3d& g, double t) {
    return {x0.x + v0.x * t + 0.5 * g.x * t * t, x0.y + v0.y * t + 0.5 * g.y * t * t,
            x0.z + v0.z * t + 0.5 * g.z * t * t};
}

// A body dropped from rest under gravity g (> 0, downward) and quadratic drag F = 1/2 rho Cd A v^2
// (rho = 1.2 kg/m^3; A the cross-section of the sphere with the body's volume, as RBDynamics documents): how
// far it has fallen after t seconds, vt^2 / g ln cosh(g t / vt) with the terminal speed
// vt = sqrt(2 m g / (rho Cd A)). Cd = 0: g t^2 / 2.
inline double dragFallDistance(double mass, double cd, double area, double g, double t) {
    if (cd <= 0) return 0.5 * g * t * t;
    const double vt = std::sqrt(2.0 * mass * g / (1.2 * cd * area));
    return vt * vt / g * std::log(std::cosh(g * t / vt));
}

// A circular orbit of radius r and period T about centre c in the xy plane, starting at c + (r, 0, 0)
// moving along +y: c + r (cos wt, sin wt, 0), w = 2 pi / T. The inverse-square field that holds it has
// GM = w^2 r^3 (F = -GM m / d^2 toward c); its start speed is w r.
inline Vec3d orbitAt(const Vec3d& c, double r, double period, double t) {
    const double w = 2.0 * kPi / period;
    return {c.x + r * std::cos(w * t), c.y + r * std::sin(w * t), c.z};
}
inline double orbitGM(double r, double period) {
    const double w = 2.0 * kPi / period;
    return w * w * r * r * r;
}

// An undamped spring (stiffness k, mass m) released from rest at displacement a: a cos(sqrt(k / m) t).
inline double springAt(double a, double k, double m, double t) { return a * std::cos(std::sqrt(k / m) * t); }

// A ball dropped from height h onto a floor with (combined) restitution e rises to e^2 h.
inline double reboundHeight(double e, double h) { return e * e * h; }

// A box sliding at v on a level floor with friction coefficient mu stops after v^2 / (2 mu g).
inline double stoppingDistance(double v, double mu, double g) { return v * v / (2.0 * mu * g); }

// A solid sphere launched sliding at v0 with no spin ends rolling at 5/7 v0 (friction's impulse
// reduces v by as much as it spins the ball up: v = v0 - J/m, w r = 5 J / (2 m)), whatever mu.
inline double rollingSpeed(double v0) { return 5.0 / 7.0 * v0; }

// The kinetic energy of rotation of a box of half extents (hx, hy, hz) and mass m spinning at w (body
// axes): the principal moments m/3 (hy^2 + hz^2) and so on.
inline double boxSpinEnergy(double m, double hx, double hy, double hz, const Vec3d& w) {
    const double ix = m / 3.0 * (hy * hy + hz * hz), iy = m / 3.0 * (hx * hx + hz * hz),
                 iz = m / 3.0 * (hx * hx + hy * hy);
    return 0.5 * (ix * w.x * w.x + iy * w.y * w.y + iz * w.z * w.z);
}

// How two bodies' friction or restitution combine into a contact's, as README.md states the engine's
// rules (iContactSettings.h): 0 sum, 1 average, 2 max, 3 min, 4 product, 5 geometric mean.
inline double combine(int rule, double a, double b) {
    switch (rule) {
    case 0:
        return a + b;
    case 1:
        return 0.5 * (a + b);
    case 2:
        return std::max(a, b);
    case 3:
        return std::min(a, b);
    case 4:
        return a * b;
    default:
        return std::sqrt(a * b);
    }
}

} // namespace tradeoff
