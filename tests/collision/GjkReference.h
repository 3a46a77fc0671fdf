#include "MathEigen.h"
// GjkReference.h - the independent truth for the narrowphase tests: GJK distance between convex shapes
// given only by their support functions, in double precision, with a brute-force sub-simplex search (every
// face, edge and vertex of the current simplex) instead of Johnson's case analysis, so it shares no code or
// reasoning with the separating-axis and closest-feature tests it checks.
#pragma once

#include <Eigen/Dense>

#include <cmath>
#include <functional>

namespace gjkref {

using V3 = Eigen::Vector3d;
using Support = std::function<V3(const V3&)>;

inline Support sphereSupport(const V3& c, double r) {
    return [c, r](const V3& d) {
        double n = d.norm();
        return n > 0 ? V3(c + d * (r / n)) : V3(c + V3(r, 0, 0));
    };
}
// axes: rows = the box's local axes in world space.
inline Support boxSupport(const V3& c, const Eigen::Matrix3d& axes, const V3& h) {
    return [c, axes, h](const V3& d) {
        V3 p = c;
        for (int i = 0; i < 3; ++i) p += axes.row(i).transpose() * (axes.row(i).dot(d) >= 0 ? h[i] : -h[i]);
        return p;
    };
}
inline Support pointSupport(const V3& p) {
    return [p](const V3&) { return p; };
}

// Closest point to the origin of the hull of the n points; keeps only the points of the sub-simplex it
// lies on (every subset is tried: the affine projection of the origin, kept when its barycentric
// coordinates are all >= 0).
inline V3 closestOnSimplex(V3* pts, int& n) {
    double best = 1e300;
    V3 bestP = pts[0];
    int bestMask = 1;
    for (int mask = 1; mask < (1 << n); ++mask) {
        int idx[4] = {0, 0, 0, 0}, k = 0;
        for (int i = 0; i < n; ++i)
            if (mask & (1 << i)) idx[k++] = i;
        const V3& p0 = pts[idx[0]];
        double lambda[3] = {0, 0, 0};
        if (k > 1) {
            Eigen::Matrix<double, 3, 3> e = Eigen::Matrix<double, 3, 3>::Zero();
            for (int j = 1; j < k; ++j) e.col(j - 1) = pts[idx[j]] - p0;
            Eigen::Matrix3d g = Eigen::Matrix3d::Identity();
            Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
            g.topLeftCorner(k - 1, k - 1) = (e.leftCols(k - 1).transpose() * e.leftCols(k - 1));
            rhs.head(k - 1) = -(e.leftCols(k - 1).transpose() * p0);
            double scale = g.topLeftCorner(k - 1, k - 1).cwiseAbs().maxCoeff();
            if (std::fabs(g.determinant()) <= 1e-14 * std::pow(scale, k - 1)) continue;
            Eigen::Vector3d sol = g.partialPivLu().solve(rhs);
            for (int j = 0; j < k - 1; ++j) lambda[j] = sol[j];
        }
        double l0 = 1.0 - lambda[0] - lambda[1] - lambda[2];
        bool ok = l0 >= -1e-12;
        for (int j = 0; j < k - 1; ++j) ok = ok && lambda[j] >= -1e-12;
        if (!ok) continue;
        V3 p = p0 * l0;
        for (int j = 1; j < k; ++j) p += pts[idx[j]] * lambda[j - 1];
        double len = p.norm();
        if (len < best - 1e-15) {
            best = len;
            bestP = p;
            bestMask = mask;
        }
    }
    V3 kept[4];
    int m = 0;
    for (int i = 0; i < n; ++i)
        if (bestMask & (1 << i)) kept[m++] = pts[i];
    for (int i = 0; i < m; ++i) pts[i] = kept[i];
    n = m;
    return bestP;
}

// Euclidean distance between the two convex shapes (0 when they overlap).
inline double distance(const Support& a, const Support& b) {
    auto support = [&](const V3& d) { return V3(a(d) - b(-d)); };
    V3 simplex[4];
    int n = 1;
    simplex[0] = support(V3(1, 0.3, 0.2));
    V3 v = simplex[0];
    for (int it = 0; it < 200; ++it) {
        double vv = v.squaredNorm();
        if (vv < 1e-24) return 0.0;
        V3 w = support(-v);
        if (vv - v.dot(w) <= 1e-9 * vv + 1e-20) return std::sqrt(vv); // relative error ~1e-9
        simplex[n++] = w;
        v = closestOnSimplex(simplex, n);
        if (n == 4) return 0.0; // origin inside the tetrahedron
    }
    return v.norm();
}

} // namespace gjkref
