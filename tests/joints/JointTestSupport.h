// JointTestSupport.h - helpers of the joint tests: a body made at a point with a mass and a solid sphere's
// or box's inertia, and zero crossings for periods.
#pragma once

#include "../physics/PhysicsTestSupport.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace joint_test {

using physics_test::ErrorRecorder;
using physics_test::kG;
using physics_test::SceneHolder;

// A body of mass m at p with the inertia of a solid sphere of radius r (2/5 m r^2).
inline iRigidBody* sphereBody(const Vector& p, float m, float r) {
    iRigidBody* b = CreateRigidBody(nullptr);
    RBDynamics& d = b->getDynamics();
    d.mass = m;
    d.position = p;
    const float i = 0.4f * m * r * r;
    Matrix inertia(1);
    inertia.m11 = inertia.m22 = inertia.m33 = i;
    d.setInertiaTensor(inertia);
    return b;
}

// A box of mass m, half extents (hx, hy, hz), at p.
inline iRigidBody* boxBody(const Vector& p, float m, float hx, float hy, float hz) {
    iRigidBody* b = CreateRigidBody(nullptr);
    RBDynamics& d = b->getDynamics();
    d.mass = m;
    d.position = p;
    Matrix inertia(1);
    inertia.m11 = m * (hy * hy + hz * hz) / 3;
    inertia.m22 = m * (hx * hx + hz * hz) / 3;
    inertia.m33 = m * (hx * hx + hy * hy) / 3;
    d.setInertiaTensor(inertia);
    return b;
}

// A chain of `links` 0.5 kg boxes (half extents thick, half, thick) hanging down -y from the world origin,
// each joined at its top end to the one above (nullptr: the world) by join(body, above, anchor).
template <class Join> std::vector<iRigidBody*> hangChain(int links, float half, float thick, Join join) {
    std::vector<iRigidBody*> bodies;
    iRigidBody* above = nullptr;
    for (int i = 0; i < links; ++i) {
        iRigidBody* b = boxBody(Vector(0, -half - 2 * half * i, 0), 0.5f, thick, half, thick);
        join(b, above, Vector(0, -2 * half * i, 0));
        bodies.push_back(b);
        above = b;
    }
    return bodies;
}

// The angle of b's rotation relative to a's (radians): zero while b keeps the turn it had against a when
// both were at the identity.
inline float relativeTurn(const RBDynamics& a, const RBDynamics& b) {
    const Matrix rel = b.orientation * a.orientation.transpose();
    const float trace = rel.m11 + rel.m22 + rel.m33;
    return std::acos(std::clamp((trace - 1) / 2, -1.0f, 1.0f));
}

// The far-out joint cases: a 1 t box (2 m across) at (0, 10, 0) spinning at (0.1, 0.2, 0.3) rad/s, and a box
// of mass m and half extent `half` L out along x, at rest.
struct FarOutPair {
    iRigidBody *heavy, *light;
};
inline FarOutPair spinningPairFarOut(float L, float m, float half) {
    FarOutPair p{boxBody(Vector(0, 10, 0), 1000.0f, 1, 1, 1), boxBody(Vector(L, 10, 0), m, half, half, half)};
    p.heavy->getDynamics().angularVelocity = Vector(0.1f, 0.2f, 0.3f);
    return p;
}

// The mean period of a signal sampled every dt, from its upward zero crossings (linearly interpolated).
inline double meanPeriod(const std::vector<double>& x, double dt) {
    std::vector<double> ups;
    for (size_t i = 1; i < x.size(); ++i)
        if (x[i - 1] < 0 && x[i] >= 0) ups.push_back((double(i - 1) + x[i - 1] / (x[i - 1] - x[i])) * dt);
    if (ups.size() < 2) return 0;
    return (ups.back() - ups.front()) / double(ups.size() - 1);
}

} // namespace joint_test

#include "iFixedUpdater.h"
#include "iPhysicsSceneHooks.h"

#include <functional>

namespace joint_test {

// Calls fn at the start of every step (it sees the state the last step left).
struct EveryStep final : iFixedUpdater {
    std::function<void()> fn;
    void fixedUpdate(iPhysicsScene*, float) override { fn(); }
};

// A scene at hz whose steps are taken one at a time; record() runs at the start of each.
struct StepScene {
    SceneHolder holder;
    EveryStep recorder;
    int hz;
    long steps = 0;
    explicit StepScene(int rate = 60) : holder(rate), hz(rate) {
        recorder.fn = [] {};
        hooksOf(holder.scene)->addFixedUpdater(&recorder);
    }
    ~StepScene() { hooksOf(holder.scene)->removeFixedUpdater(&recorder); }
    iPhysicsScene* scene() { return holder.scene; }
    // Exactly n more steps (time in ms rounded up past each step).
    void step(long n = 1) {
        for (long i = 0; i < n; ++i) {
            ++steps;
            holder.scene->update(int(std::ceil(double(steps) * 1000.0 / hz)));
        }
    }
    void seconds(double s) { step(long(std::lround(s * hz))); }
};

} // namespace joint_test
