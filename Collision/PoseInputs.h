// PoseInputs.h - what the pose of a body without a parent is made of: its position, its centre of mass and
// the rotation rows of its orientation (RBDynamics::getWorldOrigin, getWorldOrientation use nothing else).
// The same inputs, bit for bit, give the same pose, so a cache keyed on them knows a pose unchanged without
// working it out: a space's entries (SpaceGather.cpp) and the octree's query checks (TreeBroadphase.cpp).
#pragma once

#include "RBDynamics.h"

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace gcol {

// Bit for bit (so -0 is not 0, and equal bits are equal values), N floats: eight bytes at a time, without a
// copy or a call (a space compares a few of these a geometry every call).
template <size_t N> bool sameWords(const void* a, const void* b) {
    const unsigned char *p = static_cast<const unsigned char*>(a), *q = static_cast<const unsigned char*>(b);
    std::uint64_t diff = 0;
    for (size_t i = 0; i < N / 2; ++i) {
        std::uint64_t x, y;
        std::memcpy(&x, p + 8 * i, 8);
        std::memcpy(&y, q + 8 * i, 8);
        diff |= x ^ y;
    }
    if (N % 2) {
        std::uint32_t x, y;
        std::memcpy(&x, p + 4 * (N - 1), 4);
        std::memcpy(&y, q + 4 * (N - 1), 4);
        diff |= x ^ y;
    }
    return diff == 0;
}

struct PoseInputs {
    Vector position, com, rows[3];

    void store(const RBDynamics& d) {
        position = d.position;
        com = d.com;
        for (int i = 0; i < 3; ++i) rows[i] = Vector(row(d, i)[0], row(d, i)[1], row(d, i)[2]);
    }
    // d's inputs are these, bit for bit (whether d has a parent is the caller's to know).
    bool same(const RBDynamics& d) const {
        return sameWords<3>(&position, &d.position) && sameWords<3>(&com, &d.com) &&
               sameWords<3>(&rows[0], row(d, 0)) && sameWords<3>(&rows[1], row(d, 1)) &&
               sameWords<3>(&rows[2], row(d, 2));
    }

private:
    static const float* row(const RBDynamics& d, int i) { return d.orientation.data() + 4 * i; }
};

} // namespace gcol
