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
