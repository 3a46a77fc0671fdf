// ModelSettings.h - the course framework's model constants: time units and frame pacing.
//
// A course project has its own ModelSettings.h; the packages never overwrite it. The physics constants
// (INFINITE_MASS, MIN_MASS, RECIP) live in PhysicsConstants.h, which this file includes: the one line a
// course project adds to its own ModelSettings.h (INTEGRATION.md).
#pragma once

#include "PhysicsConstants.h"

// Engine time is an int in milliseconds: update(int now) receives `now` in these units.
constexpr int UNITS_PER_SEC = 1000;
// The Engine skips a frame when less than this many units have passed since the last one.
constexpr int MIN_ELAPSED_TIME = 1;
