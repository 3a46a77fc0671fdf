// FetchAhead.h - asking for memory a loop of the space will read soon: a pass over the members reaches each
// geometry's own record, its body and its dynamics, which lie apart in memory in an order no hardware
// prefetcher guesses, and the pair tests reach the entries and shapes of pairs in the broadphase's order.
// A hint: it never faults and changes no result, and it does nothing where the compiler has no such builtin.
#pragma once

#include <cstddef>

namespace gcol {

// The cache lines of [p, p + bytes) (p's line when bytes is 0).
inline void fetchAhead(const void* p, std::size_t bytes = 0) {
#if defined(__GNUC__) || defined(__clang__)
    const char* at = static_cast<const char*>(p);
    __builtin_prefetch(at);
    for (std::size_t offset = 64; offset < bytes; offset += 64) __builtin_prefetch(at + offset);
    if (bytes > 1) __builtin_prefetch(at + bytes - 1);
#else
    (void)p;
    (void)bytes;
#endif
}

} // namespace gcol
