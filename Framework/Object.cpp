// Object.cpp - the headless object behind iObject: bounds only, nothing drawn.
#include "iObject.h"

namespace {

class Object final : public iObject {
public:
    Object(const Vector& lo, const Vector& hi) : m_min(lo), m_max(hi) {}
    Vector minimum() const override { return m_min; }
    Vector maximum() const override { return m_max; }
    iObject* clone() const override { return new Object(*this); }
    void suspend() override {}
    void restore(int) override {}
    void release() override {}
    void Delete() const override { delete this; }

private:
    Vector m_min, m_max;
};

} // namespace

extern "C" iObject* CreateBox(float minx, float miny, float minz, float maxx, float maxy, float maxz) {
    return new Object(Vector(minx, miny, minz), Vector(maxx, maxy, maxz));
}
extern "C" iObject* CreateSphere(float radius) {
    return new Object(Vector(-radius, -radius, -radius), Vector(radius, radius, radius));
}
