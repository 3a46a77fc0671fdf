// Input.h - the mouse and keyboard in the scene (what ImGui's panel does not take): drag to orbit the
// camera, drag on a body to pull it with the mouse spring, wheel to zoom, right click to shoot a sphere,
// space / n / r to pause, step and reset, F12 to save a screenshot.
#pragma once

struct GLFWwindow;
class Simulation;
class OrbitCamera;
struct PanelState;

// Keeps every key press of window until the next handleInput, so that a key tapped within one frame
// counts (ImGui 1.86 only sees keys down at the start of a frame). Call before ImGui_ImplGlfw_InitForOpenGL,
// which passes the key events on to this callback.
void latchKeys(GLFWwindow* window);
// Reads this frame's input from ImGui's IO (inside an ImGui frame, after NewFrame) for a viewport of
// width x height pixels.
void handleInput(PanelState& state, Simulation& sim, OrbitCamera& camera, int width, int height);
