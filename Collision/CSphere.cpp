// CSphere.cpp - the collision sphere (CreateCSphere): one radius about its body frame's origin.
#include "BoxAxes.h"
#include "CollisionGeometry.h"
#include "iCSphere.h"
#include "iUtilities.h"

#include <cmath>

namespace {

bool validRadius(float r) { return r > 0.0f && r <= MAX_SHAPE_SIZE; } // NaN fails both

class CSphere final : public GeometryImpl<iCSphere> {
public:
    explicit CSphere(float radius) : m_radius(radius) {}
    iCollisionGeometry* clone() const override {
        auto* c = new CSphere(m_radius);
        c->bind(const_cast<CSphere*>(this)->body());
        c->copyFilter(*this);
        c->joinDefaultSpace();
        return c;
    }
    int getCollisionType() const override { return CT_SPHERE; }
    float getBoundingRadius() const override { return m_radius; }
    float getRadius() const override { return m_radius; }
    void setRadius(float radius) override {
        if (!validRadius(radius)) {
            error(
                L"iCSphere::setRadius: radius must be positive and at most MAX_SHAPE_SIZE (1e6 m); refused");
            return;
        }
        m_radius = radius;
        shapeChanged();
    }
    ShapeMass shapeMass() const override { return sphereShapeMass(m_radius); }
    int shapeCount() const override { return 1; }
    void writeWorldShapes(const Vector& origin, const Matrix& r, gcol::WorldShape* out) const override {
        gcol::WorldShape& s = *out;
        s.kind = gcol::ShapeKind::Sphere;
        s.sphere.radius = m_radius;
        gcol::placeAtBody(s, origin, r);
    }
    bool centredOnBody() const override { return true; }
    float minDimension() const override { return 2.0f * m_radius; }
    void start() { joinDefaultSpace(L"CreateCSphere"); }

private:
    float m_radius;
};

} // namespace

iCollisionGeometry* CreateCSphere(iRigidBody* rb, float radius) {
    if (!validRadius(radius)) {
        error(L"CreateCSphere: radius must be positive and at most MAX_SHAPE_SIZE (1e6 m); no geometry "
              L"created");
        return nullptr;
    }
    auto* s = new CSphere(radius);
    s->attach(rb);
    s->start();
    return s;
}
