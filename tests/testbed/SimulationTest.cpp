// SimulationTest.cpp - what the testbed window runs, without a window: every listed scene loads and runs,
// pause and single step, the knobs reach the scene, switching the space keeps the bodies, reset, shooting,
// the mouse spring, and the orbit camera's pixels and rays.
#include "Simulation.h"
#include "ErrorRecorder.h"
#include "OrbitCamera.h"
#include "RBDynamics.h"
#include "TestbedScenes.h"
#include "iCollisionSpace.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneSettings.h"
#include "iRigidBody.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

const SceneSpec& scene(const char* name) {
    const SceneSpec* s = findTestbedScene(name);
    EXPECT_NE(s, nullptr) << name;
    return *s;
}

// Runs frames frames of 16 ms from clock time start; returns the clock time reached.
int run(Simulation& sim, int frames, int start = 0, bool paused = false) {
    for (int i = 0; i <= frames; ++i) sim.frame(start + 16 * i, paused);
    return start + 16 * frames;
}

} // namespace

TEST(TestbedSimulation, ListsEveryGameSceneAndTheProbe) {
    ASSERT_EQ(testbedScenes().size(), allScenes().size() + 1);
    for (const SceneSpec& s : allScenes()) EXPECT_NE(findTestbedScene(s.name), nullptr) << s.name;
    EXPECT_NE(findTestbedScene("probe"), nullptr);
}

TEST(TestbedSimulation, EverySceneRunsWithoutErrors) {
    guardian_test::ErrorRecorder errors;
    for (const SceneSpec& s : testbedScenes()) {
        Simulation sim(s, Knobs());
        run(sim, 40); // past the shooting scene's first shot (frame 30)
        EXPECT_GT(sim.bodyCount(), 0u) << s.name;
        EXPECT_GE(sim.stepCount(), 36) << s.name; // about 38 steps in 0.64 s at 60 Hz
        EXPECT_GE(sim.lastUpdateMs(), 0.0) << s.name;
    }
    EXPECT_EQ(errors.count(), 0u);
}

TEST(TestbedSimulation, PausedFramesStandStillAndAStepIsOneStep) {
    for (int rate : {60, 240}) {
        Knobs k;
        k.stepRate = rate;
        Simulation sim(scene("tower"), k);
        int clock = run(sim, 10);
        const long long steps = sim.stepCount();
        const int now = sim.now();
        run(sim, 30, clock, true); // paused: the clock runs, the simulation does not
        EXPECT_EQ(sim.stepCount(), steps);
        EXPECT_EQ(sim.now(), now);
        for (int i = 1; i <= 5; ++i) {
            sim.singleStep();
            EXPECT_EQ(sim.stepCount(), steps + i) << "rate " << rate;
            EXPECT_EQ(sim.stepsLastFrame(), 1);
        }
    }
}

TEST(TestbedSimulation, KnobsReachTheScene) {
    Simulation sim(scene("tower"), Knobs());
    Knobs k;
    k.integrator = INTEGRATOR_RK4;
    k.stepRate = 120;
    k.solverIterations = 10;
    k.continuous = false;
    sim.setKnobs(k);
    const iPhysicsSceneSettings* s = settingsOf(static_cast<const iPhysicsScene*>(sim.scene()));
    EXPECT_EQ(s->getIntegrator(), INTEGRATOR_RK4);
    EXPECT_EQ(s->getStepRate(), 120);
    EXPECT_EQ(s->getSolverIterations(), 10);
    EXPECT_FALSE(s->getContinuousCollisionEnabled());
    sim.reset(); // a rebuilt scene keeps the knobs
    s = settingsOf(static_cast<const iPhysicsScene*>(sim.scene()));
    EXPECT_EQ(s->getStepRate(), 120);
    EXPECT_EQ(s->getIntegrator(), INTEGRATOR_RK4);
}

TEST(TestbedSimulation, SwitchingTheSpaceKeepsEveryBodyInIt) {
    guardian_test::ErrorRecorder errors;
    Knobs awake; // a sleeping tower has no contacts to look at
    awake.sleeping = false;
    Simulation sim(scene("tower"), awake);
    int clock = run(sim, 60);
    iCollisionSpace* before = sim.space();
    const size_t members = before->getAttachedGeometry().size(); // 10 boxes and the floor
    ASSERT_EQ(members, 11u);
    for (bool octree : {true, false, true}) {
        Knobs k = sim.knobs();
        k.octree = octree;
        k.samplesPerSecond = octree ? 120 : 30;
        sim.setKnobs(k);
        EXPECT_EQ(sim.space()->getAttachedGeometry().size(), members);
        clock = run(sim, 30, clock);
        EXPECT_GT(sim.contactCount(), 0u) << "the tower still stands on the floor";
    }
    EXPECT_NE(sim.space(), before);
    sim.shoot(Vector(0, 3, -10), Vector(0, 0, 1)); // a new body joins the space in use
    EXPECT_EQ(sim.space()->getAttachedGeometry().size(), members + 1);
    Vector lo, hi;
    ASSERT_TRUE(sim.bounds(lo, hi));
    EXPECT_NEAR(hi.y, 9.5f, 0.05f) << "the top box stayed up through the switches";
    EXPECT_EQ(errors.count(), 0u);
}

TEST(TestbedSimulation, ShootingAddsABodyAndResetRemovesIt) {
    Simulation sim(scene("tower"), Knobs());
    run(sim, 10);
    sim.shoot(Vector(0, 3, -10), Vector(0, 0, 1));
    sim.shoot(Vector(0, 6, -10), Vector(0, 0, 1));
    run(sim, 10, 160);
    EXPECT_EQ(sim.bodyCount(), 12u);
    sim.reset();
    EXPECT_EQ(sim.bodyCount(), 10u);
    EXPECT_EQ(sim.stepCount(), 0);
}

TEST(TestbedSimulation, TheMouseSpringPullsWhatItGrabs) {
    Simulation sim(scene("tower"), Knobs());
    int clock = run(sim, 5);
    // Nothing along the ray, then the top box (centre (0, 9.5, 0)) seen from -x.
    EXPECT_FALSE(sim.grab(Vector(-10, 20, 0), Vector(1, 0, 0), Vector(1, 0, 0)));
    ASSERT_TRUE(sim.grab(Vector(-10, 9.5f, 0), Vector(1, 0, 0), Vector(1, 0, 0)));
    EXPECT_NEAR(sim.spring().anchor().x, -0.5f, 1e-3f);
    sim.spring().drag(Vector(-10, 12, 1), Vector(1, 0, 0)); // the target: (-0.5, 12, 1) in the plane x = -0.5
    EXPECT_NEAR(sim.spring().target().y, 12.0f, 1e-4f);
    clock = run(sim, 120, clock);
    const Vector gap = sim.spring().anchor() - sim.spring().target();
    EXPECT_LT(gap.length(), 0.1f) << "the grabbed point follows the mouse (sags g / w^2 = 2.8 cm)";
    sim.spring().release();
    EXPECT_FALSE(sim.spring().holding());
    // A fixed body is not grabbed.
    sim.load(scene("probe"));
    EXPECT_FALSE(sim.grab(Vector(-10, 1, 0), Vector(1, 0, 0), Vector(1, 0, 0)));
}

TEST(TestbedCamera, PixelsAndRaysAgree) {
    OrbitCamera camera;
    camera.lookAt(Vector(0, 2, -8), Vector(0, 1, 0));
    float x = 0, y = 0;
    ASSERT_TRUE(camera.toPixel(Vector(0, 1, 0), 320, 240, x, y));
    EXPECT_NEAR(x, 160.0f, 1e-3f);
    EXPECT_NEAR(y, 120.0f, 1e-3f);
    // Left-handed, as the course framework: looking along +z, +x is to the right and +y up.
    ASSERT_TRUE(camera.toPixel(Vector(1, 1, 0), 320, 240, x, y));
    EXPECT_GT(x, 160.0f);
    ASSERT_TRUE(camera.toPixel(Vector(0, 2, 0), 320, 240, x, y));
    EXPECT_LT(y, 120.0f);
    EXPECT_FALSE(camera.toPixel(Vector(0, 2, -9), 320, 240, x, y)) << "behind the eye";
    // The ray through a point's pixel passes through the point.
    const Vector p(1.3f, 0.4f, 2.0f);
    ASSERT_TRUE(camera.toPixel(p, 320, 240, x, y));
    Vector origin, direction;
    camera.ray(x, y, 320, 240, origin, direction);
    const Vector toP = p - origin;
    EXPECT_LT((toP - direction * dot(toP, direction)).length(), 1e-3f);
    // Orbiting keeps the target and the distance; the pitch stops short of the pole.
    camera.orbit(1.0f, 5.0f);
    EXPECT_LT((camera.target() - Vector(0, 1, 0)).length(), 1e-5f);
    EXPECT_NEAR((camera.eye() - camera.target()).length(), std::sqrt(65.0f), 1e-3f);
    EXPECT_GT(camera.forward().y, -1.0f);
}
