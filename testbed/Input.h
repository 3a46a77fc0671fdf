// Input.h - the mouse and keyboard in the scene (what ImGui's panel does not take): drag to orbit the
// camera, drag on a body to pull it with the mouse spring, wheel to zoom, right click to shoot a sphere,
// space / n / r to pause, step and reset, F12 to save a screenshot.
#pragma once

class Simulation;
class OrbitCamera;
struct PanelState;

// Reads this frame's input from ImGui's IO (inside an ImGui frame, after NewFrame) for a viewport of
// width x height pixels.
void handleInput(PanelState& state, Simulation& sim, OrbitCamera& camera, int width, int height);
