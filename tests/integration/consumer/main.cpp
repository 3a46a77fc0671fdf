// main.cpp - links the installed Guardian Physics: a ball dropped for one simulated second must fall
// 1/2 g t^2 (within one step of semi-implicit Euler's O(dt) error) and touch a floor it starts in.
#include "MathDefinitions.h"
#include "iCSphere.h"
#include "iCollisionSpace.h"
#include "iPhysicsFrame.h"
#include "iPhysicsScene.h"
#include "iRigidBody.h"
#include "iSimpleCollisionSpace.h"

#include <cmath>
#include <cstdio>

int main() {
    iPhysicsScene* scene = CreatePhysicsScene(nullptr);
    iPhysicsFrame* ball = CreatePhysicsFrame();
    ball->getDynamics()->position = Vector(0, 20, 0);
    scene->update(0); // the first update sets the time base
    for (int now = 10; now <= 1000; now += 10) scene->update(now);
    float drop = 20.0f - ball->getDynamics()->position.y, t = 1.0f, g = 9.81f, dt = 1.0f / 60.0f;
    bool fell = std::fabs(drop - 0.5f * g * t * t) <= 2 * g * t * dt; // one step late + Euler O(dt)
    std::printf("consumer: dropped %.4f m in 1 s (1/2 g t^2 = %.4f)\n", drop, 0.5f * g * t * t);

    iCollisionSpace* space = CreateSimpleCollisionSpace();
    iCollisionGeometry* a = CreateCSphere(ball->getRB(), 1.0f);
    iPhysicsFrame* other = CreatePhysicsFrame();
    other->getDynamics()->position = ball->getDynamics()->position + Vector(1.5f, 0, 0);
    iCollisionGeometry* b = CreateCSphere(other->getRB(), 1.0f);
    space->add(a);
    space->add(b);
    space->populateContactList(0);
    bool touched = space->getNumContacts() == 1 && std::fabs(space->getContactList()[0].depth - 0.5f) < 1e-4f;
    std::printf("consumer: %zu contact(s)\n", space->getNumContacts());

    a->Delete();
    b->Delete();
    space->Delete();
    ball->Delete();
    other->Delete();
    scene->Delete();
    return fell && touched ? 0 : 1;
}
