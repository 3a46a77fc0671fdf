#include "Frame.h"
#include "iCSphere.h"
#include "iCollisionSpace.h"
#include "iPhysicsFrame.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneSettings.h"
#include "iPhysicsSceneStats.h"
#include "iRigidBody.h"
#include "iSimpleCollisionSpace.h"

#include <cstdio>

int main() {
    // Engine: create the scene in the constructor, give it a collision space in setup().
    iPhysicsScene* physicsScene = CreatePhysicsScene(nullptr);
    iCollisionSpace* space = CreateSimpleCollisionSpace();
    physicsScene->setNewGlobalCollisionSpace(space);

    // Design: a physics frame, an object drawn with it, and (optionally) a collision sphere.
    iPhysicsFrame* f = CreatePhysicsFrame(); // a frame that owns a rigid body, added to the scene
    RBDynamics* d = f->getDynamics();        // its physical state: edit it directly
    Frame* o = new Frame();                  // stands in for your drawable object (an iObject is a Frame)...
    o->attachTo(f);                          // ...that follows the frame
    d->position = Vector(0, 10, 0);          // metres, y up
    d->velocity += Vector(0, 0, 5);          // metres per second
    iCollisionGeometry* c = CreateCSphere(f->getRB(), 0.5f);

    // Engine run(): once a frame, before design->update(now); now is in milliseconds. The first update
    // only sets the time base; the next ones take fixed 1/60 s steps: 60 steps by now = 1000.
    for (int now = 0; now <= 1000; now += 20) physicsScene->update(now);

    // The body's state after the last step is what a student computes by hand: z = 5 t, and
    // y = 10 - g t^2 / 2 less semi-implicit Euler's g t dt / 2 (8.2 cm). The drawn object is interpolated
    // between the last two steps, so it is drawn one step behind (here exactly: 16 cm higher, 8 cm back).
    double t = double(statsOf(physicsScene)->getStepCount()) / settingsOf(physicsScene)->getStepRate();
    Vector p = d->position, drawn = o->position();
    std::printf("after %.3f s the ball is at (%.3f, %.3f, %.3f) m\n", t, p.x, p.y, p.z);
    std::printf("and is drawn at (%.3f, %.3f, %.3f) m\n", drawn.x, drawn.y, drawn.z);

    // Release in any order; the scene deletes any bodies still in it.
    o->Delete();
    f->Delete();
    c->Delete();
    physicsScene->setNewGlobalCollisionSpace(nullptr);
    space->Delete();
    physicsScene->Delete();
    return 0;
}
