// Input.cpp - turning mouse and keys into camera moves, grabs, shots and commands (Input.h).
#include "Input.h"

#include "OrbitCamera.h"
#include "Panel.h"
#include "Simulation.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cmath>
#include <vector>

namespace {
const float kRadiansPerPixel = 0.006f;
const float kZoomPerNotch = 0.88f;
const float kClickPixels = 4.0f; // a right button that moved less than this clicked (shoots), else dragged
bool g_orbiting = false;         // the left drag that started on empty space turns the camera
std::vector<int> g_keys;         // keys pressed (or repeating) since the last frame, in order
} // namespace

void latchKeys(GLFWwindow* window) {
    glfwSetKeyCallback(window, [](GLFWwindow*, int key, int, int action, int) {
        if (action != GLFW_RELEASE) g_keys.push_back(key);
    });
}

void handleInput(PanelState& state, Simulation& sim, OrbitCamera& camera, int width, int height) {
    ImGuiIO& io = ImGui::GetIO();
    Vector origin, direction;
    camera.ray(io.MousePos.x, io.MousePos.y, width, height, origin, direction);
    MouseSpring& spring = sim.spring();

    if (!io.WantCaptureMouse) {
        if (ImGui::IsMouseClicked(ImGuiMouseButton_Left))
            g_orbiting = !sim.grab(origin, direction, camera.forward());
        if (ImGui::IsMouseReleased(ImGuiMouseButton_Right)) {
            const ImVec2 moved = ImGui::GetMouseDragDelta(ImGuiMouseButton_Right, 0.0f);
            if (moved.x * moved.x + moved.y * moved.y < kClickPixels * kClickPixels)
                sim.shoot(origin, direction);
        }
        if (io.MouseWheel != 0.0f) camera.zoom(std::pow(kZoomPerNotch, io.MouseWheel));
    }
    const bool rightDrag = ImGui::IsMouseDragging(ImGuiMouseButton_Right) && !io.WantCaptureMouse;
    if ((g_orbiting && ImGui::IsMouseDown(ImGuiMouseButton_Left)) || rightDrag)
        camera.orbit(io.MouseDelta.x * kRadiansPerPixel, io.MouseDelta.y * kRadiansPerPixel);
    if (spring.holding()) {
        if (ImGui::IsMouseDown(ImGuiMouseButton_Left))
            spring.drag(origin, direction);
        else
            spring.release();
    }
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) g_orbiting = false;

    for (int key : g_keys) {
        if (io.WantCaptureKeyboard) break;
        if (key == GLFW_KEY_SPACE) state.paused = !state.paused;
        if (key == GLFW_KEY_N) state.stepRequested = true; // held: one step per repeat
        if (key == GLFW_KEY_R) state.resetRequested = true;
        if (key == GLFW_KEY_F12) state.screenshotRequested = true;
    }
    g_keys.clear();
}
