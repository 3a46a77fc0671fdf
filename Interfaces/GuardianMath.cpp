// GuardianMath.cpp - the math operations that need a numerical library: general inverse, nearest rotation,
// rotation test, and the inertia of point masses. Eigen stays in here (MathDeclarations.h declares them).
#include "MathDeclarations.h"
#include "MathEigen.h"

#include <Eigen/SVD>

#include <cmath>

Matrix Matrix::inverse() const {
    gmath::Mat4 inv;
    bool invertible = false;
    gmath::map(*this).computeInverseWithCheck(inv, invertible, 1e-12f);
    return invertible ? gmath::toMatrix(inv) : *this;
}

Matrix orthoNormalize(const Matrix& m) {
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

bool isRotation(const Matrix& m, float tol) {
    gmath::Mat3 r = gmath::block3(m);
    if (!r.allFinite()) return false;
    return (r * r.transpose() - gmath::Mat3::Identity()).cwiseAbs().maxCoeff() <= tol &&
           std::fabs(r.determinant() - 1.0f) <= tol;
}

Vector getCentreOfMass(const PointMass* points, size_t n) {
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

Matrix getInertiaTensor(const PointMass* points, size_t n) {
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
