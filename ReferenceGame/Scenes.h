// Scenes.h - the named demo scenes, written once for the reference game, the tests and the benchmarks.
//
// A scene builds its bodies into a World and may act once a frame (shooting). A game adds its own scenes
// with registerScene from its own files, before it runs them: the game (ReferenceGame/GameRun.h) then lists,
// finds and runs them like the built-in ones.
#pragma once

#include <cstddef>
#include <deque>
#include <string>

class World;

struct SceneSpec {
    const char* name;
    const char* description;
    void (*build)(World& world);
    // Called by the game once a frame with the frame number (may be nullptr).
    void (*act)(World& world, int frame);
};

// The built-in scenes, then the registered ones in registration order. Registering adds to the end and
// leaves every SceneSpec already handed out where it is.
const std::deque<SceneSpec>& allScenes();
const SceneSpec* findScene(const std::string& name);

// Adds a scene, an explicit call (static self-registration in a library is dropped by linkers). The name and
// description must outlive the program (string literals). Refused (false, nothing added) when the name is
// empty, "all", has a space, comma or slash, is already taken, or build is nullptr. Example:
//   registerScene({"drop", "one ball falling from 20 m",
//                  [](World& w) { w.name(w.sphere(Vector(0, 20, 0), 0.5f, 1.0f), "ball"); }, nullptr});
bool registerScene(const SceneSpec& spec);

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
