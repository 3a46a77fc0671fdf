// Prefetch.h - asking for memory a loop will read soon to be brought into the cache: for the passes over
// bodies that lie apart in memory, in an order no hardware prefetcher guesses (each body's lines asked for
// a few bodies ahead arrive while the bodies before it are worked on). A hint: it never faults and changes
// no result, and it does nothing where the compiler has no such builtin.
#pragma once

#include <cstddef>

namespace physics {

// The cache lines of [p, p + bytes); nothing for a null p (an offset from it is undefined, and a caller
// asking ahead may meet one: a game's space can list a contact without its geometry).
inline void prefetchLines(const void* p, std::size_t bytes) {
#if defined(__GNUC__) || defined(__clang__)
    if (!p) return;
    const char* at = static_cast<const char*>(p);
    for (std::size_t offset = 0; offset < bytes; offset += 64) __builtin_prefetch(at + offset);
#else
    (void)p;
    (void)bytes;
#endif
}

} // namespace physics
