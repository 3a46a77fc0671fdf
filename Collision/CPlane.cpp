// CPlane.cpp - the one-sided infinite plane (CreateCPlane): normal and offset in its body's frame, or in
// world space without a body.
#include "CollisionGeometry.h"
#include "iCPlane.h"
#include "iUtilities.h"

#include <cmath>
#include <limits>

namespace {

float largestComponent(const Vector& n) {
    return std::fmax(std::fabs(n.x), std::fmax(std::fabs(n.y), std::fabs(n.z)));
}

bool validPlane(const Vector& n, float offset) {
    return n.isFinite() && largestComponent(n) > 0.0f && std::isfinite(offset);
}

// Scaled by its largest component first, so that neither (0, 1e20, 0) (length squared overflows) nor
// (0, 1e-30, 0) (underflows) loses its direction: both become (0, 1, 0).
Vector unitNormal(const Vector& n) {
    const float m = largestComponent(n); // divided, not multiplied by 1 / m: a denormal m has no reciprocal
    return Vector(n.x / m, n.y / m, n.z / m).normalize();
}

class CPlane final : public GeometryImpl<iCPlane> {
public:
    CPlane(const Vector& n, float offset) : m_normal(unitNormal(n)), m_offset(offset) {}
    iCollisionGeometry* clone() const override {
        auto* c = new CPlane(m_normal, m_offset);
        c->bind(const_cast<CPlane*>(this)->body());
        c->copyFilter(*this);
        c->joinDefaultSpace();
        return c;
    }
    int getCollisionType() const override { return CT_PLANE; }
    float getBoundingRadius() const override { return std::numeric_limits<float>::infinity(); }
    Vector getNormal() const override { return m_normal; }
    float getOffset() const override { return m_offset; }
    void setPlane(const Vector& n, float offset) override {
        if (!validPlane(n, offset)) {
            error(L"iCPlane::setPlane: normal must be non-zero and finite, offset finite; refused");
            return;
        }
        m_normal = unitNormal(n);
        m_offset = offset;
        shapeChanged(); // spaces rebuild it, and what slept on it wakes
    }
    int shapeCount() const override { return 1; }
    void writeWorldShapes(const Vector& origin, const Matrix& r, gcol::WorldShape* out) const override {
        gcol::WorldShape& s = *out;
        s.kind = gcol::ShapeKind::Plane;
        s.plane.normal = r.direction(m_normal).normalize();
        s.plane.offset = m_offset + dot(s.plane.normal, origin);
    }
    // A plane is never sampled on its own account; its size plays no part.
    float minDimension() const override { return std::numeric_limits<float>::infinity(); }
    bool isPlane() const override { return true; }
    void start() { joinDefaultSpace(L"CreateCPlane"); }

private:
    Vector m_normal;
    float m_offset;
};

} // namespace

iCollisionGeometry* CreateCPlane(iRigidBody* rb, const Vector& normal, float offset) {
    if (!validPlane(normal, offset)) {
        error(L"CreateCPlane: normal must be non-zero and finite, offset finite; no geometry created");
        return nullptr;
    }
    auto* p = new CPlane(normal, offset);
    p->attach(rb);
    p->start();
    return p;
}
