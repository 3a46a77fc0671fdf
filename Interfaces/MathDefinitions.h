// MathDefinitions.h - the inline operations of Vector and Matrix, and the framework's camera helpers.
//
// Plain C++, as the course framework's own MathDefinitions.h, of which this is a superset: a course project
// may overwrite its copy with this one. The few operations that need a numerical library (general inverse,
// nearest rotation, inertia of point sets) are declared in MathDeclarations.h and defined once, with Eigen
// inside, in GuardianMath.cpp. See MathDeclarations.h for the conventions (row vectors, translation in
// m41..m43, left-handed, y up).
// The framework's own include guard, not #pragma once: a project may hold this file twice (its copy and
// the package's Interfaces/ copy), and the guard keeps the two from both expanding.
#ifndef _MATH_DEFINITIONS_H_
#define _MATH_DEFINITIONS_H_

#include "MathDeclarations.h"

#include <cmath>

// The framework's GeneralConstants.h (MODEL_Z_AXIS) comes along, as with the framework's own file.
#if defined(__has_include)
#if __has_include("GeneralConstants.h")
#include "GeneralConstants.h"
#endif
#endif
#if defined(MODEL_Z_AXIS)
static_assert(MODEL_Z_AXIS == 1,
              "Guardian Physics supports MODEL_Z_AXIS NEAR_TO_FAR (the framework default) only");
#endif

// --- Vector ---
inline float Vector::length() const { return std::sqrt(lengthSquared()); }
inline Vector Vector::normalize() const {
    float len = length();
    return len > 0.0f ? Vector(x / len, y / len, z / len) : Vector();
}
inline bool Vector::isFinite() const { return std::isfinite(x) && std::isfinite(y) && std::isfinite(z); }
inline Vector& Vector::operator*=(const Matrix& m) { return *this = *this * m; }
inline float length(const Vector& v) { return v.length(); }
inline Vector normal(const Vector& v) { return v.normalize(); }
inline Vector projectOnTo(const Vector& a, const Vector& b) {
    float bb = dot(b, b);
    return bb > 0.0f ? b * (dot(a, b) / bb) : Vector();
}

// --- Matrix members ---
inline Matrix& Matrix::isIdentity() { return *this = Matrix(1); }
inline Matrix& Matrix::operator+=(const Matrix& a) {
    for (int i = 0; i < 16; ++i) data()[i] += a.data()[i];
    return *this;
}
inline Matrix& Matrix::operator-=(const Matrix& a) {
    for (int i = 0; i < 16; ++i) data()[i] -= a.data()[i];
    return *this;
}
inline Matrix& Matrix::operator*=(const Matrix& a) { return *this = *this * a; }
inline Matrix Matrix::transpose() const {
    return Matrix(m11, m21, m31, m41, m12, m22, m32, m42, m13, m23, m33, m43, m14, m24, m34, m44);
}
inline bool Matrix::isFinite() const {
    for (int i = 0; i < 16; ++i)
        if (!std::isfinite(data()[i])) return false;
    return true;
}
inline Matrix& Matrix::translate(float x, float y, float z) { return *this = *this * ::translation(x, y, z); }
// Applies r about this transform's own origin: T = T * r with the translation row restored.
inline Matrix& Matrix::rotate(const Matrix& r) {
    Vector t = position();
    *this = *this * r.rotation();
    m41 = t.x;
    m42 = t.y;
    m43 = t.z;
    return *this;
}
inline Matrix& Matrix::rotatex(float rad) { return rotate(::rotatex(rad)); }
inline Matrix& Matrix::rotatey(float rad) { return rotate(::rotatey(rad)); }
inline Matrix& Matrix::rotatez(float rad) { return rotate(::rotatez(rad)); }
inline Matrix& Matrix::rotate(const Vector& axis, float rad) { return rotate(::rotate(axis, rad)); }
inline Matrix& Matrix::scale(float x, float y, float z) { return rotate(Matrix(Vector(x, y, z))); }
inline Matrix& Matrix::orient(const Matrix& rot) {
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) (*this)(r, c) = rot(r, c);
    return *this;
}
inline Matrix Matrix::rotation() const {
    return Matrix(m11, m12, m13, 0, m21, m22, m23, 0, m31, m32, m33, 0, 0, 0, 0, 1);
}
inline Vector Matrix::direction(const Vector& v) const {
    return Vector(v.x * m11 + v.y * m21 + v.z * m31, v.x * m12 + v.y * m22 + v.z * m32,
                  v.x * m13 + v.y * m23 + v.z * m33);
}
inline Vector Matrix::direction(char axis) const {
    int row = axis == 'x' || axis == 'X' ? 0 : axis == 'y' || axis == 'Y' ? 1 : 2;
    return Vector((*this)(row, 0), (*this)(row, 1), (*this)(row, 2));
}

// --- free operators ---
inline Matrix operator*(const Matrix& a, const Matrix& b) {
    Matrix out;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            out(r, c) = a(r, 0) * b(0, c) + a(r, 1) * b(1, c) + a(r, 2) * b(2, c) + a(r, 3) * b(3, c);
    return out;
}
inline Matrix operator+(const Matrix& a, const Matrix& b) { return Matrix(a) += b; }
inline Matrix operator-(const Matrix& a, const Matrix& b) { return Matrix(a) -= b; }
inline Matrix operator*(const Matrix& a, float s) {
    Matrix out(a);
    for (int i = 0; i < 16; ++i) out.data()[i] *= s;
    return out;
}
// Row vector (v, 1) times M, no perspective divide.
inline Vector operator*(const Vector& v, const Matrix& m) { return m.direction(v) + m.position(); }
inline Vector operator*(const Matrix& a, const Vector& b) {
    return Vector(a.m11 * b.x + a.m12 * b.y + a.m13 * b.z + a.m14,
                  a.m21 * b.x + a.m22 * b.y + a.m23 * b.z + a.m24,
                  a.m31 * b.x + a.m32 * b.y + a.m33 * b.z + a.m34);
}
inline bool operator==(const Matrix& a, const Matrix& b) {
    for (int i = 0; i < 16; ++i)
        if (a.data()[i] != b.data()[i]) return false;
    return true;
}

// --- generators ---
// Rodrigues' rotation written for row vectors: p * rotate(k, a) = p cos a + (k x p) sin a + k (k.p)(1 - cos
// a). rotatex/y/z are the same rotations about the unit axes (the D3DXMatrixRotationX layout).
inline Matrix rotate(const Vector& axis, float rad) {
    Vector k = axis.normalize();
    if (k.lengthSquared() == 0.0f) return Matrix(1);
    float c = std::cos(rad), s = std::sin(rad), t = 1.0f - c;
    return Matrix(t * k.x * k.x + c, t * k.x * k.y + k.z * s, t * k.x * k.z - k.y * s, 0,
                  t * k.x * k.y - k.z * s, t * k.y * k.y + c, t * k.y * k.z + k.x * s, 0,
                  t * k.x * k.z + k.y * s, t * k.y * k.z - k.x * s, t * k.z * k.z + c, 0, 0, 0, 0, 1);
}
inline Matrix rotatex(float rad) { return rotate(Vector(1, 0, 0), rad); }
inline Matrix rotatey(float rad) { return rotate(Vector(0, 1, 0), rad); }
inline Matrix rotatez(float rad) { return rotate(Vector(0, 0, 1), rad); }
inline Matrix translation(float x, float y, float z) {
    Matrix m(1);
    m.m41 = x;
    m.m42 = y;
    m.m43 = z;
    return m;
}
inline Vector position(const Matrix& m) { return m.position(); }
inline Matrix rotation(const Matrix& m) { return m.rotation(); }

// --- the framework's camera and scaling helpers ---
inline Matrix& scale(Matrix& m, float x, float y, float z) { return m = Matrix(Vector(x, y, z)); }
inline Matrix& scale(Matrix& m, const Vector& v) { return scale(m, v.x, v.y, v.z); }
inline Matrix view(const Vector& p, const Vector& d, const Vector& u) {
    Vector z = normal(d - p);
    Vector x = normal(cross(u, z));
    Vector y = cross(z, x);
    return Matrix(x.x, y.x, z.x, 0, x.y, y.y, z.y, 0, x.z, y.z, z.z, 0, -dot(x, p), -dot(y, p), -dot(z, p),
                  1);
}
inline Matrix projection(float fov, float aspect, float nearCp, float farCp) {
    float sy = 1.0f / std::tan(fov * 0.5f);
    float sx = sy / aspect;
    float sz = farCp / (farCp - nearCp);
    return Matrix(sx, 0, 0, 0, 0, sy, 0, 0, 0, 0, sz, 1, 0, 0, -nearCp * sz, 0);
}
inline Matrix projection(float minx, float maxx, float miny, float maxy, float nearCp, float farCp) {
    float sy = 2 * nearCp / (maxy - miny);
    float sx = 2 * nearCp / (maxx - minx);
    float zx = (minx + maxx) / (maxx - minx);
    float zy = (miny + maxy) / (maxy - miny);
    float sz = farCp / (farCp - nearCp);
    return Matrix(sx, 0, 0, 0, 0, sy, 0, 0, zx, zy, sz, 1, 0, 0, -nearCp * sz, 0);
}
inline Matrix projToRhs(const Matrix& m) {
    return Matrix(m.m11, m.m12, m.m13, 0, m.m21, m.m22, m.m23, 0, m.m31, m.m32, m.m33, -m.m43, m.m41, m.m42,
                  -m.m34, 0);
}
inline Matrix orthographic(int w, int h) {
    return Matrix(2.f / float(w), 0, 0, 0, 0, 2.f / float(h), 0, 0, 0, 0, -1, 0, -1, -1, 0, 1);
}

// --- inertia helpers ---
inline Matrix getBoxInertiaTensor(float mass, const Vector& h) {
    // I = m/12 (b^2 + c^2) with full sizes 2h, i.e. m/3 (hy^2 + hz^2).
    float k = mass / 3.0f;
    return Matrix(
        Vector(k * (h.y * h.y + h.z * h.z), k * (h.x * h.x + h.z * h.z), k * (h.x * h.x + h.y * h.y)));
}
inline Matrix getSphereInertiaTensor(float mass, float radius) {
    return Matrix(0.4f * mass * radius * radius);
}

#endif // _MATH_DEFINITIONS_H_
