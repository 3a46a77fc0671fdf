// RecordingDraw.h - a recorded frame drawn through an iDebugDraw as the live scene draws itself
// (iDebugDrawable.h), without the engine: --replay --image makes its pictures with it.
//
// It draws what the game's --image asks of the live scene, DEBUGDRAW_Default: shapes (a plane as the same
// grid patch under the rest), contact points and normals, and sleeping bodies (blue, "zz" at their centre).
// The calls, their order and their numbers are those of Collision/SpaceDebugDraw.cpp and
// Physics/SceneDebugDraw.cpp, so the same SvgDebugDraw writes the same bytes (ctest game_tests:
// GameReplay.*). Other flags (bounds, axes, islands) are not recorded and are ignored.
#pragma once

#include "RecordingReader.h"
#include "iDebugDraw.h"

// The flags drawRecordedFrame honours.
constexpr unsigned kRecordingDrawFlags = DEBUGDRAW_Default;

// Draws frame f of a recording whose shapes (in build order) are shapes.
void drawRecordedFrame(iDebugDraw& out, const std::vector<RecordedShape>& shapes, const RecordedFrame& f,
                       unsigned flags = kRecordingDrawFlags);
