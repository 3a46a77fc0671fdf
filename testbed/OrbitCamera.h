// OrbitCamera.h - the testbed's camera: it orbits a target point (yaw about world y, pitch up and down,
// distance), and gives the view and projection matrices the window draws with, the world point under a
// pixel (a ray, for picking and shooting) and the pixel of a world point.
//
// The matrices are the course framework's (view() and projection() in MathDefinitions.h: row vectors,
// left-handed, y up, depth 0..1), so what the testbed shows is what a course project shows.
#pragma once

#include "MathDeclarations.h"

class OrbitCamera {
public:
    // Looks from eye at target (eye != target).
    void lookAt(const Vector& eye, const Vector& target);
    // Mouse drag: turn about the target by these angles (radians); pitch is kept within +-89 degrees.
    void orbit(float yawDelta, float pitchDelta);
    // Wheel: scale the distance (factor < 1 moves closer), kept within 0.5 .. 2000 m.
    void zoom(float factor);

    Vector eye() const;
    Vector target() const { return m_target; }
    Vector forward() const; // unit, from the eye towards the target
    float fovY() const { return m_fovY; }
    void setFovY(float radians) { m_fovY = radians; }

    // Row-vector matrices (p * view * projection), for a viewport of width x height pixels.
    Matrix view() const;
    Matrix projection(int width, int height) const;
    // The same, with depth mapped to OpenGL's -1..1: load it with glLoadMatrixf(m.data()) (a row-vector
    // matrix stored row by row is the column-vector matrix stored column by column).
    Matrix glViewProjection(int width, int height) const;

    // The ray through pixel (x, y) (from the top left corner, y down): origin at the eye, unit direction.
    void ray(float x, float y, int width, int height, Vector& origin, Vector& direction) const;
    // The pixel of a world point; false when it is behind the eye.
    bool toPixel(const Vector& p, int width, int height, float& x, float& y) const;

    static constexpr float kNear = 0.1f, kFar = 2000.0f;

private:
    Vector m_target;
    float m_yaw = 0.0f;   // 0: looking along +z
    float m_pitch = 0.3f; // positive: looking down
    float m_distance = 20.0f;
    float m_fovY = 0.7853982f; // 45 degrees
};
