// GrowingArrays.h - working arrays that a step or a call sizes anew, grown geometrically as push_back
// grows them. vector::assign(n, value) and reserve(n) allocate exactly n when n outgrows the storage, so an
// array whose size creeps up (a pile forming, a wave of bodies waking) allocated at every new largest
// size; these allocate a logarithmic number of times (StepAllocation.*). (Physics/GrowingStorage.h is the
// simulator's own copy: the two modules meet only through Interfaces/, and the packages ship apart.)
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace gcol {

// Room for at least n elements: twice the storage when it must grow.
template <class T> void reserveGrowing(std::vector<T>& v, std::size_t n) {
    if (n > v.capacity()) v.reserve(std::max(n, 2 * v.capacity()));
}

// v.assign(n, value), growing the storage as above.
template <class T> void assignGrowing(std::vector<T>& v, std::size_t n, const T& value) {
    reserveGrowing(v, n);
    v.assign(n, value);
}

} // namespace gcol
