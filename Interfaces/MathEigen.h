// MathEigen.h - views of Vector and Matrix storage as Eigen types, for the engine's .cpp files only.
//
// Not a public header: no public header includes it, and a game never needs it. The simulator and the
// collision detector compute with Eigen inside their .cpp files and keep Vector and Matrix at the edges;
// this is the one place that says how the two meet (Matrix as a row-major 4x4, Vector as a 3-vector).
#pragma once

#include "MathDeclarations.h"

// Core and LU (inverse, determinant) only: the rest of Eigen/Dense (decompositions, eigenvalues) costs every
// file that includes this a fifth of a second to parse; the two files that use them include them.
#include <Eigen/Core>
#include <Eigen/LU>

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
