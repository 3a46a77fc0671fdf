// Scenes.h - the named demo scenes, written once for the reference game, the tests and the benchmarks.
//
// A scene builds its bodies into a World and may act once a physics step's worth of frames (shooting).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

class World;

struct SceneSpec {
    const char* name;
    const char* description;
    void (*build)(World& world);
    // Called by the game once a frame with the frame number (may be nullptr).
    void (*act)(World& world, int frame);
};

const std::vector<SceneSpec>& allScenes();
const SceneSpec* findScene(const std::string& name);

// The builders, also used directly by tests and benchmarks.
void buildTower(World& world, int boxes);                  // unit boxes stacked on a floor
void buildPyramid(World& world, int base);                 // base + (base-1) + ... + 1 unit boxes
void buildBallPit(World& world, int balls, unsigned seed); // spheres dropped into a walled pit
void buildDominoes(World& world, int count);               // a row of thin slabs, the first one pushed
void buildNewtonsCradle(World& world, int balls); // floating balls in a row, restitution 1, one moving
void buildShootingGallery(World& world);          // a wall of boxes to shoot spheres at
void shootSphere(World& world, int shot);         // fires one sphere at the wall with ApplyImpulse
void buildBoxPile(World& world, int boxes, unsigned seed); // randomly turned boxes dropped on a floor
void buildSpherePile(World& world, int spheres, unsigned seed);
