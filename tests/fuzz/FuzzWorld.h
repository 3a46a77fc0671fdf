// FuzzWorld.h - one fuzz sequence: a seeded random walk over the public API (creation and deletion of every
// kind of object, attachment, extreme dynamics, updates at any time, and callbacks that delete, clone and
// re-attach), using only what the interface headers allow. Memory errors are for ASan+UBSan to catch.
#pragma once

#include <cstdint>

namespace fuzz {

struct SequenceStats {
    unsigned long calls = 0;     // API calls made, callbacks' included
    unsigned long errors = 0;    // refusals reported with error() (expected: bad values are part of the walk)
    unsigned long steps = 0;     // fixed steps the scenes took
    unsigned long callbacks = 0; // listener, fixed updater and force generator calls
};

// Runs `calls` top-level random API calls from `seed`, then deletes everything left in a random legal order.
// Returns what it did (a crash or a sanitizer report ends the process instead).
SequenceStats runSequence(std::uint64_t seed, int calls);

} // namespace fuzz
