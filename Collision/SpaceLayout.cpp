// SpaceLayout.cpp - where a space keeps its entries (SpaceEntry.h) and their world shapes: one entry per
// member in the members' order, each entry's shapes a run of m_shapes, laid out anew when members join or
// leave or when most of m_shapes is runs no entry owns any more.
#include "SimpleCollisionSpace.h"

#include <algorithm>

// Room for n shapes of e at the end of m_shapes: they no longer fit in its own.
void SimpleCollisionSpace::moveToEnd(Entry& e, int n) {
    m_shapeWaste += size_t(e.cache.capacity);
    e.first = int(m_shapes.size());
    e.cache.capacity = n;
    m_shapes.resize(m_shapes.size() + size_t(n));
    if (m_shapeWaste > m_shapes.size() / 2) m_layoutDirty = true; // compacted at the next call
}

// One entry per member, in the members' order: a member that had an entry keeps it (its cache and shapes),
// a new one starts empty. The shapes are packed anew (each entry's room is its shapes, at least one).
void SimpleCollisionSpace::layOutEntries() {
    m_oldEntries.swap(m_entries);
    m_oldShapes.swap(m_shapes);
    m_entries.clear();
    m_shapes.clear();
    m_shapeWaste = 0;
    for (CollisionGeometry* g : m_members) {
        CollisionGeometry::SpaceState& st = g->spaceState();
        const int old = st.entry;
        st.entry = int(m_entries.size());
        if (old >= 0 && size_t(old) < m_oldEntries.size() && m_oldEntries[size_t(old)].g == g) {
            m_entries.push_back(m_oldEntries[size_t(old)]);
            Entry& e = m_entries.back();
            const int first = int(m_shapes.size());
            m_shapes.insert(m_shapes.end(), m_oldShapes.begin() + e.first, m_oldShapes.begin() + e.last);
            e.last = first + (e.last - e.first);
            e.first = first;
            e.cache.capacity = std::max(1, e.last - e.first);
        } else {
            m_entries.emplace_back();
            Entry& e = m_entries.back();
            e.g = g;
            e.plane = g->isPlane();
            e.active = false;
            e.first = e.last = int(m_shapes.size());
            e.cache.capacity = 1;
        }
        m_shapes.resize(size_t(m_entries.back().first + m_entries.back().cache.capacity));
    }
    m_interfaces.resize(m_entries.size());
    for (size_t i = 0; i < m_entries.size(); ++i) m_interfaces[i] = m_entries[i].g->asInterface();
    m_layoutDirty = false;
}
