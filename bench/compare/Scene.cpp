// Scene.cpp - bench_compare's engine-neutral scenes (one fixed-seed generator for every engine) and its
// accuracy figures, computed from the poses the engines report: ground penetration, the deepest overlap of
// any two bodies (sphere-sphere, sphere-box and box-box exactly, by the separating axis test), and how many
// bodies still move.
#include "Scene.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace compare {

namespace {

constexpr unsigned kSeed = 20261122;
constexpr double kPi = 3.14159265358979323846;

// Row-major rotation about a (not necessarily unit) axis.
Pose turned(const double axis[3], double angle) {
    Pose pose;
    double n = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    if (n < 1e-9) return pose;
    double x = axis[0] / n, y = axis[1] / n, z = axis[2] / n, c = std::cos(angle), s = std::sin(angle),
           t = 1 - c;
    double R[9] = {t * x * x + c,     t * x * y - s * z, t * x * z + s * y, t * x * y + s * z, t * y * y + c,
                   t * y * z - s * x, t * x * z - s * y, t * y * z + s * x, t * z * z + c};
    std::copy(R, R + 9, pose.R);
    return pose;
}

Pose randomTurn(std::mt19937& rng) {
    std::uniform_real_distribution<double> unit(-1, 1), angle(-kPi, kPi);
    double axis[3] = {unit(rng), unit(rng), unit(rng)};
    return turned(axis, angle(rng));
}

// The pile column of ReferenceGame's buildBoxPile: 10 x 10 cells 1.8 m apart a layer, layers 1.8 m apart from
// y = 1; but jittered by +-3 cm, not +-0.2 m, so that no two turned unit cubes (bounding radius 0.866 m)
// start overlapping.
void pileCell(int i, std::mt19937& rng, double p[3]) {
    std::uniform_real_distribution<double> jitter(-0.03, 0.03);
    int layer = i / 100, ix = i % 10, iz = (i / 10) % 10;
    p[0] = 1.8 * (ix - 4.5) + jitter(rng);
    p[1] = 1.0 + 1.8 * layer;
    p[2] = 1.8 * (iz - 4.5) + jitter(rng);
}

double boundingRadius(const BodyDesc& b) {
    return b.shape == Shape::Sphere ? b.size : b.size * std::sqrt(3.0);
}

// Column k of R (a body axis in world coordinates).
void axisOf(const Pose& pose, int k, double out[3]) {
    for (int r = 0; r < 3; ++r) out[r] = pose.R[3 * r + k];
}

double dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Overlap of two cubes along the 15 separating axes; the smallest is the penetration depth (< 0: apart).
double boxBox(double ha, const Pose& a, double hb, const Pose& b) {
    double A[3][3], B[3][3], T[3];
    for (int k = 0; k < 3; ++k) {
        axisOf(a, k, A[k]);
        axisOf(b, k, B[k]);
        T[k] = b.p[k] - a.p[k];
    }
    double best = 1e30;
    auto test = [&](const double L[3]) {
        double n = std::sqrt(dot(L, L));
        if (n < 1e-9) return;
        double ra = 0, rb = 0;
        for (int k = 0; k < 3; ++k) {
            ra += ha * std::fabs(dot(A[k], L));
            rb += hb * std::fabs(dot(B[k], L));
        }
        best = std::min(best, (ra + rb - std::fabs(dot(T, L))) / n);
    };
    for (int k = 0; k < 3; ++k) {
        test(A[k]);
        test(B[k]);
    }
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double L[3] = {A[i][1] * B[j][2] - A[i][2] * B[j][1], A[i][2] * B[j][0] - A[i][0] * B[j][2],
                           A[i][0] * B[j][1] - A[i][1] * B[j][0]};
            test(L);
        }
    return best;
}

double sphereBox(double r, const double c[3], double h, const Pose& box) {
    double local[3], d[3] = {c[0] - box.p[0], c[1] - box.p[1], c[2] - box.p[2]};
    for (int k = 0; k < 3; ++k) {
        double ax[3];
        axisOf(box, k, ax);
        local[k] = dot(d, ax);
    }
    double outside = 0, inside = 1e30;
    bool in = true;
    for (int k = 0; k < 3; ++k) {
        double e = std::fabs(local[k]) - h;
        if (e > 0) {
            in = false;
            outside += e * e;
        }
        inside = std::min(inside, -e);
    }
    return in ? r + inside : r - std::sqrt(outside);
}

double pairDepth(const BodyDesc& da, const BodyState& a, const BodyDesc& db, const BodyState& b) {
    if (da.shape == Shape::Sphere && db.shape == Shape::Sphere)
        return da.size + db.size - distance(a.pose.p, b.pose.p);
    if (da.shape == Shape::Box && db.shape == Shape::Box) return boxBox(da.size, a.pose, db.size, b.pose);
    if (da.shape == Shape::Sphere) return sphereBox(da.size, a.pose.p, db.size, b.pose);
    return sphereBox(db.size, b.pose.p, da.size, a.pose);
}

} // namespace

double distance(const double a[3], const double b[3]) {
    double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    return std::sqrt(dx * dx + dy * dy + dz * dz);
}

SceneDesc rainScene(int spheres) {
    SceneDesc s;
    s.name = "rain";
    std::mt19937 rng(kSeed);
    for (int i = 0; i < spheres; ++i) {
        BodyDesc b;
        b.shape = Shape::Sphere;
        b.size = 0.5;
        pileCell(i, rng, b.pose.p);
        s.bodies.push_back(b);
    }
    return s;
}

SceneDesc boxPileScene(int boxes) {
    SceneDesc s;
    s.name = "box pile";
    std::mt19937 rng(kSeed);
    for (int i = 0; i < boxes; ++i) {
        BodyDesc b;
        double p[3];
        pileCell(i, rng, p);
        b.pose = randomTurn(rng);
        std::copy(p, p + 3, b.pose.p);
        s.bodies.push_back(b);
    }
    return s;
}

SceneDesc pyramidScene(int base) {
    SceneDesc s;
    s.name = "pyramid";
    for (int row = 0; row < base; ++row) {
        int count = base - row;
        for (int i = 0; i < count; ++i) {
            BodyDesc b;
            b.pose.p[0] = -0.5 * (count - 1) + i;
            b.pose.p[1] = 0.5 + row;
            s.bodies.push_back(b);
        }
    }
    return s;
}

SceneDesc heavyOnLightScene(double heavy) {
    SceneDesc s;
    s.name = "heavy on light";
    BodyDesc light, top;
    light.pose.p[1] = 0.5;
    top.pose.p[1] = 1.5;
    top.mass = heavy;
    s.bodies = {light, top};
    return s;
}

SceneDesc scatteredBoxes(int boxes) {
    SceneDesc s;
    s.name = "scattered";
    s.ground = false;
    std::mt19937 rng(kSeed);
    const int side = int(std::ceil(std::cbrt(double(boxes))));
    for (int i = 0; i < boxes; ++i) {
        BodyDesc b;
        b.pose = randomTurn(rng);
        b.pose.p[0] = 1.5 * (i % side);
        b.pose.p[1] = 1.0 + 1.5 * (i / (side * side));
        b.pose.p[2] = 1.5 * ((i / side) % side);
        s.bodies.push_back(b);
    }
    return s;
}

std::vector<Pose> jiggled(const SceneDesc& scene, unsigned round) {
    std::mt19937 rng(kSeed + 1 + round);
    std::uniform_real_distribution<double> offset(-0.01, 0.01);
    std::vector<Pose> poses;
    poses.reserve(scene.bodies.size());
    for (const BodyDesc& b : scene.bodies) {
        Pose p = b.pose;
        for (double& x : p.p) x += offset(rng);
        poses.push_back(p);
    }
    return poses;
}

std::vector<BodyState> readAll(const Sim& sim) {
    std::vector<BodyState> out;
    out.reserve(sim.bodyCount());
    for (size_t i = 0; i < sim.bodyCount(); ++i) out.push_back(sim.state(i));
    return out;
}

namespace {
// The 99th percentile of positive values (0 when there are none).
double percentile99(std::vector<double>& values) {
    if (values.empty()) return 0;
    const size_t at = (values.size() - 1) * 99 / 100;
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(at), values.end());
    return values[at];
}
} // namespace

Accuracy measure(const SceneDesc& scene, const std::vector<BodyState>& states) {
    Accuracy acc;
    std::vector<double> groundDepths, pairDepths;
    const size_t n = std::min(scene.bodies.size(), states.size());
    for (size_t i = 0; i < n; ++i) {
        const BodyDesc& b = scene.bodies[i];
        const BodyState& s = states[i];
        double low = s.pose.p[1] - b.size;
        if (b.shape == Shape::Box)
            low = s.pose.p[1] -
                  b.size * (std::fabs(s.pose.R[3]) + std::fabs(s.pose.R[4]) + std::fabs(s.pose.R[5]));
        if (scene.ground) acc.groundPenetration = std::max(acc.groundPenetration, -low);
        if (scene.ground && low < 0) groundDepths.push_back(-low);
        if (std::sqrt(dot(s.v, s.v)) > 0.05) ++acc.moving;
    }
    // Sweep along x over the bounding spheres.
    std::vector<size_t> order(n);
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return states[a].pose.p[0] < states[b].pose.p[0]; });
    double widest = 0;
    for (size_t i = 0; i < n; ++i) widest = std::max(widest, boundingRadius(scene.bodies[i]));
    for (size_t oi = 0; oi < n; ++oi) {
        size_t i = order[oi];
        double ri = boundingRadius(scene.bodies[i]);
        for (size_t oj = oi + 1; oj < n; ++oj) {
            size_t j = order[oj];
            double rj = boundingRadius(scene.bodies[j]);
            if (states[j].pose.p[0] - states[i].pose.p[0] > ri + widest) break;
            if (distance(states[i].pose.p, states[j].pose.p) > ri + rj) continue;
            const double depth = pairDepth(scene.bodies[i], states[i], scene.bodies[j], states[j]);
            acc.pairPenetration = std::max(acc.pairPenetration, depth);
            if (depth > 0) pairDepths.push_back(depth);
        }
    }
    acc.groundPenetration99 = percentile99(groundDepths);
    acc.pairPenetration99 = percentile99(pairDepths);
    return acc;
}

} // namespace compare
