// FlatMapTest.cpp - the step's hash map (Physics/FlatMap.h) against std::map, the brute-force reference:
// random inserts, erases, finds and clears with a fixed seed, with a hash that sends many keys to the same
// few slots (long runs that wrap round the table, where backward-shift deletion must move the right keys).
#include "FlatMap.h"

#include <gtest/gtest.h>

#include <map>
#include <random>

namespace {

struct Crowded { // eight homes for every key, the table's last eight slots: long runs that wrap round
    size_t operator()(int k) const { return ~size_t(k % 8); }
};
struct Spread {
    size_t operator()(int k) const { return size_t(k) * 2654435761u; }
};

template <class Hash> void compareWithMap(unsigned seed) {
    physics::FlatMap<int, int, Hash> map;
    std::map<int, int> reference;
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> key(0, 199), op(0, 99);
    for (int step = 0; step < 20000; ++step) {
        const int k = key(rng), o = op(rng);
        if (o < 45) {
            const bool inserted = map.emplace(k, step).second;
            EXPECT_EQ(inserted, reference.emplace(k, step).second) << step;
        } else if (o < 90) {
            EXPECT_EQ(map.erase(k), reference.erase(k) == 1) << step;
        } else if (o == 99) {
            map.clear();
            reference.clear();
        }
        ASSERT_EQ(map.size(), reference.size()) << step;
        if (step % 97 == 0 || o >= 45)
            for (int q = 0; q < 200; ++q) { // every key of the universe, present or not
                const int* found = map.find(q);
                const auto it = reference.find(q);
                ASSERT_EQ(found != nullptr, it != reference.end()) << "step " << step << " key " << q;
                if (found) {
                    ASSERT_EQ(*found, it->second) << "step " << step << " key " << q;
                }
            }
    }
}

} // namespace

TEST(FlatMap, EraseKeepsEveryOtherKeyFindableUnderHeavyCollisions) { compareWithMap<Crowded>(11); }

TEST(FlatMap, InsertEraseFindAndClearAgreeWithStdMap) { compareWithMap<Spread>(12); }
