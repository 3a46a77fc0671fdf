// Scenes.cpp - the demo scenes. Sizes in metres, masses in kilograms; y is up and the floor is at y = 0.
#include "Scenes.h"

#include "JointScenes.h"
#include "MathDefinitions.h"
#include "RBDynamics.h"
#include "World.h"
#include "iPhysicsFrame.h"
#include "iRigidBody.h"

#include <cstring>
#include <random>

namespace {

const Vector kUnitHalf(0.5f, 0.5f, 0.5f);

void act(World& world, int frame) {
    // One shot a second (60 frames), five shots.
    if (frame % 60 == 30 && frame / 60 < 5) shootSphere(world, frame / 60);
}

} // namespace

void buildTower(World& world, int boxes) {
    world.ground();
    for (int i = 0; i < boxes; ++i) world.box(Vector(0, 0.5f + i, 0), kUnitHalf, 1.0f);
    if (boxes > 0) {
        world.name(world.bodies().front(), "bottom");
        world.name(world.bodies().back(), "top");
    }
}

void buildPyramid(World& world, int base) {
    world.ground();
    for (int row = 0; row < base; ++row) {
        int count = base - row;
        float x0 = -0.5f * (count - 1);
        for (int i = 0; i < count; ++i) world.box(Vector(x0 + i, 0.5f + row, 0), kUnitHalf, 1.0f);
    }
    if (base > 0) world.name(world.bodies().back(), "top");
}

void buildBallPit(World& world, int balls, unsigned seed) {
    world.ground();
    const float half = 3.0f; // a 6 m x 6 m pit with 2 m walls
    world.fixedBox(Vector(-half - 0.25f, 1, 0), Vector(0.25f, 1, half));
    world.fixedBox(Vector(half + 0.25f, 1, 0), Vector(0.25f, 1, half));
    world.fixedBox(Vector(0, 1, -half - 0.25f), Vector(half, 1, 0.25f));
    world.fixedBox(Vector(0, 1, half + 0.25f), Vector(half, 1, 0.25f));
    // Balls start on a jittered 8 x 8 grid of cells 0.7 m apart, layer above layer: none overlap.
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> jitter(-0.04f, 0.04f);
    for (int i = 0; i < balls; ++i) {
        int layer = i / 64, ix = i % 8, iz = (i / 8) % 8;
        // Draws in a stated order (z first): the order of a call's arguments is the compiler's choice.
        const float dz = jitter(rng), dx = jitter(rng);
        Vector at(0.7f * (ix - 3.5f) + dx, 1.0f + 0.7f * layer, 0.7f * (iz - 3.5f) + dz);
        world.sphere(at, 0.3f, 0.5f);
    }
}

void buildDominoes(World& world, int count) {
    world.ground();
    const Vector half(0.05f, 0.5f, 0.25f);
    for (int i = 0; i < count; ++i) world.box(Vector(0.6f * i, 0.5f, 0), half, 0.5f);
    world.name(world.bodies().front(), "first");
    world.name(world.bodies().back(), "last");
    // Push the first one's top along +x.
    RBDynamics* first = world.bodies().front()->getDynamics();
    first->ApplyImpulse(Vector(0.6f, 0, 0), first->position + Vector(0, 0.45f, 0));
}

void buildNewtonsCradle(World& world, int balls) {
    // Floating balls (no gravity, no strings) 1 cm apart, so each collision is between two balls at a time.
    for (int i = 0; i < balls; ++i) {
        RBDynamics* d = world.sphere(Vector(1.01f * i, 1, 0), 0.5f, 1.0f)->getDynamics();
        d->physicsType = PHYS_Floating;
        d->restitution = 1.0f;
        d->friction = 0.0f;
    }
    world.name(world.bodies().front(), "cue")->getDynamics()->velocity = Vector(2, 0, 0);
    world.name(world.bodies().back(), "last");
}

void buildShootingGallery(World& world) {
    world.ground();
    for (int row = 0; row < 5; ++row)
        for (int i = 0; i < 8; ++i) world.box(Vector(-3.5f + i, 0.5f + row, 0), kUnitHalf, 1.0f);
    world.name(world.bodies().back(), "corner"); // the top row's right-hand box
}

void shootSphere(World& world, int shot) {
    RBDynamics* d = world.sphere(Vector(-2.0f + shot, 2.5f, -12), 0.25f, 2.0f)->getDynamics();
    // "To shoot or prod objects": an impulse of 60 N s at the centre sends 2 kg at 30 m/s toward the wall.
    d->ApplyImpulse(Vector(0, 2.0f, 60), d->position);
}

// Grid cell i of a 10 x 10 layout, layers 1.8 m apart: no two bodies start overlapping.
static Vector pileCell(int i, std::mt19937& rng) {
    std::uniform_real_distribution<float> jitter(-0.2f, 0.2f);
    int layer = i / 100, ix = i % 10, iz = (i / 10) % 10;
    const float dz = jitter(rng), dx = jitter(rng); // in this order, on every compiler
    return Vector(1.8f * (ix - 4.5f) + dx, 1.0f + 1.8f * layer, 1.8f * (iz - 4.5f) + dz);
}

void buildBoxPile(World& world, int boxes, unsigned seed) {
    world.ground();
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> angle(-3.14159f, 3.14159f), unit(-1, 1);
    for (int i = 0; i < boxes; ++i) {
        // Random draws in a stated order: the order of a call's arguments is the compiler's choice.
        const float az = unit(rng), ay = unit(rng), ax = unit(rng);
        const float turn = angle(rng);
        const Vector at = pileCell(i, rng);
        world.box(at, kUnitHalf, 1.0f, rotate(Vector(ax, ay, az), turn));
    }
}

void buildSpherePile(World& world, int spheres, unsigned seed) {
    world.ground();
    std::mt19937 rng(seed);
    for (int i = 0; i < spheres; ++i) world.sphere(pileCell(i, rng), 0.5f, 1.0f);
}

// The registry: a deque, so registering never moves a SceneSpec a running game holds.
static std::deque<SceneSpec>& registry() {
    static std::deque<SceneSpec> scenes = {
        {"tower", "10 boxes stacked (named: top, bottom)", [](World& w) { buildTower(w, 10); }, nullptr},
        {"pyramid", "210 boxes, a base of 20 (named: top)", [](World& w) { buildPyramid(w, 20); }, nullptr},
        {"ballpit", "200 balls dropped into a pit", [](World& w) { buildBallPit(w, 200, 7); }, nullptr},
        {"dominoes", "30 dominoes, the first one pushed (named: first, last)",
         [](World& w) { buildDominoes(w, 30); }, nullptr},
        {"cradle", "Newton's cradle of 5 balls (named: cue, last)",
         [](World& w) { buildNewtonsCradle(w, 5); }, nullptr},
        {"shooting", "spheres shot into a wall of 40 boxes (named: corner)", buildShootingGallery, act},
    };
    static const bool withJoints = (addJointScenes(scenes), true); // JointScenes.cpp, once, after these
    (void)withJoints;
    return scenes;
}

const std::deque<SceneSpec>& allScenes() { return registry(); }

const SceneSpec* findScene(const std::string& name) {
    for (const SceneSpec& s : allScenes())
        if (name == s.name) return &s;
    return nullptr;
}

bool registerScene(const SceneSpec& spec) {
    if (!spec.name || !*spec.name || !spec.build || !std::strcmp(spec.name, "all") ||
        std::strpbrk(spec.name, " \t,/") || findScene(spec.name))
        return false;
    registry().push_back(spec);
    return true;
}
