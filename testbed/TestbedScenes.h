// TestbedScenes.h - the scenes the testbed lists: every reference-game scene (allScenes()), then the
// testbed's own "probe", a picture with one thing at a known place for the screenshot test.
#pragma once

#include "MathDeclarations.h"
#include "Scenes.h"

#include <string>
#include <vector>

// The probe: one fixed box (drawn in debugcolour::kFixed) with this centre and these half extents, axis
// aligned, and nothing else. tests/testbed/CMakeLists.txt states the same numbers to its checker.
const Vector kProbeCentre(2.0f, 1.0f, 0.0f);
const Vector kProbeHalfExtents(0.75f, 0.5f, 0.5f);

const std::vector<SceneSpec>& testbedScenes();
const SceneSpec* findTestbedScene(const std::string& name);
