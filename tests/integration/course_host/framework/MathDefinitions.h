#ifndef _MATH_DEFINITIONS_H_
#define _MATH_DEFINITIONS_H_
// MathDefinitions.h - the test host's matrix operations, shaped like the course framework's.
#include "GeneralConstants.h"
#include "MathDeclarations.h"

inline Matrix operator*(const Matrix& a, const Matrix& b) {
    const float* p = &a.m11;
    const float* q = &b.m11;
    Matrix out;
    float* o = &out.m11;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            o[r * 4 + c] = p[r * 4] * q[c] + p[r * 4 + 1] * q[4 + c] + p[r * 4 + 2] * q[8 + c] +
                           p[r * 4 + 3] * q[12 + c];
    return out;
}
inline Vector operator*(const Vector& v, const Matrix& m) {
    return Vector(v.x * m.m11 + v.y * m.m21 + v.z * m.m31 + m.m41,
                  v.x * m.m12 + v.y * m.m22 + v.z * m.m32 + m.m42,
                  v.x * m.m13 + v.y * m.m23 + v.z * m.m33 + m.m43);
}
inline Matrix Matrix::transpose() const {
    return Matrix(m11, m21, m31, m41, m12, m22, m32, m42, m13, m23, m33, m43, m14, m24, m34, m44);
}
inline Matrix& Matrix::translate(float x, float y, float z) {
    return *this = *this * Matrix(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, x, y, MODEL_Z_AXIS * z, 1);
}
inline Matrix& Matrix::orient(const Matrix& r) {
    m11 = r.m11, m12 = r.m12, m13 = r.m13, m21 = r.m21, m22 = r.m22, m23 = r.m23, m31 = r.m31, m32 = r.m32,
    m33 = r.m33;
    return *this;
}
inline Matrix& Matrix::scale(float x, float y, float z) {
    Vector t = position();
    *this = *this * Matrix(x, 0, 0, 0, 0, y, 0, 0, 0, 0, z, 0, 0, 0, 0, 1);
    m41 = t.x, m42 = t.y, m43 = t.z;
    return *this;
}
inline Matrix& Matrix::rotatex(float rad) {
    float c = std::cos(rad * MODEL_Z_AXIS), s = std::sin(rad * MODEL_Z_AXIS);
    Vector t = position();
    *this = *this * Matrix(1, 0, 0, 0, 0, c, s, 0, 0, -s, c, 0, 0, 0, 0, 1);
    m41 = t.x, m42 = t.y, m43 = t.z;
    return *this;
}
inline Matrix& Matrix::rotatey(float rad) {
    float c = std::cos(rad * MODEL_Z_AXIS), s = std::sin(rad * MODEL_Z_AXIS);
    Vector t = position();
    *this = *this * Matrix(c, 0, -s, 0, 0, 1, 0, 0, s, 0, c, 0, 0, 0, 0, 1);
    m41 = t.x, m42 = t.y, m43 = t.z;
    return *this;
}
inline Matrix& Matrix::rotatez(float rad) {
    float c = std::cos(rad * MODEL_Z_AXIS), s = std::sin(rad * MODEL_Z_AXIS);
    Vector t = position();
    *this = *this * Matrix(c, s, 0, 0, -s, c, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1);
    m41 = t.x, m42 = t.y, m43 = t.z;
    return *this;
}
inline Matrix view(const Vector& p, const Vector& d, const Vector& u) {
    Vector z = d - p;
    z = (1.0f / z.length()) * z;
    Vector x = cross(u, z);
    x = (1.0f / x.length()) * x;
    Vector y = cross(z, x);
    return Matrix(x.x, y.x, z.x, 0, x.y, y.y, z.y, 0, x.z, y.z, z.z, 0, -dot(x, p), -dot(y, p), -dot(z, p),
                  1);
}

#endif
