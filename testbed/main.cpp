// main.cpp - the testbed: a window that runs the demo scenes with the course engine loop (input, then
// physicsScene->update(now) with now in milliseconds from a clock, then drawing through iDebugDraw), with
// controls to pause, step, reset and turn the knobs.
//
// Usage: Testbed [--scene NAME] [--frames N --screenshot FILE.ppm|FILE.png] [--size WxH]
//                [--eye X,Y,Z --target X,Y,Z] [--no-ui] [--list] [--help]
// With --frames the run is headless in spirit: N frames on a stepped 16 ms clock, no input, then the
// framebuffer is written to the screenshot file and the program exits (0, or 1 when it cannot write).
// Exit status 2: bad arguments; 3: no window (no display, no OpenGL).
#include "GlDebugDraw.h"
#include "Input.h"
#include "OrbitCamera.h"
#include "Panel.h"
#include "Screenshot.h"
#include "Simulation.h"
#include "TestbedScenes.h"
#include "iClock.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl2.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

const char* const kUsage =
    "usage: Testbed [--scene NAME] [--frames N --screenshot FILE] [--size WxH] [--eye X,Y,Z --target X,Y,Z]\n"
    "               [--no-ui] [--list] [--help]\n"
    "  --scene NAME       the scene to start with (default: pyramid; --list names them)\n"
    "  --frames N         run N frames on a stepped 16 ms clock without input, write --screenshot, exit\n"
    "  --screenshot FILE  the picture after the last frame: binary PPM, or PNG when FILE ends in .png\n"
    "  --size WxH         the window's size in pixels (default 1280x720)\n"
    "  --eye X,Y,Z        the camera's position and the point it looks at (default: framing the scene)\n"
    "  --target X,Y,Z\n"
    "  --no-ui            no panel: only the scene\n"
    "Mouse: drag to turn the camera, drag a body to pull it, wheel to zoom, right click to shoot a sphere.\n"
    "Keys: space pause/run, n one step, r reset, F12 screenshot (testbed-NNN.png).\n";

struct Options {
    std::string scene = "pyramid", screenshot;
    int frames = 0, width = 1280, height = 720;
    bool haveEye = false, haveTarget = false, ui = true;
    Vector eye, target;
};

bool parseVector(const char* text, Vector& v) { return std::sscanf(text, "%f,%f,%f", &v.x, &v.y, &v.z) == 3; }

// 0: run; 1: printed what was asked (exit 0); 2: bad arguments.
int parse(int argc, char** argv, Options& o) {
    for (int i = 1; i < argc; ++i) {
        const char* a = argv[i];
        const bool more = i + 1 < argc;
        if (!std::strcmp(a, "--scene") && more) {
            o.scene = argv[++i];
        } else if (!std::strcmp(a, "--frames") && more) {
            o.frames = std::atoi(argv[++i]);
            if (o.frames <= 0) return 2;
        } else if (!std::strcmp(a, "--screenshot") && more) {
            o.screenshot = argv[++i];
        } else if (!std::strcmp(a, "--size") && more) {
            if (std::sscanf(argv[++i], "%dx%d", &o.width, &o.height) != 2 || o.width < 16 || o.height < 16)
                return 2;
        } else if (!std::strcmp(a, "--eye") && more) {
            if (!(o.haveEye = parseVector(argv[++i], o.eye))) return 2;
        } else if (!std::strcmp(a, "--target") && more) {
            if (!(o.haveTarget = parseVector(argv[++i], o.target))) return 2;
        } else if (!std::strcmp(a, "--no-ui")) {
            o.ui = false;
        } else if (!std::strcmp(a, "--list")) {
            for (const SceneSpec& s : testbedScenes()) std::printf("%-10s %s\n", s.name, s.description);
            return 1;
        } else if (!std::strcmp(a, "--help") || !std::strcmp(a, "-h")) {
            std::fputs(kUsage, stdout);
            return 1;
        } else {
            return 2;
        }
    }
    if (o.haveEye != o.haveTarget || (o.frames > 0) != !o.screenshot.empty()) return 2;
    return 0;
}

// Looks at the middle of the scene's bodies from the front, above and to the left; with the panel on the
// left, the scene moves right to keep clear of it.
void frameScene(const Simulation& sim, OrbitCamera& camera, bool panel) {
    Vector lo(-3, 0, -3), hi(3, 3, 3);
    sim.bounds(lo, hi);
    const Vector centre = (lo + hi) * 0.5f;
    const float size = std::max(3.0f, (hi - lo).length());
    const Vector eye = centre + normal(Vector(-0.5f, 0.45f, -1.0f)) * (size * 1.3f + 4.0f);
    const Vector right = normal(cross(Vector(0, 1, 0), centre - eye));
    const Vector shift = panel ? right * (-0.3f * size) : Vector();
    camera.lookAt(eye + shift, centre + shift);
}

// The background: tests/testbed/CMakeLists.txt gives the screenshot checker the same colour (1A1F2E).
const float kClear[3] = {0.10f, 0.12f, 0.18f};

int indexOf(const SceneSpec* spec) {
    const auto& scenes = testbedScenes();
    for (size_t i = 0; i < scenes.size(); ++i)
        if (&scenes[i] == spec) return int(i);
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    Options o;
    if (int r = parse(argc, argv, o)) {
        if (r == 2) std::fputs(kUsage, stderr);
        return r == 2 ? 2 : 0;
    }
    const SceneSpec* spec = findTestbedScene(o.scene);
    if (!spec) {
        std::fprintf(stderr, "Testbed: no scene '%s' (try --list)\n", o.scene.c_str());
        return 2;
    }
    const bool headless = o.frames > 0;
    glfwSetErrorCallback([](int, const char* what) { std::fprintf(stderr, "Testbed: GLFW: %s\n", what); });
    if (!glfwInit()) {
        std::fputs("Testbed: cannot open a window (no display?)\n", stderr);
        return 3;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
    glfwWindowHint(GLFW_RESIZABLE, headless ? GLFW_FALSE : GLFW_TRUE);
    GLFWwindow* window = glfwCreateWindow(o.width, o.height, "Guardian Physics testbed", nullptr, nullptr);
    if (!window) {
        std::fputs("Testbed: cannot create an OpenGL 2.1 window\n", stderr);
        glfwTerminate();
        return 3;
    }
    glfwMakeContextCurrent(window);
    glfwSwapInterval(headless ? 0 : 1);
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr; // no imgui.ini beside the program
    ImGui::StyleColorsDark();
    latchKeys(window); // before the backend, which chains to it
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL2_Init();

    int status = 0;
    {
        Simulation sim(*spec, Knobs());
        OrbitCamera camera;
        if (o.haveEye)
            camera.lookAt(o.eye, o.target);
        else
            frameScene(sim, camera, o.ui);
        PanelState state;
        state.scene = indexOf(spec);
        GlDebugDraw draw;
        int screenshots = 0;
        iClock* clock = headless ? CreateSteppedClock(16) : CreateRealClock();
        for (int frame = 1; !glfwWindowShouldClose(window); ++frame) {
            glfwPollEvents();
            clock->tick();
            int width = 0, height = 0;
            glfwGetFramebufferSize(window, &width, &height);
            ImGui_ImplOpenGL2_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            ImGui::NewFrame();
            if (!headless) handleInput(state, sim, camera, width, height);
            if (o.ui) drawPanel(state, sim, ImGui::GetIO().Framerate);
            if (state.sceneRequested >= 0) {
                state.scene = state.sceneRequested;
                state.sceneRequested = -1;
                sim.load(testbedScenes()[size_t(state.scene)]);
                frameScene(sim, camera, o.ui);
            }
            if (state.resetRequested) sim.reset();
            if (state.stepRequested) {
                state.paused = true;
                sim.singleStep();
            }
            state.resetRequested = state.stepRequested = false;
            sim.frame(clock->now(), state.paused); // physicsScene->update(now)

            draw.clear();
            sim.draw(draw, state.flags);
            if (sim.spring().holding())
                draw.drawLine(sim.spring().anchor(), sim.spring().target(), 0xFFFFFFFFu);
            glViewport(0, 0, width, height);
            glClearColor(kClear[0], kClear[1], kClear[2], 1.0f);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            draw.render(camera.glViewProjection(width, height));
            drawDebugTexts(draw, camera, width, height);
            ImGui::Render();
            ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
            if (state.screenshotRequested) {
                char name[32];
                std::snprintf(name, sizeof name, "testbed-%03d.png", ++screenshots);
                if (writeScreenshot(name, width, height)) std::printf("Testbed: wrote %s\n", name);
                std::fflush(stdout);
                state.screenshotRequested = false;
            }
            if (headless && frame >= o.frames) {
                status = writeScreenshot(o.screenshot, width, height) ? 0 : 1;
                break;
            }
            glfwSwapBuffers(window);
        }
        clock->Delete();
    }
    ImGui_ImplOpenGL2_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window);
    glfwTerminate();
    return status;
}
