// Tracking.h - the reference game's --track: the bodies a person asked to follow, by the name a scene gave
// them (World::name) or by index, and the line printed for each once a second.
#pragma once

#include "MathDeclarations.h"

#include <cstdio>
#include <string>
#include <vector>

class World;
class iPhysicsFrame;

class BodyTracker {
public:
    // Finds each wanted body in world: a name given with World::name, else a decimal index into
    // world.bodies(). A scene that has no such body is told on err (with the names it has) and skipped.
    void resolve(const World& world, const std::vector<std::string>& wanted, const char* scene,
                 std::FILE* err);

    const std::vector<std::string>& names() const { return m_names; } // of the bodies found
    std::vector<Vector> positions() const;                            // their centres now, m
    // One line per body: "  track NAME  pos (x, y, z) m  speed S m/s" with "  asleep" when it sleeps.
    void print(std::FILE* out) const;

private:
    std::vector<std::string> m_names;
    std::vector<const iPhysicsFrame*> m_bodies;
};
