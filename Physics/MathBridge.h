// MathBridge.h - conversions between the framework's row-vector Matrix/Vector and the column-vector Eigen
// types the integrators work in.
//
// A row-vector orientation M (p_world = p_local * M) is the column-vector rotation R = M^T, and R is what an
// Eigen quaternion represents. Inertia tensors are symmetric, so they need no transpose.
#pragma once

#include "MathEigen.h"

#include <Eigen/Geometry>

namespace physics {

using Vec3 = Eigen::Vector3f;
using Mat3 = Eigen::Matrix3f;
using Quat = Eigen::Quaternionf;

inline Vec3 toEigen(const Vector& v) { return Vec3(v.x, v.y, v.z); }
inline Vector toVector(const Vec3& v) { return Vector(v.x(), v.y(), v.z()); }
// Column-vector rotation of a row-vector orientation matrix.
inline Mat3 toRotation(const Matrix& m) { return gmath::block3(m).transpose(); }
// Row-vector orientation Matrix (zero translation, m44 = 1) of a column-vector rotation.
inline Matrix toOrientation(const Mat3& r) { return gmath::fromBlock3(r.transpose()); }
inline Matrix toOrientation(const Quat& q) { return toOrientation(q.toRotationMatrix()); }
inline Quat toQuat(const Matrix& m) { return Quat(toRotation(m)).normalized(); }
inline Mat3 tensor(const Matrix& m) { return gmath::block3(m); }

} // namespace physics
