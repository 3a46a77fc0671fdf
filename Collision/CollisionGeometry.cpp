// CollisionGeometry.cpp - body binding, the body-lifetime watch (one index of bound geometry for all) and
// space membership of a geometry.
#include "CollisionGeometry.h"
#include "SimpleCollisionSpace.h"
#include "iRigidBody.h"
#include "iUtilities.h"

#include <string>
#include <unordered_map>

namespace {

// Which geometries are bound to which body. One watcher for all geometry: a dying body finds just its own
// geometries, so deleting N bodies costs O(N) rather than O(N x geometries) (a watcher per geometry did).
class GeometryBodyIndex {
public:
    GeometryBodyIndex() { watchRigidBodies(&GeometryBodyIndex::onBodyDestroyed, this); }
    void add(const iRigidBody* b, CollisionGeometry* g) {
        if (b) m_bound.emplace(b, g);
    }
    void remove(const iRigidBody* b, const CollisionGeometry* g) {
        if (!b) return;
        const auto range = m_bound.equal_range(b);
        for (auto it = range.first; it != range.second; ++it)
            if (it->second == g) {
                m_bound.erase(it);
                return;
            }
    }

private:
    static void onBodyDestroyed(const iRigidBody* dying, void* self) {
        auto& bound = static_cast<GeometryBodyIndex*>(self)->m_bound;
        const auto range = bound.equal_range(dying);
        for (auto it = range.first; it != range.second; ++it) CollisionGeometry::bodyDestroyed(*it->second);
        bound.erase(range.first, range.second);
    }
    std::unordered_multimap<const iRigidBody*, CollisionGeometry*> m_bound;
};

// Never destroyed: a geometry with static storage duration may outlive any other static.
GeometryBodyIndex& geometryBodyIndex() {
    static auto* index = new GeometryBodyIndex;
    return *index;
}

} // namespace

CollisionGeometry::~CollisionGeometry() {
    if (m_body) {
        geometryBodyIndex().remove(m_body, this);
        m_body->getDynamics().removeShapeMass(this);
    }
}

void CollisionGeometry::bodyDestroyed(CollisionGeometry& g) {
    g.m_body = nullptr; // the body is going: its dynamics are not touched
    g.m_state.hasPrevious = false;
    g.edited();
}

void CollisionGeometry::bind(iRigidBody* rb) {
    if (m_body != rb) {
        if (m_body) m_body->getDynamics().removeShapeMass(this);
        geometryBodyIndex().remove(m_body, this);
        geometryBodyIndex().add(rb, this);
    }
    m_body = rb;
    m_state.hasPrevious = false;
    shapeChanged();
}

void CollisionGeometry::shapeChanged() {
    ++m_shapeVersion;
    if (m_body) m_body->getDynamics().setShapeMass(this, shapeMass());
    edited();
}

void CollisionGeometry::edited() {
    // (Found through the space rather than kept in the space state: eight bytes more there made a box
    // geometry five cache lines instead of four.)
    if (auto* s = dynamic_cast<SimpleCollisionSpace*>(m_space)) s->geometryEdited(*this);
}

void CollisionGeometry::joinDefaultSpace(const wchar_t* factory) {
    if (iCollisionSpace* s = getDefaultCollisionSpace()) {
        s->add(asInterface());
    } else if (factory) { // the seed's order is scene, space, geometry: a geometry in no space never collides
        std::wstring msg = std::wstring(factory) +
                           L": no default collision space is set, so this geometry collides with nothing; "
                           L"set the space first (setNewGlobalCollisionSpace) or add it with space->add()";
        error(msg.c_str());
    }
}

bool CollisionGeometry::currentPose(Vector& origin, Matrix& rotation) const {
    if (!m_body) {
        origin = Vector();
        rotation = Matrix(1);
        return true;
    }
    const RBDynamics& d = m_body->getDynamics();
    Vector o = d.getWorldOrigin();
    Matrix r = d.getWorldOrientation().rotation();
    if (!o.isFinite() || !r.isFinite()) return false;
    origin = o;
    rotation = r;
    return true;
}

void CollisionGeometry::destroy() const {
    auto* self = const_cast<CollisionGeometry*>(this);
    if (auto* s = dynamic_cast<SimpleCollisionSpace*>(m_space)) {
        if (s->deferDelete(self)) return; // the space deletes it once its listeners are done
    }
    if (m_space) m_space->remove(self->asInterface());
    delete this;
}
