// OrbitCamera.cpp - the orbit camera's angles, matrices, rays and projection (OrbitCamera.h).
#include "OrbitCamera.h"

#include "MathDefinitions.h"

#include <algorithm>
#include <cmath>

namespace {
const float kMaxPitch = 1.5533430f; // 89 degrees
}

void OrbitCamera::lookAt(const Vector& eye, const Vector& target) {
    const Vector d = target - eye;
    m_target = target;
    m_distance = std::max(d.length(), 1e-3f);
    const Vector f = d / m_distance;
    m_pitch = std::asin(std::max(-1.0f, std::min(1.0f, -f.y)));
    m_yaw = std::atan2(f.x, f.z);
}

void OrbitCamera::orbit(float yawDelta, float pitchDelta) {
    m_yaw += yawDelta;
    m_pitch = std::max(-kMaxPitch, std::min(kMaxPitch, m_pitch + pitchDelta));
}

void OrbitCamera::zoom(float factor) { m_distance = std::max(0.5f, std::min(2000.0f, m_distance * factor)); }

Vector OrbitCamera::forward() const {
    const float c = std::cos(m_pitch);
    return Vector(std::sin(m_yaw) * c, -std::sin(m_pitch), std::cos(m_yaw) * c);
}

Vector OrbitCamera::eye() const { return m_target - forward() * m_distance; }

Matrix OrbitCamera::view() const { return ::view(eye(), m_target, Vector(0, 1, 0)); }

Matrix OrbitCamera::projection(int width, int height) const {
    return ::projection(m_fovY, float(width) / float(std::max(height, 1)), kNear, kFar);
}

Matrix OrbitCamera::glViewProjection(int width, int height) const {
    // Direct3D's depth 0..1 to OpenGL's -1..1: z' = 2 z - w.
    Matrix depth(1);
    depth(2, 2) = 2.0f;
    depth(3, 2) = -1.0f;
    return view() * projection(width, height) * depth;
}

void OrbitCamera::ray(float x, float y, int width, int height, Vector& origin, Vector& direction) const {
    const float ndcX = 2.0f * x / float(width) - 1.0f, ndcY = 1.0f - 2.0f * y / float(height);
    const float sy = std::tan(m_fovY * 0.5f), sx = sy * float(width) / float(std::max(height, 1));
    const Vector f = forward();
    const Vector right = normal(cross(Vector(0, 1, 0), f)), up = cross(f, right);
    origin = eye();
    direction = normal(f + right * (ndcX * sx) + up * (ndcY * sy));
}

bool OrbitCamera::toPixel(const Vector& p, int width, int height, float& x, float& y) const {
    const Matrix m = view() * projection(width, height);
    const float w = p.x * m.m14 + p.y * m.m24 + p.z * m.m34 + m.m44;
    if (w <= kNear * 0.5f) return false;
    const float cx = p.x * m.m11 + p.y * m.m21 + p.z * m.m31 + m.m41;
    const float cy = p.x * m.m12 + p.y * m.m22 + p.z * m.m32 + m.m42;
    x = (cx / w + 1.0f) * 0.5f * float(width);
    y = (1.0f - cy / w) * 0.5f * float(height);
    return true;
}
