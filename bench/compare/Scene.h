// Scene.h - what bench_compare's three engine adapters share: an engine-neutral scene description (bodies
// with shape, size, mass and initial pose, made once by a fixed-seed generator), the state an adapter reads
// back, the adapter interfaces (a simulation and a pair finder), and the accuracy figures, computed from the
// poses alone (spheres and boxes are analytic), so that every engine is measured the same way.
//
// Axes: y up, gravity (0, -9.81, 0), the ground is the plane y = 0. A rotation R is row-major and maps body
// coordinates to world coordinates as a column vector: world = R * local + p.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace compare {

enum class Shape { Sphere, Box };

struct Pose {
    double p[3] = {0, 0, 0};
    double R[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
};

struct BodyDesc {
    Shape shape = Shape::Box;
    double size = 0.5; // sphere radius or cube half-extent (m)
    double mass = 1.0; // kg
    Pose pose;
};

// Material for every contact (the engines combine per-body values differently; each adapter sets its bodies
// so that the combined coefficient is this).
constexpr double kFriction = 0.5;
constexpr double kDt = 1.0 / 60.0;

struct SceneDesc {
    std::string name;
    bool ground = true;
    std::vector<BodyDesc> bodies;
};

// What an adapter reads back: the pose and the linear velocity of each body, in SceneDesc order.
struct BodyState {
    Pose pose;
    double v[3] = {0, 0, 0};
};

struct SimOptions {
    bool sleeping = false;  // each engine's own sleeping / deactivation at its defaults when on
    int iterations = 0;     // 0: the engine's default; otherwise its own knob (see EngineInfo::knob)
    bool continuous = true; // Guardian only: its continuous collision stage (on by default)
};

// A scene being simulated by one engine.
class Sim {
public:
    virtual ~Sim() = default;
    virtual void step() = 0; // one step of kDt
    virtual BodyState state(size_t body) const = 0;
    virtual size_t bodyCount() const = 0;
};

// Broadphase only: bodies that never move by themselves; place() moves them (untimed), findPairs() runs the
// engine's pair finding (timed) and returns the pairs (or contacts) it found.
class PairFinder {
public:
    virtual ~PairFinder() = default;
    virtual void place(const std::vector<Pose>& poses) = 0;
    virtual size_t findPairs() = 0;
};

struct EngineInfo {
    std::string name;
    std::string precision;   // "float" / "double"
    std::string defaults;    // what "its defaults" are
    std::string knob;        // what SimOptions::iterations sets
    std::string pairsNote;   // what findPairs() does and counts
    std::vector<int> ladder; // settings of the knob tried for the equal-accuracy row, cheapest first
};

// The adapters (GuardianScenes.cpp, BulletScenes.cpp, OdeScenes.cpp).
EngineInfo guardianInfo();
std::unique_ptr<Sim> makeGuardianSim(const SceneDesc& scene, const SimOptions& options);
std::unique_ptr<PairFinder> makeGuardianPairs(const SceneDesc& scene);
// The same with the octree space (CreateOctreeCollisionSpace) instead of the simple one.
std::unique_ptr<PairFinder> makeGuardianOctreePairs(const SceneDesc& scene);
// The candidate-pair stage alone (each geometry's box, then the broadphase; what Bullet's and ODE's pair
// finders time), in the simple (sort-and-sweep) or the octree (persistent tree) space.
std::unique_ptr<PairFinder> makeGuardianCandidatePairs(const SceneDesc& scene, bool octree);
EngineInfo bulletInfo();
std::unique_ptr<Sim> makeBulletSim(const SceneDesc& scene, const SimOptions& options);
std::unique_ptr<PairFinder> makeBulletPairs(const SceneDesc& scene);
EngineInfo odeInfo();
std::unique_ptr<Sim> makeOdeSim(const SceneDesc& scene, const SimOptions& options);
std::unique_ptr<PairFinder> makeOdePairs(const SceneDesc& scene);

// The scenes (Scene.cpp), all from one fixed seed.
SceneDesc rainScene(int spheres);          // spheres r 0.5 m, 1 kg, in a jittered 10 x 10 column
SceneDesc boxPileScene(int boxes);         // randomly turned unit boxes, 1 kg, in the same column
SceneDesc pyramidScene(int base);          // base + (base - 1) + ... + 1 unit boxes; the last is the top
SceneDesc heavyOnLightScene(double heavy); // a 1 kg unit box on the ground, a `heavy` kg one on it
SceneDesc
scatteredBoxes(int boxes); // randomly turned unit boxes on a 1.5 m grid (neighbours may touch), no ground
// The scattered boxes moved by up to +-1 cm from their start (a fresh offset per call of this function).
std::vector<Pose> jiggled(const SceneDesc& scene, unsigned round);

// Accuracy figures from the poses.
struct Accuracy {
    double groundPenetration = 0; // deepest any body reaches below y = 0 (m)
    double pairPenetration = 0;   // deepest overlap of any two bodies (m)
    // The 99th percentile of the same over the bodies below y = 0 and the overlapping pairs: a settling
    // pile's deepest is one body or pair and swings from second to second; this is where the rest are.
    double groundPenetration99 = 0, pairPenetration99 = 0;
    size_t moving = 0; // bodies faster than 0.05 m/s
};
Accuracy measure(const SceneDesc& scene, const std::vector<BodyState>& states);
std::vector<BodyState> readAll(const Sim& sim);
double distance(const double a[3], const double b[3]);

} // namespace compare
