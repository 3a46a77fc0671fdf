// DynamicTree.h - a dynamic bounding-volume tree of axis-aligned boxes: the broadphase structure of the
// tree space (TreeBroadphase.h), usable on its own.
//
// Leaves hold a box and an int the caller chooses; inner nodes hold the union of their two children.
// insert picks the sibling by the surface-area heuristic (the cost of the new parent plus the growth it
// causes in every ancestor, as Box2D's and Bullet's trees do), then walks up refitting boxes and applying
// AVL-style rotations where one child is more than one level taller than the other, so the height stays
// O(log n) whatever the insertion order. Node ids are indices into one pool with a free list: after
// warm-up neither insertions nor queries allocate, and the same calls give the same ids (no addresses).
// Not thread-safe: queries share one traversal stack.
#pragma once

#include "Shapes.h"

#include <vector>

namespace gcol {

inline bool overlaps(const Aabb& a, const Aabb& b) {
    return a.min.x <= b.max.x && a.max.x >= b.min.x && a.min.y <= b.max.y && a.max.y >= b.min.y &&
           a.min.z <= b.max.z && a.max.z >= b.min.z;
}

inline bool contains(const Aabb& outer, const Aabb& inner) {
    return outer.min.x <= inner.min.x && outer.min.y <= inner.min.y && outer.min.z <= inner.min.z &&
           inner.max.x <= outer.max.x && inner.max.y <= outer.max.y && inner.max.z <= outer.max.z;
}

// (Plain comparisons, not std::fmin: boxes are finite, and this runs at every level of every insertion.)
inline Aabb unite(const Aabb& a, const Aabb& b) {
    auto lo = [](float x, float y) { return x < y ? x : y; };
    auto hi = [](float x, float y) { return x > y ? x : y; };
    Aabb u;
    u.min = Vector(lo(a.min.x, b.min.x), lo(a.min.y, b.min.y), lo(a.min.z, b.min.z));
    u.max = Vector(hi(a.max.x, b.max.x), hi(a.max.y, b.max.y), hi(a.max.z, b.max.z));
    return u;
}

// The box of shapes (at least one, all bounded).
inline Aabb boundsOf(const std::vector<WorldShape>& shapes) {
    Aabb box;
    shapeAabb(shapes[0], box);
    for (size_t i = 1; i < shapes.size(); ++i) {
        Aabb b;
        shapeAabb(shapes[i], b);
        box = unite(box, b);
    }
    return box;
}

// The segment origin + t * dir, 0 <= t <= maxT (dir need not be unit), ready to be tested against many
// boxes: the reciprocals of dir's components are worked out once.
struct RaySegment {
    RaySegment(const Vector& origin, const Vector& dir, float maxT);
    bool hits(const Aabb& box) const; // whether it meets box (a slab test)
    float origin[3], inverse[3], maxT;
    bool flat[3]; // dir's component is 0: the slab test is whether origin lies within the box on that axis
};
// Whether origin + t * dir meets box for some t in [0, maxT] (RaySegment::hits, for one box).
inline bool rayHitsBox(const Aabb& box, const Vector& origin, const Vector& dir, float maxT) {
    return RaySegment(origin, dir, maxT).hits(box);
}

class DynamicTree {
public:
    static constexpr int kNull = -1;

    // Adds a leaf with box and the caller's value; returns its id. With place = false the leaf waits,
    // outside the tree, for the next rebuild (which must list it).
    int insert(const Aabb& box, int value, bool place = true);
    void remove(int leaf);
    // Gives a leaf a new box (re-inserted where it now fits best); its id stays.
    void move(int leaf, const Aabb& box);
    // Bulk update, for when most leaves moved: give leaves new boxes with setLeafBox (the tree is not valid
    // in between), then rebuild over every leaf, listed in a spatially coherent order (Morton order): a
    // balanced tree of height ceil(log2 n), leaf ids kept, no allocation.
    void setLeafBox(int leaf, const Aabb& box) { m_nodes[size_t(leaf)].box = box; }
    void rebuild(const std::vector<int>& leaves);
    const Aabb& box(int leaf) const { return m_nodes[size_t(leaf)].box; }
    int value(int leaf) const { return m_nodes[size_t(leaf)].value; }

    // visit(value) for every leaf whose box overlaps box.
    template <class Visit> void query(const Aabb& box, Visit&& visit) const;
    // visit(value) for every leaf whose box the segment origin + t * dir, 0 <= t <= maxT, meets.
    template <class Visit>
    void rayCast(const Vector& origin, const Vector& dir, float maxT, Visit&& visit) const;

    int height() const { return m_root == kNull ? 0 : m_nodes[size_t(m_root)].height; }
    int leafCount() const { return m_leaves; }
    // Checks every invariant (parents, heights, boxes, leaf count); for tests.
    bool valid() const;

private:
    struct Node {
        Aabb box;
        int parent = kNull;
        int child1 = kNull, child2 = kNull; // kNull for a leaf
        int height = 0;                     // 0 for a leaf, -1 for a free node
        int value = 0;                      // a leaf's value; the next free node when free
        bool leaf() const { return child1 == kNull; }
    };
    int allocate();
    void release(int node);
    void attach(int leaf);
    void detach(int leaf);
    void refitFrom(int node); // boxes, heights and balance from node up to the root
    int rotate(int node);
    bool validNode(int node, int& leaves) const;
    int build(const int* leaves, int count, int parent);

    std::vector<Node> m_nodes;
    int m_root = kNull;
    int m_free = kNull;
    int m_leaves = 0;
    mutable std::vector<int> m_stack;
    // Depth first from the root into every node whose box enter(box) accepts; visit(value) at its leaves.
    template <class Enter, class Visit> void walk(Enter&& enter, Visit&& visit) const;
};

template <class Enter, class Visit> void DynamicTree::walk(Enter&& enter, Visit&& visit) const {
    if (m_root == kNull) return;
    m_stack.clear();
    m_stack.push_back(m_root);
    while (!m_stack.empty()) {
        const Node& n = m_nodes[size_t(m_stack.back())];
        m_stack.pop_back();
        if (!enter(n.box)) continue;
        if (n.leaf()) {
            visit(n.value);
        } else {
            m_stack.push_back(n.child1);
            m_stack.push_back(n.child2);
        }
    }
}

template <class Visit> void DynamicTree::query(const Aabb& box, Visit&& visit) const {
    walk([&box](const Aabb& node) { return overlaps(node, box); }, visit);
}

template <class Visit>
void DynamicTree::rayCast(const Vector& origin, const Vector& dir, float maxT, Visit&& visit) const {
    const RaySegment segment(origin, dir, maxT);
    walk([&segment](const Aabb& node) { return segment.hits(node); }, visit);
}

} // namespace gcol
