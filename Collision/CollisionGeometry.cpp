// CollisionGeometry.cpp - body binding, the body-lifetime watch and space membership of a geometry.
#include "CollisionGeometry.h"
#include "SimpleCollisionSpace.h"
#include "iRigidBody.h"
#include "iUtilities.h"

#include <string>

CollisionGeometry::CollisionGeometry() { watchRigidBodies(&CollisionGeometry::onBodyDestroyed, this); }

CollisionGeometry::~CollisionGeometry() {
    unwatchRigidBodies(&CollisionGeometry::onBodyDestroyed, this);
    if (m_body) m_body->getDynamics().removeShapeMass(this);
}

void CollisionGeometry::onBodyDestroyed(const iRigidBody* dying, void* self) {
    auto* g = static_cast<CollisionGeometry*>(self);
    if (g->m_body != dying) return;
    g->m_body = nullptr; // the body is going: its dynamics are not touched
    g->m_state.hasPrevious = false;
}

void CollisionGeometry::bind(iRigidBody* rb) {
    if (m_body && m_body != rb) m_body->getDynamics().removeShapeMass(this);
    m_body = rb;
    m_state.hasPrevious = false;
    shapeChanged();
}

void CollisionGeometry::shapeChanged() {
    ++m_shapeVersion;
    if (m_body) m_body->getDynamics().setShapeMass(this, shapeMass());
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
