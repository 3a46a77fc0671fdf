// The collision-only package's INTEGRATION.md, as a whole program: a space set as the default before any
// geometry, two objects of the game's own iRigidBody class moved by the game, contacts and HitWall calls.
// Exits 0 when the contact is the geometric truth.
#include "RBDynamics.h"
#include "iCSphere.h"
#include "iCollisionListener.h"
#include "iCollisionSpace.h"
#include "iRigidBody.h"
#include "iSimpleCollisionSpace.h"

#include <cmath>
#include <cstdio>
#include <vector>

// The game's own body: it keeps its RBDynamics current and calls rigidBodyDestroyed when it goes.
class Ball final : public iRigidBody {
public:
    ~Ball() { rigidBodyDestroyed(this); }
    iRigidBody* clone() const override { return new Ball(*this); }
    void attach(iFrame*) override {}
    void attachListener(iCollisionListener* l) override { m_listeners.push_back(l); }
    void detachListener(const iCollisionListener*) override {}
    void restore(int) override {}
    std::vector<iCollisionListener*>& getListeners() override { return m_listeners; }
    iFrame* getFrame() override { return nullptr; }
    RBDynamics& getDynamics() override { return m_d; }
    const RBDynamics& getDynamics() const override { return m_d; }
    void setDynamics(const RBDynamics& d) override { m_d = d; }
    void reset(int) override {}
    void suspend() const override {}
    void release() const override {}
    void Delete() const override { delete this; }

private:
    RBDynamics m_d;
    std::vector<iCollisionListener*> m_listeners;
};

struct Hits final : iCollisionListener {
    int count = 0;
    Vector normal;
    void HitWall(iRigidBody*, Vector n, Vector) override {
        ++count;
        normal = n;
    }
};

int main() {
    iCollisionSpace* space = CreateSimpleCollisionSpace();
    setDefaultCollisionSpace(space); // before creating any geometry

    Ball* a = new Ball();
    Ball* b = new Ball();
    a->getDynamics().position = Vector(-2, 0, 0);
    b->getDynamics().position = Vector(2, 0.3f, 0);
    CreateCSphere(a, 0.5f);
    CreateCSphere(b, 0.5f);
    Hits hits;
    a->attachListener(&hits);

    // Each frame the game moves its bodies, then asks the space for contacts.
    int frames = 0;
    while (space->getNumContacts() == 0 && frames < 200) {
        a->getDynamics().position += Vector(0.02f, 0, 0);
        b->getDynamics().position -= Vector(0.02f, 0, 0);
        space->populateContactList(1.0f / 60);
        ++frames;
    }
    const CollisionContact* c = space->getContactList();
    Vector ab = b->getDynamics().position - a->getDynamics().position;
    float expectedDepth = 1.0f - ab.length(); // r1 + r2 - distance
    bool aFirst = c && c->g1->getRigidBody() == a;
    Vector n = c ? (aFirst ? c->normal : -c->normal) : Vector();
    std::printf("contact after %d frames: depth %.4f m (expected %.4f), normal (%.3f, %.3f, %.3f)\n", frames,
                c ? c->depth : -1, expectedDepth, n.x, n.y, n.z);
    bool ok = c && std::fabs(c->depth - expectedDepth) < 1e-4f &&
              (n - ab.normalize()).length() < 1e-4f && // from a towards b
              hits.count == 1 && (hits.normal - ab.normalize()).length() < 1e-4f;

    space->Delete(); // deletes its geometry
    a->Delete();
    b->Delete();
    std::printf("%s\n", ok ? "OK" : "FAIL");
    return ok ? 0 : 1;
}
