// DynamicTree.cpp - insertion by the surface-area heuristic, removal, and the rotations that keep the
// dynamic tree balanced (DynamicTree.h).
#include "DynamicTree.h"

#include <algorithm>
#include <cstdlib>

namespace gcol {

namespace {

float area(const Aabb& b) {
    Vector d = b.max - b.min;
    return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
}

} // namespace

RaySegment::RaySegment(const Vector& o, const Vector& dir, float t) : maxT(t) {
    for (int i = 0; i < 3; ++i) {
        origin[i] = component(o, i);
        const float d = component(dir, i);
        flat[i] = d == 0.0f;
        inverse[i] = flat[i] ? 0.0f : 1.0f / d;
    }
}

bool RaySegment::hits(const Aabb& box) const {
    float lo = 0.0f, hi = maxT;
    for (int i = 0; i < 3; ++i) {
        const float o = origin[i], bmin = component(box.min, i), bmax = component(box.max, i);
        if (flat[i]) {
            if (o < bmin || o > bmax) return false;
            continue;
        }
        float t0 = (bmin - o) * inverse[i], t1 = (bmax - o) * inverse[i];
        if (t0 > t1) std::swap(t0, t1);
        lo = std::fmax(lo, t0);
        hi = std::fmin(hi, t1);
        if (lo > hi) return false;
    }
    return true;
}

int DynamicTree::allocate() {
    if (m_free == kNull) {
        m_nodes.emplace_back();
        return int(m_nodes.size()) - 1;
    }
    int id = m_free;
    m_free = m_nodes[size_t(id)].value;
    m_nodes[size_t(id)] = Node();
    return id;
}

void DynamicTree::release(int node) {
    Node& n = m_nodes[size_t(node)];
    n.height = -1;
    n.child1 = n.child2 = n.parent = kNull;
    n.value = m_free;
    m_free = node;
}

int DynamicTree::insert(const Aabb& box, int value, bool place) {
    int leaf = allocate();
    Node& n = m_nodes[size_t(leaf)];
    n.box = box;
    n.value = value;
    n.height = 0;
    if (place) attach(leaf);
    ++m_leaves;
    return leaf;
}

void DynamicTree::remove(int leaf) {
    detach(leaf);
    release(leaf);
    --m_leaves;
}

void DynamicTree::move(int leaf, const Aabb& box) {
    detach(leaf);
    m_nodes[size_t(leaf)].box = box;
    attach(leaf);
}

void DynamicTree::attach(int leaf) {
    if (m_root == kNull) {
        m_root = leaf;
        m_nodes[size_t(leaf)].parent = kNull;
        return;
    }
    // Walk down to the sibling where the leaf costs least: a new parent above node costs the area of their
    // union, and every ancestor grows by the same union's growth.
    const Aabb leafBox = m_nodes[size_t(leaf)].box;
    int node = m_root;
    while (!m_nodes[size_t(node)].leaf()) {
        const Node& n = m_nodes[size_t(node)];
        const float combined = area(unite(n.box, leafBox));
        const float here = 2.0f * combined;                      // a new parent of node and the leaf
        const float inherited = 2.0f * (combined - area(n.box)); // what going lower adds above
        auto descend = [&](int child) {
            const Node& c = m_nodes[size_t(child)];
            const float grown = area(unite(c.box, leafBox));
            return (c.leaf() ? grown : grown - area(c.box)) + inherited;
        };
        const float cost1 = descend(n.child1), cost2 = descend(n.child2);
        if (here < cost1 && here < cost2) break;
        node = cost1 <= cost2 ? n.child1 : n.child2;
    }
    const int sibling = node;
    const int oldParent = m_nodes[size_t(sibling)].parent;
    const int parent = allocate();
    Node& p = m_nodes[size_t(parent)];
    p.parent = oldParent;
    p.box = unite(m_nodes[size_t(sibling)].box, leafBox);
    p.height = m_nodes[size_t(sibling)].height + 1;
    p.child1 = sibling;
    p.child2 = leaf;
    m_nodes[size_t(sibling)].parent = parent;
    m_nodes[size_t(leaf)].parent = parent;
    if (oldParent == kNull) {
        m_root = parent;
    } else {
        Node& op = m_nodes[size_t(oldParent)];
        (op.child1 == sibling ? op.child1 : op.child2) = parent;
    }
    refitFrom(m_nodes[size_t(leaf)].parent);
}

void DynamicTree::detach(int leaf) {
    if (leaf == m_root) {
        m_root = kNull;
        return;
    }
    const int parent = m_nodes[size_t(leaf)].parent;
    const int grand = m_nodes[size_t(parent)].parent;
    const Node& p = m_nodes[size_t(parent)];
    const int sibling = p.child1 == leaf ? p.child2 : p.child1;
    m_nodes[size_t(sibling)].parent = grand;
    release(parent);
    m_nodes[size_t(leaf)].parent = kNull;
    if (grand == kNull) {
        m_root = sibling;
        return;
    }
    Node& g = m_nodes[size_t(grand)];
    (g.child1 == parent ? g.child1 : g.child2) = sibling;
    refitFrom(grand);
}

void DynamicTree::refitFrom(int node) {
    while (node != kNull) {
        node = rotate(node);
        Node& n = m_nodes[size_t(node)];
        const Node& a = m_nodes[size_t(n.child1)];
        const Node& b = m_nodes[size_t(n.child2)];
        n.height = 1 + std::max(a.height, b.height);
        n.box = unite(a.box, b.box);
        node = n.parent;
    }
}

// When one child of node is more than one level taller, lifts that child into node's place: the taller
// child's taller child stays under it, the shorter one moves under node. Returns the node now in node's
// place.
int DynamicTree::rotate(int node) {
    Node& a = m_nodes[size_t(node)];
    if (a.leaf() || a.height < 2) return node;
    const int balance = m_nodes[size_t(a.child2)].height - m_nodes[size_t(a.child1)].height;
    if (std::abs(balance) <= 1) return node;
    const bool liftSecond = balance > 1;
    const int up = liftSecond ? a.child2 : a.child1;   // the taller child
    const int stay = liftSecond ? a.child1 : a.child2; // the shorter child, stays under node
    Node& u = m_nodes[size_t(up)];
    const int f = u.child1, g = u.child2;
    // up takes node's place.
    u.parent = a.parent;
    a.parent = up;
    if (u.parent == kNull) {
        m_root = up;
    } else {
        Node& pp = m_nodes[size_t(u.parent)];
        (pp.child1 == node ? pp.child1 : pp.child2) = up;
    }
    // up keeps its taller child and takes node as its other child; node gets up's shorter child.
    const bool fTaller = m_nodes[size_t(f)].height > m_nodes[size_t(g)].height;
    const int keep = fTaller ? f : g, give = fTaller ? g : f;
    u.child1 = node;
    u.child2 = keep;
    (liftSecond ? a.child2 : a.child1) = give;
    m_nodes[size_t(give)].parent = node;
    const Node& s = m_nodes[size_t(stay)];
    const Node& gv = m_nodes[size_t(give)];
    a.box = unite(s.box, gv.box);
    a.height = 1 + std::max(s.height, gv.height);
    const Node& k = m_nodes[size_t(keep)];
    u.box = unite(a.box, k.box);
    u.height = 1 + std::max(a.height, k.height);
    return up;
}

void DynamicTree::rebuild(const std::vector<int>& leaves) {
    for (size_t i = 0; i < m_nodes.size(); ++i)
        if (m_nodes[i].height > 0) release(int(i)); // inner nodes: free, reused below
    m_root = leaves.empty() ? kNull : build(leaves.data(), int(leaves.size()), kNull);
}

int DynamicTree::build(const int* leaves, int count, int parent) {
    if (count == 1) {
        m_nodes[size_t(leaves[0])].parent = parent;
        return leaves[0];
    }
    const int node = allocate();
    const int half = count / 2;
    const int c1 = build(leaves, half, node), c2 = build(leaves + half, count - half, node);
    Node& n = m_nodes[size_t(node)];
    n.parent = parent;
    n.child1 = c1;
    n.child2 = c2;
    n.height = 1 + std::max(m_nodes[size_t(c1)].height, m_nodes[size_t(c2)].height);
    n.box = unite(m_nodes[size_t(c1)].box, m_nodes[size_t(c2)].box);
    return node;
}

bool DynamicTree::validNode(int node, int& leaves) const {
    const Node& n = m_nodes[size_t(node)];
    if (n.leaf()) {
        ++leaves;
        return n.height == 0 && n.child2 == kNull;
    }
    const Node& a = m_nodes[size_t(n.child1)];
    const Node& b = m_nodes[size_t(n.child2)];
    if (a.parent != node || b.parent != node) return false;
    if (n.height != 1 + std::max(a.height, b.height)) return false;
    const Aabb u = unite(a.box, b.box);
    if (!(u.min == n.box.min) || !(u.max == n.box.max)) return false;
    return validNode(n.child1, leaves) && validNode(n.child2, leaves);
}

bool DynamicTree::valid() const {
    if (m_root == kNull) return m_leaves == 0;
    if (m_nodes[size_t(m_root)].parent != kNull) return false;
    int leaves = 0;
    return validNode(m_root, leaves) && leaves == m_leaves;
}

} // namespace gcol
