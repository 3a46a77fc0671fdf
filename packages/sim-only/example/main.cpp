// The sim-only package's INTEGRATION.md, as a whole program: a physics frame under gravity with a constant
// torque, and a drawn frame riding on it. Exits 0 when the motion is what a student computes by hand.
#include "Frame.h"
#include "PhysicsConstants.h"
#include "RBDynamics.h"
#include "iPhysicsFrame.h"
#include "iPhysicsScene.h"

#include <cmath>
#include <cstdio>

int main() {
    iPhysicsScene* physicsScene = CreatePhysicsScene(nullptr); // the Engine's constructor

    iPhysicsFrame* f = CreatePhysicsFrame();
    Frame drawn;       // stands in for the game's drawable object
    drawn.attachTo(f); // attach first: attaching keeps world poses
    f->translate(0, 10, 0);
    RBDynamics* d = f->getDynamics();
    d->torque = Vector(0, 1, 0); // N m, every step; the default inertia about y is I (see RBDynamics.h)

    for (int now = 0; now <= 1000; now += 20) physicsScene->update(now); // 60 steps of 1/60 s

    // Semi-implicit Euler, n steps from rest: y = 10 - g dt^2 n (n + 1) / 2; spin w = tau t / I.
    const double g = 9.81, dt = 1.0 / 60, n = 60;
    double y = 10 - g * dt * dt * n * (n + 1) / 2;
    double inertia = d->getInertiaTensor().m22;
    double w = 1.0 * n * dt / inertia;
    std::printf("y = %.4f m (expected %.4f), spin = %.4f rad/s (expected %.4f)\n", d->position.y, y,
                d->angularVelocity.y, w);
    bool ok = std::fabs(d->position.y - y) < 2e-3 && std::fabs(d->angularVelocity.y - w) < 1e-3 * w &&
              std::fabs(drawn.position().y - d->position.y) < 0.2; // drawn at most one step behind

    f->Delete();
    physicsScene->Delete();
    std::printf("%s\n", ok ? "OK" : "FAIL");
    return ok ? 0 : 1;
}
