// CCompound.cpp - compound geometry (CreateCCompound): spheres and boxes at local offsets on one body.
#include "BoxAxes.h"
#include "CollisionGeometry.h"
#include "iCCompound.h"
#include "iUtilities.h"

#include <cmath>
#include <limits>

namespace {

// Every component within MAX_SHAPE_SIZE of the geometry's centre (NaN fails).
bool validOffset(const Vector& o) {
    auto ok = [](float f) { return std::fabs(f) <= MAX_SHAPE_SIZE; };
    return ok(o.x) && ok(o.y) && ok(o.z);
}

struct Child {
    gcol::ShapeKind kind;
    Vector offset;
    Matrix rotation = Matrix(1); // child local -> body local (boxes)
    float radius = 0.0f;
    Vector half;
};

class CCompound final : public GeometryImpl<iCCompound> {
public:
    iCollisionGeometry* clone() const override {
        auto* c = new CCompound();
        c->m_children = m_children;
        c->bind(const_cast<CCompound*>(this)->body());
        c->copyFilter(*this);
        c->joinDefaultSpace();
        return c;
    }
    int getCollisionType() const override { return CT_COMPOUND; }
    float getBoundingRadius() const override {
        float r = 0.0f;
        for (const Child& c : m_children)
            r = std::fmax(r, c.offset.length() +
                                 (c.kind == gcol::ShapeKind::Sphere ? c.radius : c.half.length()));
        return r;
    }
    bool addSphere(const Vector& offset, float radius) override {
        if (!validOffset(offset) || !(radius > 0.0f && radius <= MAX_SHAPE_SIZE)) {
            error(L"iCCompound::addSphere: offset and radius must be at most MAX_SHAPE_SIZE (1e6 m), the "
                  L"radius "
                  L"positive; refused");
            return false;
        }
        Child c;
        c.kind = gcol::ShapeKind::Sphere;
        c.offset = offset;
        c.radius = radius;
        m_children.push_back(c);
        shapeChanged();
        return true;
    }
    bool addBox(const Vector& offset, const Matrix& rotation, const Vector& h) override {
        auto ok = [](float f) { return f > 0.0f && f <= MAX_SHAPE_SIZE; };
        if (!validOffset(offset) || !isRotation(rotation) || !ok(h.x) || !ok(h.y) || !ok(h.z)) {
            error(L"iCCompound::addBox: needs an offset within MAX_SHAPE_SIZE (1e6 m), a proper rotation and "
                  L"positive half extents at most MAX_SHAPE_SIZE; refused");
            return false;
        }
        Child c;
        c.kind = gcol::ShapeKind::Box;
        c.offset = offset;
        c.rotation = rotation.rotation();
        c.half = h;
        m_children.push_back(c);
        shapeChanged();
        return true;
    }
    size_t getNumChildren() const override { return m_children.size(); }
    void clearChildren() override {
        m_children.clear();
        shapeChanged();
    }
    // The children as one solid of uniform density (overlaps count twice), about the compound's centroid.
    ShapeMass shapeMass() const override {
        std::vector<ShapeMass> parts;
        parts.reserve(m_children.size());
        for (const Child& c : m_children)
            parts.push_back(c.kind == gcol::ShapeKind::Sphere ? sphereShapeMass(c.radius, c.offset)
                                                              : boxShapeMass(c.half, c.offset, c.rotation));
        return combineShapeMass(parts.data(), parts.size());
    }
    int shapeCount() const override { return int(m_children.size()); }
    void writeWorldShapes(const Vector& origin, const Matrix& r, gcol::WorldShape* out) const override {
        for (const Child& c : m_children) {
            gcol::WorldShape& s = *out++;
            s.kind = c.kind;
            Vector centre = origin + r.direction(c.offset);
            if (c.kind == gcol::ShapeKind::Sphere) {
                s.sphere.centre = centre;
                s.sphere.radius = c.radius;
            } else {
                Matrix w = c.rotation * r;
                s.box.centre = centre;
                gcol::unitAxes(w, s.box.axis);
                s.box.halfExtents = c.half;
            }
        }
    }
    float minDimension() const override {
        float m = std::numeric_limits<float>::infinity();
        for (const Child& c : m_children)
            m = std::fmin(m, c.kind == gcol::ShapeKind::Sphere
                                 ? 2.0f * c.radius
                                 : 2.0f * std::fmin(c.half.x, std::fmin(c.half.y, c.half.z)));
        return m;
    }
    void start() { joinDefaultSpace(L"CreateCCompound"); }

private:
    std::vector<Child> m_children;
};

} // namespace

iCollisionGeometry* CreateCCompound(iRigidBody* rb) {
    auto* c = new CCompound();
    c->attach(rb);
    c->start();
    return c;
}
