// MathDefinitions.h - Vector and Matrix operations and the inertia helpers, implemented on Eigen.
//
// Header-only so that the Interfaces target stays an INTERFACE library and each drop-in package carries
// its math with it. Matrix storage is mapped as a row-major Eigen 4x4; Vector as an Eigen 3-vector.
// See MathDeclarations.h for the conventions (row vectors, translation in m41..m43, left-handed, y up).
#pragma once

#include "MathDeclarations.h"

#include <Eigen/Dense>
#include <cmath>

namespace gmath {
using Mat4 = Eigen::Matrix<float, 4, 4, Eigen::RowMajor>;
using Mat3 = Eigen::Matrix3f;
static_assert(sizeof(Vector) == 3 * sizeof(float), "Vector must be three packed floats");
static_assert(sizeof(Matrix) == 16 * sizeof(float), "Matrix must be sixteen packed floats");

inline Eigen::Map<Mat4> map(Matrix& m) { return Eigen::Map<Mat4>(m.data()); }
inline Eigen::Map<const Mat4> map(const Matrix& m) { return Eigen::Map<const Mat4>(m.data()); }
inline Eigen::Map<Eigen::Vector3f> map(Vector& v) { return Eigen::Map<Eigen::Vector3f>(&v.x); }
inline Eigen::Map<const Eigen::Vector3f> map(const Vector& v) {
    return Eigen::Map<const Eigen::Vector3f>(&v.x);
}
inline Vector toVector(const Eigen::Vector3f& v) { return Vector(v.x(), v.y(), v.z()); }
inline Matrix toMatrix(const Mat4& e) {
    Matrix m;
    map(m) = e;
    return m;
}
// The upper-left 3x3 block (rotation or inertia tensor) as a column-major Eigen matrix.
inline Mat3 block3(const Matrix& m) { return map(m).topLeftCorner<3, 3>(); }
// A Matrix holding r in its 3x3 block, zero translation and m44 = 1.
inline Matrix fromBlock3(const Mat3& r) {
    Matrix m(1);
    map(m).topLeftCorner<3, 3>() = r;
    return m;
}
} // namespace gmath

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
    gmath::map(*this) += gmath::map(a);
    return *this;
}
inline Matrix& Matrix::operator-=(const Matrix& a) {
    gmath::map(*this) -= gmath::map(a);
    return *this;
}
inline Matrix& Matrix::operator*=(const Matrix& a) { return *this = *this * a; }
inline Matrix Matrix::transpose() const { return gmath::toMatrix(gmath::map(*this).transpose()); }
inline Matrix Matrix::inverse() const {
    gmath::Mat4 inv;
    bool invertible = false;
    gmath::map(*this).computeInverseWithCheck(inv, invertible, 1e-12f);
    return invertible ? gmath::toMatrix(inv) : *this;
}
inline bool Matrix::isFinite() const { return gmath::map(*this).allFinite(); }
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
    gmath::map(*this).topLeftCorner<3, 3>() = gmath::map(rot).topLeftCorner<3, 3>();
    return *this;
}
inline Matrix Matrix::rotation() const { return gmath::fromBlock3(gmath::block3(*this)); }
inline Vector Matrix::direction(const Vector& v) const {
    return gmath::toVector(gmath::block3(*this).transpose() * gmath::map(v));
}
inline Vector Matrix::direction(char axis) const {
    int row = axis == 'x' || axis == 'X' ? 0 : axis == 'y' || axis == 'Y' ? 1 : 2;
    return Vector((*this)(row, 0), (*this)(row, 1), (*this)(row, 2));
}

// --- free operators ---
inline Matrix operator*(const Matrix& a, const Matrix& b) {
    return gmath::toMatrix(gmath::map(a) * gmath::map(b));
}
inline Matrix operator+(const Matrix& a, const Matrix& b) {
    return gmath::toMatrix(gmath::map(a) + gmath::map(b));
}
inline Matrix operator-(const Matrix& a, const Matrix& b) {
    return gmath::toMatrix(gmath::map(a) - gmath::map(b));
}
inline Matrix operator*(const Matrix& a, float s) { return gmath::toMatrix(gmath::map(a) * s); }
inline Vector operator*(const Vector& v, const Matrix& m) {
    // Row vector (v, 1) times M, no perspective divide.
    return gmath::toVector(gmath::block3(m).transpose() * gmath::map(v) +
                           Eigen::Vector3f(m.m41, m.m42, m.m43));
}
inline bool operator==(const Matrix& a, const Matrix& b) { return gmath::map(a) == gmath::map(b); }

// --- generators ---
// Rodrigues' rotation written for row vectors: p * rotate(k, a) = p cos a + (k x p) sin a + k (k.p)(1 - cos
// a). rotatex/y/z are the same rotations about the unit axes (the D3DXMatrixRotationX layout).
inline Matrix rotate(const Vector& axis, float rad) {
    Vector k = axis.normalize();
    if (k.lengthSquared() == 0.0f) return Matrix(1);
    // Eigen's AngleAxis is the column-vector form; its transpose is the row-vector form.
    gmath::Mat3 r = Eigen::AngleAxisf(rad, gmath::map(k)).toRotationMatrix();
    return gmath::fromBlock3(r.transpose());
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

inline Matrix orthoNormalize(const Matrix& m) {
    // Polar decomposition via SVD: the orthonormal factor U V^T is the nearest rotation in Frobenius norm.
    Eigen::JacobiSVD<gmath::Mat3> svd(gmath::block3(m), Eigen::ComputeFullU | Eigen::ComputeFullV);
    gmath::Mat3 u = svd.matrixU();
    gmath::Mat3 r = u * svd.matrixV().transpose();
    if (r.determinant() < 0.0f) { // reflection: flip the least significant direction
        u.col(2) = -u.col(2);
        r = u * svd.matrixV().transpose();
    }
    Matrix out = gmath::fromBlock3(r);
    out.m41 = m.m41;
    out.m42 = m.m42;
    out.m43 = m.m43;
    return out;
}
inline bool isRotation(const Matrix& m, float tol) {
    gmath::Mat3 r = gmath::block3(m);
    if (!r.allFinite()) return false;
    return (r * r.transpose() - gmath::Mat3::Identity()).cwiseAbs().maxCoeff() <= tol &&
           std::fabs(r.determinant() - 1.0f) <= tol;
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
inline Vector getCentreOfMass(const PointMass* points, size_t n) {
    double total = 0, cx = 0, cy = 0, cz = 0;
    for (size_t i = 0; points && i < n; ++i) {
        total += points[i].mass;
        cx += double(points[i].mass) * points[i].position.x;
        cy += double(points[i].mass) * points[i].position.y;
        cz += double(points[i].mass) * points[i].position.z;
    }
    if (total <= 0) return Vector();
    return Vector(float(cx / total), float(cy / total), float(cz / total));
}
inline Matrix getInertiaTensor(const PointMass* points, size_t n) {
    // I = sum m (|r|^2 E - r r^T) with r measured from the centre of mass (the original measured from the
    // local origin, which is what "exaggerated results" came from). Accumulated in double.
    Vector c = getCentreOfMass(points, n);
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
    for (size_t i = 0; points && i < n; ++i) {
        Eigen::Vector3d r = gmath::map(points[i].position - c).cast<double>();
        inertia +=
            double(points[i].mass) * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
    }
    return gmath::fromBlock3(inertia.cast<float>());
}
