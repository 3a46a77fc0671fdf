// CheckDesign.cpp (sim-collision) - a course design written after the merge: a ball in a PhysicsFrame with a
// sphere geometry falls onto a fixed box, carrying the host's own drawable object. Checks: free fall matches
// semi-implicit Euler's exact discrete solution, the drawn object follows the body, nothing is integrated
// while suspended, the ball comes to rest on the box and its listener heard the hit.
#include "Checks.h"
#include "ModelSettings.h"
#include "RBDynamics.h"
#include "iCOBB.h"
#include "iCSphere.h"
#include "iCollisionListener.h"
#include "iContext.h"
#include "iDesign.h"
#include "iObject.h"
#include "iPhysicsFrame.h"
#include "iRigidBody.h"

namespace {

const float g = 9.81f, dt = 1.0f / 60.0f;
iPhysicsFrame* ball = nullptr;
iPhysicsFrame* ground = nullptr;
iObject* drawn = nullptr;

struct Hits : iCollisionListener {
    int count = 0;
    void HitWall(iRigidBody*, Vector, Vector) override { ++count; }
} hits;

// Height after n fixed steps of semi-implicit Euler from rest at h: h - g dt^2 n (n + 1) / 2.
float eulerFall(float h, int n) { return h - g * dt * dt * float(n) * float(n + 1) / 2.0f; }

class CheckDesign final : public iDesign {
public:
    void initialize(int) override {
        ground = CreatePhysicsFrame();
        ground->translate(0, -0.5f, 0);
        ground->getDynamics()->physicsType = PHYS_FixedInSpace;
        ground->getDynamics()->mass = INFINITE_MASS; // from ModelSettings.h, through the merged line
        CreateCOBB(ground->getRB(), Vector(10, 0.5f, 10));
        ball = CreatePhysicsFrame();
        // As the seed's sample: attach the drawable first (attaching keeps world poses), then move the frame.
        drawn = CreateSphere(0.5f, Reflectivity(Colour(1, 0, 0)));
        drawn->attachTo(ball);
        ball->translate(0, 10, 0);
        ball->getDynamics()->restitution = 0;
        ball->getRB()->attachListener(&hits);
        CreateCSphere(ball->getRB(), 0.5f);
    }
    void reset(int) override {}
    void restore(int) override {}
    void update(int) override { drawn->draw(); }
    void suspend() override {}
    void Delete() const override {
        drawn->Delete();
        ball->Delete();
        ground->Delete();
        delete this;
    }
};

} // namespace

iDesign* CreateDesign(iContext*) { return new CheckDesign(); }

void checkAfterFirstSecond() {
    // The first update only sets the time base: 944 ms of simulation, 56 whole steps of 1/60 s.
    float y = ball->getDynamics()->position.y;
    check("ball height after 56 steps (semi-implicit Euler, exact)", y, eulerFall(10, 56), 2e-3f);
    check("continuous free fall 10 - g t^2 / 2 at t = 56/60 s, within Euler's g t dt / 2", y,
          10 - g * (56 * dt) * (56 * dt) / 2, g * (56 * dt) * dt / 2 + 1e-3f);
    // Drawn frames are interpolated between the last two steps: at most one step's motion behind.
    float speed = g * 56 * dt;
    check("drawn object follows the body within one step", lastDrawnPosition().y, y, speed * dt + 1e-3f);
}

void checkAfterRestore() {
    // 5 s suspended, then one 16 ms frame: exactly one step more, not 5 s of falling.
    check("one step after the suspension, none for it", ball->getDynamics()->position.y, eulerFall(10, 57),
          2e-3f);
}

void checkAtEnd() {
    check("ball rests on the box (centre 0.5 m above its top)", ball->getDynamics()->position.y, 0.5f, 0.01f);
    check("resting speed", ball->getDynamics()->velocity.length(), 0, 0.01f);
    check("the listener heard the ball hit the box", hits.count > 0 ? 1.0f : 0.0f, 1, 0);
    check("drawn object rests with the body", lastDrawnPosition().y, 0.5f, 0.01f);
}
