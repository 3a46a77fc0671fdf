// iFrame.h - the stand-in framework's reference frame: a homogeneous transform T relative to an optional
// parent (the course framework's iFrame).
//
// A course project has its own iFrame.h; the packages never overwrite it. The engine drives a frame with the
// framework's own members only: world() to read it, orient(), rotation(), position() and translate() to move
// it (Physics/FrameDriver.cpp). Row-vector convention: world = T * parent->world(), translation in the
// m41..m43 row (see MathDeclarations.h).
#pragma once

#include "MathDeclarations.h"

class iFrame {
public:
    // Transforms applied to T in parent space (rotations about the frame's own origin).
    virtual void translate(float x, float y, float z) = 0;
    virtual void scale(float x, float y, float z) = 0;
    virtual void rotatex(float rad) = 0;
    virtual void rotatey(float rad) = 0;
    virtual void rotatez(float rad) = 0;
    virtual void rotate(const Vector& axis, float rad) = 0;
    virtual void rotate(const Matrix& rot) = 0;
    virtual void orient(const Matrix& rot) = 0; // replaces T's rotation, keeps its translation
    // World-space queries (through the parent chain).
    virtual Vector position() const = 0;                   // world position of the frame's origin
    virtual Matrix rotation() const = 0;                   // world rotation (no translation)
    virtual Vector orientation(char axis) const = 0;       // local 'x', 'y' or 'z' axis in world space
    virtual Vector orientation(const Vector& v) const = 0; // local direction v in world space
    virtual Matrix world() const = 0;                      // the full world transform
    virtual Vector relativePosition() const = 0;           // T's translation (parent space)
    // Attaching keeps the world pose (T is re-expressed relative to the new parent); nullptr detaches.
    // Attaching to itself or to one of its own descendants is refused with error().
    virtual void attachTo(iFrame* newParent) = 0;
    virtual iFrame* parent() const = 0;
    // Destroys this frame. Detach or delete any frame attached to it first.
    virtual void Delete() const = 0;
};

// CreateFrame() is declared with the concrete Frame, in Frame.h.
