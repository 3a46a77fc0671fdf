// FrameDriver.h - reading and writing a game's frame through the course framework's own iFrame members.
//
// A course project brings its own iFrame and Frame, which have no "set world transform". The simulator
// therefore moves a frame with members every version of the framework has: orient(), rotation(),
// position(), translate() and world(). Scale in the frame's own T is dropped (physics is rigid).
#pragma once

#include "MathDeclarations.h"

class iFrame;

namespace physics {

// Puts frame's origin at `origin` and turns it to `rotation` (row-vector, world space), whatever its parent.
void setFrameWorldPose(iFrame* frame, const Matrix& rotation, const Vector& origin);
// The frame's world rotation with any scale removed, and its origin.
Matrix frameWorldRotation(const iFrame* frame);

} // namespace physics
