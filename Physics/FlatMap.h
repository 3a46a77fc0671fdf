// FlatMap.h - the step's lookup tables (body -> solver index, geometry pair -> manifold, ...): a hash map
// with open addressing in one array that keeps its storage when cleared, so that a warm scene's step does not
// touch the heap. clear() is O(1) (a generation stamp). No iteration, so nothing can depend on the order in
// which the keys' addresses hash. A power-of-two table: no division per lookup (std::unordered_map takes the
// hash modulo a prime).
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace physics {

// Default hashing: a pointer's bits mixed (allocators align, so the low bits carry little).
template <class Key> struct FlatHash {
    size_t operator()(Key k) const {
        std::uint64_t x = std::uint64_t(reinterpret_cast<std::uintptr_t>(k));
        x ^= x >> 29;
        x *= 0xbf58476d1ce4e5b9ull;
        x ^= x >> 32;
        return size_t(x);
    }
};

template <class Key, class Value, class Hash = FlatHash<Key>> class FlatMap {
public:
    // Forgets every key; the storage stays.
    void clear() {
        m_size = 0;
        if (++m_generation == 0) { // wrapped: stamps from long ago would look current
            for (Slot& s : m_slots) s.stamp = 0;
            m_generation = 1;
        }
    }
    size_t size() const { return m_size; }

    Value* find(const Key& key) {
        if (m_slots.empty()) return nullptr;
        for (size_t i = Hash()(key) & mask();; i = (i + 1) & mask()) {
            Slot& s = m_slots[i];
            if (s.stamp != m_generation) return nullptr;
            if (s.key == key) return &s.value;
        }
    }
    const Value* find(const Key& key) const { return const_cast<FlatMap*>(this)->find(key); }

    // Inserts (key, value) unless key is present; returns the stored value and whether it was inserted.
    std::pair<Value*, bool> emplace(const Key& key, const Value& value) {
        if ((m_size + 1) * 4 > m_slots.size() * 3) grow();
        for (size_t i = Hash()(key) & mask();; i = (i + 1) & mask()) {
            Slot& s = m_slots[i];
            if (s.stamp != m_generation) {
                s.stamp = m_generation;
                s.key = key;
                s.value = value;
                ++m_size;
                return {&s.value, true};
            }
            if (s.key == key) return {&s.value, false};
        }
    }
    // The value stored under key, inserted as Value() when absent.
    Value& operator[](const Key& key) { return *emplace(key, Value()).first; }

    // Removes key, if present. The keys after it in its run of used slots move back into the hole unless
    // their own slot lies between the hole and where they are (backward-shift deletion): every other key is
    // still found from its slot without gaps, and no tombstones accumulate.
    bool erase(const Key& key) {
        if (m_slots.empty()) return false;
        size_t hole = Hash()(key) & mask();
        for (;; hole = (hole + 1) & mask()) {
            if (m_slots[hole].stamp != m_generation) return false;
            if (m_slots[hole].key == key) break;
        }
        for (size_t j = (hole + 1) & mask(); m_slots[j].stamp == m_generation; j = (j + 1) & mask()) {
            const size_t home = Hash()(m_slots[j].key) & mask();
            const bool stays = hole <= j ? (hole < home && home <= j) : (hole < home || home <= j);
            if (stays) continue;
            m_slots[hole] = m_slots[j];
            hole = j;
        }
        m_slots[hole].stamp = 0; // (never a generation)
        --m_size;
        return true;
    }

    void swap(FlatMap& other) noexcept {
        m_slots.swap(other.m_slots);
        std::swap(m_size, other.m_size);
        std::swap(m_generation, other.m_generation);
    }

private:
    struct Slot {
        unsigned stamp = 0; // == m_generation: in use
        Key key{};
        Value value{};
    };
    size_t mask() const { return m_slots.size() - 1; }
    // Doubles the table (at least 16 slots) and re-inserts what is in use.
    void grow() {
        std::vector<Slot> old;
        old.swap(m_slots);
        const unsigned oldGeneration = m_generation;
        m_slots.assign(old.empty() ? 16 : old.size() * 2, Slot());
        m_generation = 1;
        m_size = 0;
        for (Slot& s : old)
            if (s.stamp == oldGeneration) emplace(s.key, s.value);
    }

    std::vector<Slot> m_slots;
    size_t m_size = 0;
    unsigned m_generation = 1;
};

} // namespace physics
