// MathBridge.h - conversions between the framework's row-vector Matrix/Vector and the column-vector Eigen
// types the integrators work in.
//
// A row-vector orientation M (p_world = p_local * M) is the column-vector rotation R = M^T, and R is what an
// Eigen quaternion represents. Inertia tensors are symmetric, so they need no transpose.
//
// Real is the simulator's scalar: float, or double when built with GUARDIAN_DOUBLE (CMake option
// GUARDIAN_DOUBLE, README.md (Double precision)). The public types (Vector, Matrix, RBDynamics) stay float;
// in a double build each body keeps its own pose and velocities in Real between steps (RigidBody.h) and the
// conversions below round only at those edges. With float the casts are no-ops: the same code, the same bits.
#pragma once

#include "MathEigen.h"

#include <Eigen/Geometry>

namespace physics {

#if defined(GUARDIAN_DOUBLE) && GUARDIAN_DOUBLE
#define GUARDIAN_REAL_IS_DOUBLE 1
using Real = double;
#else
#define GUARDIAN_REAL_IS_DOUBLE 0
using Real = float;
#endif
using Vec3 = Eigen::Matrix<Real, 3, 1>;
using Mat3 = Eigen::Matrix<Real, 3, 3>;
using Quat = Eigen::Quaternion<Real>;

inline Vec3 toEigen(const Vector& v) { return Vec3(Real(v.x), Real(v.y), Real(v.z)); }
inline Vector toVector(const Vec3& v) { return Vector(float(v.x()), float(v.y()), float(v.z())); }
// Column-vector rotation of a row-vector orientation matrix.
inline Mat3 toRotation(const Matrix& m) { return gmath::block3(m).transpose().cast<Real>(); }
// Row-vector orientation Matrix (zero translation, m44 = 1) of a column-vector rotation.
inline Matrix toOrientation(const Mat3& r) { return gmath::fromBlock3(r.transpose().cast<float>()); }
inline Matrix toOrientation(const Quat& q) { return toOrientation(q.toRotationMatrix()); }
inline Quat toQuat(const Matrix& m) { return Quat(toRotation(m)).normalized(); }
inline Mat3 tensor(const Matrix& m) { return gmath::block3(m).cast<Real>(); }

} // namespace physics
