// CheckDesign.cpp (collision-only) - a course design written after the merge: two of the game's own objects
// implement iRigidBody and move towards each other at 1 m/s each; the game calls the collision space itself
// and stops them at the first contact. Checks: no contact while apart, the contact's depth and normal are the
// geometric truth, HitWall reached both bodies' listeners with normals pointing at the other.
#include "Checks.h"
#include "RBDynamics.h"
#include "iCSphere.h"
#include "iCollisionListener.h"
#include "iCollisionSpace.h"
#include "iContext.h"
#include "iDesign.h"
#include "iObject.h"
#include "iRigidBody.h"
#include "iSimpleCollisionSpace.h"

#include <vector>

namespace {

// The game's own body: an object of the host that keeps its RBDynamics current.
class Body final : public iRigidBody {
public:
    explicit Body(iObject* o) : m_object(o) {}
    ~Body() { rigidBodyDestroyed(this); }
    iRigidBody* clone() const override { return new Body(m_object); }
    void attach(iFrame*) override {}
    void attachListener(iCollisionListener* l) override { m_listeners.push_back(l); }
    void detachListener(const iCollisionListener*) override {}
    void restore(int) override {}
    std::vector<iCollisionListener*>& getListeners() override { return m_listeners; }
    iFrame* getFrame() override { return m_object; }
    RBDynamics& getDynamics() override { return m_d; }
    const RBDynamics& getDynamics() const override { return m_d; }
    void setDynamics(const RBDynamics& d) override { m_d = d; }
    void reset(int) override {}
    void suspend() const override {}
    void release() const override {}
    void Delete() const override { delete this; }
    void moveTo(const Vector& p) {
        Vector d = p - m_d.position;
        m_d.position = p;
        m_object->translate(d.x, d.y, d.z);
    }

private:
    iObject* m_object;
    RBDynamics m_d;
    std::vector<iCollisionListener*> m_listeners;
};

struct Heard : iCollisionListener {
    iRigidBody* self = nullptr;
    int count = 0;
    float normalTowardsOther = 0; // dot(normal, other - self) at the last call, over |other - self|
    void HitWall(iRigidBody* other, Vector n, Vector) override {
        ++count;
        Vector d = other->getDynamics().position - self->getDynamics().position;
        normalTowardsOther = dot(n, d) / d.length();
    }
};

iCollisionSpace* space = nullptr;
Body* left = nullptr;
Body* right = nullptr;
Heard heardLeft, heardRight;
iObject* objects[2];
bool stopped = false;
float depthAtStop = -1, gapAtStop = 0, normalXAtStop = 0;
int lastNow = 0;

class CheckDesign final : public iDesign {
public:
    void initialize(int now) override {
        space = CreateSimpleCollisionSpace();
        setDefaultCollisionSpace(space); // before any geometry, as INTEGRATION.md says
        objects[0] = CreateSphere(0.5f, Reflectivity(Colour(1, 0, 0)));
        objects[1] = CreateSphere(0.5f, Reflectivity(Colour(0, 0, 1)));
        left = new Body(objects[0]);
        right = new Body(objects[1]);
        left->moveTo(Vector(-2, 0, 0));
        right->moveTo(Vector(2, 0, 0));
        CreateCSphere(left, 0.5f);
        CreateCSphere(right, 0.5f);
        heardLeft.self = left;
        heardRight.self = right;
        left->attachListener(&heardLeft);
        right->attachListener(&heardRight);
        lastNow = now;
    }
    void reset(int now) override { lastNow = now; }
    void restore(int now) override { lastNow = now; }
    void update(int now) override {
        float dt = float(now - lastNow) / 1000.0f;
        lastNow = now;
        if (!stopped) {
            left->moveTo(left->getDynamics().position + Vector(dt, 0, 0));
            right->moveTo(right->getDynamics().position - Vector(dt, 0, 0));
        }
        space->populateContactList(dt);
        if (!stopped && space->getNumContacts() > 0) {
            stopped = true;
            const CollisionContact& c = space->getContactList()[0];
            depthAtStop = c.depth;
            gapAtStop = right->getDynamics().position.x - left->getDynamics().position.x;
            normalXAtStop = c.g1->getRigidBody() == left ? c.normal.x : -c.normal.x;
        }
        objects[0]->draw();
        objects[1]->draw();
    }
    void suspend() override {}
    void Delete() const override {
        space->Delete(); // deletes its geometry
        left->Delete();
        right->Delete();
        objects[0]->Delete();
        objects[1]->Delete();
        delete this;
    }
};

} // namespace

iDesign* CreateDesign(iContext*) { return new CheckDesign(); }

void checkAfterFirstSecond() {
    check("no contact while 1.08 m apart", float(space->getNumContacts()), 0, 0);
    check("left body moved 0.96 m", left->getDynamics().position.x, -2 + 0.96f, 1e-4f);
}

void checkAfterRestore() {
    check("no time passes for the game's own bodies while suspended", left->getDynamics().position.x,
          -2 + 0.976f, 1e-4f);
}

void checkAtEnd() {
    check("the bodies met and stopped", stopped ? 1.0f : 0.0f, 1, 0);
    check("contact depth = r1 + r2 - distance", depthAtStop, 1.0f - gapAtStop, 1e-4f);
    check("first contact within one frame's closing (0.032 m)", depthAtStop, 0.016f, 0.0161f);
    check("normal points from the left body at the right one (+x)", normalXAtStop, 1, 1e-4f);
    check("left listener heard the hit, normal at the other", heardLeft.normalTowardsOther, 1, 1e-4f);
    check("right listener heard the hit, normal at the other", heardRight.normalTowardsOther, 1, 1e-4f);
    check("both listeners were called", heardLeft.count > 0 && heardRight.count > 0 ? 1.0f : 0.0f, 1, 0);
}
