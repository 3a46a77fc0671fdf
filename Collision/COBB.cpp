// COBB.cpp - the oriented box (CreateCOBB): three half extents about its body frame's origin, turning with
// the body.
#include "BoxAxes.h"
#include "CollisionGeometry.h"
#include "iCOBB.h"
#include "iUtilities.h"

#include <cmath>

namespace {

// Positive and at most MAX_SHAPE_SIZE (PhysicsConstants.h): NaN fails every comparison.
bool validExtents(const Vector& h) {
    auto ok = [](float f) { return f > 0.0f && f <= MAX_SHAPE_SIZE; };
    return ok(h.x) && ok(h.y) && ok(h.z);
}

class COBB final : public GeometryImpl<iCOBB> {
public:
    explicit COBB(const Vector& h) : m_half(h) {}
    iCollisionGeometry* clone() const override {
        auto* c = new COBB(m_half);
        c->bind(const_cast<COBB*>(this)->body());
        c->copyFilter(*this);
        c->joinDefaultSpace();
        return c;
    }
    int getCollisionType() const override { return CT_OBB; }
    float getBoundingRadius() const override { return m_half.length(); }
    Vector getRadius() const override { return m_half; }
    void setRadius(const Vector& h) override {
        if (!validExtents(h)) {
            error(L"iCOBB::setRadius: half extents must be positive and at most MAX_SHAPE_SIZE (1e6 m); "
                  L"refused");
            return;
        }
        m_half = h;
        shapeChanged();
    }
    ShapeMass shapeMass() const override { return boxShapeMass(m_half); }
    int shapeCount() const override { return 1; }
    void writeWorldShapes(const Vector& origin, const Matrix& r, gcol::WorldShape* out) const override {
        gcol::WorldShape& s = *out;
        s.kind = gcol::ShapeKind::Box;
        s.box.halfExtents = m_half;
        // Its axes normalised: the simulator tolerates orientation drift up to 1e-2 before cleaning it.
        gcol::placeAtBody(s, origin, r);
    }
    bool centredOnBody() const override { return true; }
    float minDimension() const override { return 2.0f * std::fmin(m_half.x, std::fmin(m_half.y, m_half.z)); }
    void start() { joinDefaultSpace(L"CreateCOBB"); }

private:
    Vector m_half;
};

} // namespace

iCollisionGeometry* CreateCOBB(iRigidBody* rb, const Vector& radius) {
    if (!validExtents(radius)) {
        error(L"CreateCOBB: half extents must be positive and at most MAX_SHAPE_SIZE (1e6 m); no geometry "
              L"created");
        return nullptr;
    }
    auto* b = new COBB(radius);
    b->attach(rb);
    b->start();
    return b;
}
