// CheckDesign.cpp (sim-only) - a course design written after the merge: a projectile in a PhysicsFrame and
// a kinematic platform (INFINITE_MASS from the host's ModelSettings.h) moving at constant speed. Checks: the
// projectile follows semi-implicit Euler's exact discrete solution, nothing is integrated while suspended,
// the platform moves at its speed, the host's drawn object follows its frame.
#include "Checks.h"
#include "ModelSettings.h"
#include "RBDynamics.h"
#include "iContext.h"
#include "iDesign.h"
#include "iObject.h"
#include "iPhysicsFrame.h"

namespace {

const float g = 9.81f, dt = 1.0f / 60.0f, vx = 3, vy = 10;
iPhysicsFrame* shot = nullptr;
iPhysicsFrame* platform = nullptr;
iObject* drawn = nullptr;

class CheckDesign final : public iDesign {
public:
    void initialize(int) override {
        shot = CreatePhysicsFrame();
        shot->getDynamics()->velocity = Vector(vx, vy, 0);
        platform = CreatePhysicsFrame();
        platform->getDynamics()->mass = INFINITE_MASS; // from ModelSettings.h, through the merged line
        platform->getDynamics()->velocity = Vector(0, 0, 1);
        drawn = CreateSphere(0.1f, Reflectivity(Colour(0, 1, 0)));
        drawn->attachTo(shot);
    }
    void reset(int) override {}
    void restore(int) override {}
    void update(int) override { drawn->draw(); }
    void suspend() override {}
    void Delete() const override {
        drawn->Delete();
        shot->Delete();
        platform->Delete();
        delete this;
    }
};

// Checks the projectile after however many steps its x says were taken (x moves at exactly vx).
int checkProjectile() {
    Vector p = shot->getDynamics()->position;
    int n = int(p.x / (vx * dt) + 0.5f);
    check("projectile x is a whole number of steps", p.x, float(n) * vx * dt, 1e-3f);
    float y = vy * float(n) * dt - g * dt * dt * float(n) * float(n + 1) / 2;
    check("projectile height (semi-implicit Euler, exact)", p.y, y, 2e-3f + 1e-5f * float(n));
    check("kinematic platform moved at 1 m/s for the same steps", platform->getDynamics()->position.z,
          float(n) * dt, 1e-3f);
    return n;
}

} // namespace

iDesign* CreateDesign(iContext*) { return new CheckDesign(); }

void checkAfterFirstSecond() {
    int n = checkProjectile();
    check("steps in the first 0.96 s (the first update sets the time base)", float(n), 56, 0);
}

void checkAfterRestore() {
    int n = checkProjectile();
    check("steps after a 5 s suspension and one frame (none for the suspension)", float(n), 57, 0);
}

void checkAtEnd() {
    int n = checkProjectile();
    // 300 frames of 16 ms = 4.8 s = 288 steps more.
    check("steps at the end", float(n), 57 + 288, 1);
    Vector d = lastDrawnPosition() - shot->getDynamics()->position;
    check("drawn object within one step of the body", d.length(), 0, (vx + vy + g * float(n) * dt) * dt);
}
