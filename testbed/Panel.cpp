// Panel.cpp - the ImGui controls, counters and debug-draw text (Panel.h).
#include "Panel.h"

#include "GlDebugDraw.h"
#include "OrbitCamera.h"
#include "Simulation.h"
#include "TestbedScenes.h"

#include "iPhysicsSceneProfile.h"

#include <imgui.h>

namespace {

const char* const kIntegrators[] = {"semi-implicit Euler", "explicit Euler", "velocity Verlet", "RK4"};

struct FlagName {
    unsigned flag;
    const char* name;
};
const FlagName kFlags[] = {
    {DEBUGDRAW_Shapes, "shapes"},
    {DEBUGDRAW_Bounds, "bounds"},
    {DEBUGDRAW_ContactPoints, "contact points"},
    {DEBUGDRAW_ContactNormals, "contact normals"},
    {DEBUGDRAW_Sleeping, "sleeping"},
    {DEBUGDRAW_Islands, "islands"},
    {DEBUGDRAW_BodyAxes, "body axes"},
};

// Where the scene's step time went (iPhysicsSceneProfile): ms per phase, summed over the update's steps.
void phases(Simulation& sim) {
    const iPhysicsSceneProfile* profile = sim.scene() ? profileOf(sim.scene()) : nullptr;
    if (!profile) return;
    const PhysicsProfile& p = profile->getProfile();
    const struct {
        const char* name;
        double seconds;
    } rows[] = {{"updaters", p.updaters},
                {"edits", p.edits},
                {"collision", p.collision},
                {"islands", p.islands},
                {"integration", p.integration},
                {"solver", p.solver},
                {"continuous", p.continuous},
                {"sleeping", p.sleeping},
                {"events", p.events}};
    ImGui::Text("%d steps, %.3f ms in all", p.steps, p.total * 1000.0);
    for (const auto& r : rows) ImGui::Text("  %-12s %8.3f ms", r.name, r.seconds * 1000.0);
    ImGui::Text("pairs %zu   solver rows %zu", p.touchingPairs, p.solverRows);
}

void knobs(Simulation& sim) {
    Knobs k = sim.knobs();
    int integrator = int(k.integrator) - int(INTEGRATOR_SemiImplicitEuler);
    bool changed = ImGui::Combo("integrator", &integrator, kIntegrators, IM_ARRAYSIZE(kIntegrators));
    k.integrator = Integrator(integrator + int(INTEGRATOR_SemiImplicitEuler));
    changed |= ImGui::SliderInt("step rate (Hz)", &k.stepRate, 10, 480);
    changed |= ImGui::SliderInt("iterations", &k.solverIterations, 1, 50);
    changed |= ImGui::SliderInt("samples / s", &k.samplesPerSecond, 0, 240);
    int space = k.octree ? 1 : 0;
    changed |= ImGui::RadioButton("simple space", &space, 0);
    ImGui::SameLine();
    changed |= ImGui::RadioButton("octree space", &space, 1);
    k.octree = space == 1;
    changed |= ImGui::Checkbox("sleeping", &k.sleeping);
    ImGui::SameLine();
    changed |= ImGui::Checkbox("continuous", &k.continuous);
    if (changed) sim.setKnobs(k);
}

} // namespace

void drawPanel(PanelState& state, Simulation& sim, float fps) {
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(360, 0), ImGuiCond_FirstUseEver);
    ImGui::Begin("Guardian testbed");
    if (ImGui::CollapsingHeader("scene", ImGuiTreeNodeFlags_DefaultOpen)) {
        const auto& scenes = testbedScenes();
        for (int i = 0; i < int(scenes.size()); ++i) {
            if (ImGui::Selectable(scenes[size_t(i)].name, state.scene == i)) state.sceneRequested = i;
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", scenes[size_t(i)].description);
        }
    }
    if (ImGui::Button(state.paused ? "run (space)" : "pause (space)")) state.paused = !state.paused;
    ImGui::SameLine();
    if (ImGui::Button("step (n)")) state.stepRequested = true;
    ImGui::SameLine();
    if (ImGui::Button("reset (r)")) state.resetRequested = true;
    if (ImGui::CollapsingHeader("knobs", ImGuiTreeNodeFlags_DefaultOpen)) knobs(sim);
    if (ImGui::CollapsingHeader("debug draw", ImGuiTreeNodeFlags_DefaultOpen))
        for (const FlagName& f : kFlags) ImGui::CheckboxFlags(f.name, &state.flags, f.flag);
    if (ImGui::CollapsingHeader("counters", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::Text("bodies %zu   awake %zu   contacts %zu", sim.bodyCount(), sim.awakeCount(),
                    sim.contactCount());
        ImGui::Text("steps %lld   now %d ms", sim.stepCount(), sim.now());
        ImGui::Text("update() %.3f ms (%d steps)   %.0f fps", sim.lastUpdateMs(), sim.stepsLastFrame(),
                    double(fps));
    }
    if (ImGui::CollapsingHeader("phases (last update that stepped)", ImGuiTreeNodeFlags_DefaultOpen))
        phases(sim);
    ImGui::TextDisabled("drag: turn (on a body: pull it)  wheel: zoom");
    ImGui::TextDisabled("right click: shoot a sphere");
    ImGui::End();
}

void drawDebugTexts(const GlDebugDraw& draw, const OrbitCamera& camera, int width, int height) {
    ImDrawList* list = ImGui::GetBackgroundDrawList();
    for (const GlDebugDraw::Text& t : draw.texts()) {
        float x = 0, y = 0;
        if (!camera.toPixel(t.at, width, height, x, y)) continue;
        const DebugColour c = t.colour;
        list->AddText(ImVec2(x, y), IM_COL32((c >> 16) & 0xFF, (c >> 8) & 0xFF, c & 0xFF, (c >> 24) & 0xFF),
                      t.text.c_str());
    }
}
