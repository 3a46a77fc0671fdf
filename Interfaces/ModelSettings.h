// ModelSettings.h - constants the modules share: time units, mass limits and tolerances.
#pragma once

#include <limits>

// Engine time is an int in milliseconds: update(int now) receives `now` in these units.
constexpr int UNITS_PER_SEC = 1000;
// The Engine skips a frame when less than this many units have passed since the last one.
constexpr int MIN_ELAPSED_TIME = 1;

// A body with this mass (or any mass >= it) cannot be moved by forces, impulses or contacts.
constexpr float INFINITE_MASS = std::numeric_limits<float>::infinity();
// Masses and distances below these are treated as zero where a reciprocal is taken.
constexpr float MIN_MASS = 1e-10f;
constexpr float MIN_DIST = 1e-10f;
// Reciprocal clamped at zero: 1/x for |x| > MIN_MASS, else 0 (so INFINITE_MASS gives 0 too).
inline float RECIP(float x) { return (x > MIN_MASS || x < -MIN_MASS) ? 1.0f / x : 0.0f; }
constexpr float MAX_COLLISION_TOLERANCE = 1e-6f;
