// TestbedScenes.cpp - the reference game's scenes plus the testbed's probe (TestbedScenes.h).
#include "TestbedScenes.h"

#include "World.h"

namespace {
void buildProbe(World& world) { world.fixedBox(kProbeCentre, kProbeHalfExtents); }
} // namespace

const std::vector<SceneSpec>& testbedScenes() {
    static const std::vector<SceneSpec> scenes = [] {
        std::vector<SceneSpec> all(allScenes().begin(), allScenes().end());
        all.push_back({"probe", "one fixed box at a known place (the screenshot test)", buildProbe, nullptr});
        return all;
    }();
    return scenes;
}

const SceneSpec* findTestbedScene(const std::string& name) {
    for (const SceneSpec& s : testbedScenes())
        if (name == s.name) return &s;
    return nullptr;
}
