// Object.cpp - the test host's drawable objects, headless: drawing records the object's world pose.
#include "MathDefinitions.h"
#include "iObject.h"

static int draws = 0;
static Vector lastDrawn;

class Object : public iObject {
    Reflectivity reflectivity;
    Vector extent;

public:
    Object(const Vector& e, const Reflectivity& r) : reflectivity(r), extent(e) {}
    void draw() {
        ++draws;
        lastDrawn = position();
    }
    const Reflectivity& material() const { return reflectivity; }
    void Delete() const { delete this; }
};

iObject* CreateSphere(float radius, const Reflectivity& r) {
    return new Object(Vector(radius, radius, radius), r);
}

iObject* CreateBox(float minx, float miny, float minz, float maxx, float maxy, float maxz,
                   const Reflectivity& r) {
    Object* o = new Object(Vector(maxx - minx, maxy - miny, maxz - minz), r);
    o->translate((minx + maxx) / 2, (miny + maxy) / 2, (minz + maxz) / 2);
    return o;
}

int drawsRecorded() { return draws; }
Vector lastDrawnPosition() { return lastDrawn; }
