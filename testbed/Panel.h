// Panel.h - the testbed's controls and counters: an ImGui window with the scene list, pause / step / reset,
// the knobs, the debug-draw switches and the counters, plus the debug drawing's text over the picture.
#pragma once

#include "iDebugDraw.h"

class Simulation;
class OrbitCamera;
class GlDebugDraw;

// What the user asked for this frame, and what stays between frames.
struct PanelState {
    bool paused = false;
    unsigned flags = DEBUGDRAW_Default; // DebugDrawFlag values
    bool stepRequested = false;         // one physics step (pauses)
    bool resetRequested = false;
    bool screenshotRequested = false; // F12: testbed-NNN.png in the working directory
    int sceneRequested = -1;          // an index into testbedScenes(), or -1
    int scene = 0;                    // the index of the scene shown
};

// Draws the panel (inside an ImGui frame) and applies knob changes to sim at once; scene changes, steps and
// resets are left in state for the caller. fps: frames per second of the window.
void drawPanel(PanelState& state, Simulation& sim, float fps);
// Writes each collected text at its point's pixel (ImGui's background draw list; inside an ImGui frame).
void drawDebugTexts(const GlDebugDraw& draw, const OrbitCamera& camera, int width, int height);
