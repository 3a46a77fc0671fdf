// PhysicsConstants.h - the constants the engine's public API speaks in: infinite mass and the reciprocal
// that treats tiny masses as zero.
//
// The seed tells games to take INFINITE_MASS from ModelSettings.h. A course project's ModelSettings.h is its
// own, so the package does not overwrite it: add `#include "PhysicsConstants.h"` to it (INTEGRATION.md).
#pragma once

#include <limits>

// A body with this mass (or any mass >= it) cannot be moved by forces, impulses or contacts.
constexpr float INFINITE_MASS = std::numeric_limits<float>::infinity();
// Masses below this are treated as zero where a reciprocal is taken.
constexpr float MIN_MASS = 1e-10f;
// Reciprocal clamped at zero: 1/x for |x| > MIN_MASS, else 0 (so INFINITE_MASS gives 0 too).
inline float RECIP(float x) { return (x > MIN_MASS || x < -MIN_MASS) ? 1.0f / x : 0.0f; }
// The largest sphere radius, box half extent or compound child offset (m) a collision geometry accepts; a
// larger one is refused with error(). Shape sizes are squared and cubed (volume 8 h^3, inertia h^2 per kg,
// squared distances between corners): 1e6 m keeps those within 1e19 and leaves float headroom of 1e19 for
// positions and masses, so no narrowphase product overflows for any scene within a thousand kilometres.
// (A half extent of 3e38 made the box-box test read the axis at index -1.)
constexpr float MAX_SHAPE_SIZE = 1e6f;
