// SpeedExtremesTest.cpp - balls at up to 10^4 m/s into a fixed wall and into the ground: the continuous
// stage stops them at the surface (none passes), and every state stays finite.
#include "ExtremesSupport.h"

#include <algorithm>
#include <vector>

using namespace extremes;

namespace {

struct ShotResult {
    float deepest; // how far the ball's centre got past the wall's near face minus its radius (m; < 0: short)
    float maxSpeed;
};

// A ball of radius r moving at v along +x, starting (2 + phase) steps of travel short of a 1 m thick fixed
// wall whose near face is at x = 0; gravity off, 30 steps.
ShotResult shootAtWall(float r, float v, float phase) {
    Bench b(4);
    settingsOf(b.scene)->setGravity(Vector());
    b.world->fixedBox(Vector(0.5f, 0, 0), Vector(0.5f, 5, 5));
    RBDynamics* d = b.world->sphere(Vector(-r - v * b.dt() * (2 + phase), 0, 0), r, 1.0f)->getDynamics();
    d->velocity = Vector(v, 0, 0);
    ShotResult out{-1e30f, 0};
    b.steps(30, [&] {
        out.deepest = std::max(out.deepest, d->position.x + r);
        out.maxSpeed = std::max(out.maxSpeed, d->velocity.length());
        return true;
    });
    EXPECT_TRUE(allFinite(*b.world)) << "r " << r << " v " << v;
    return out;
}

} // namespace

// Nothing passes: the ball's leading point never goes more than 1 cm into the 1 m wall (the stage puts it
// back 0.2 mm in; the solver then pushes it out), and it never comes back faster than it came (restitution
// 0.5). Short: 10^4 m/s for a 0.5 m and a 5 cm ball at 5 start phases; full: 10^2..10^4 m/s at 50 phases.
TEST(ExtremeSpeed, BallsIntoAWallDoNotPass) {
    std::vector<float> speeds = {1e4f};
    int phases = 5;
    if (fullRun()) {
        speeds = {1e2f, 1e3f, 3e3f, 1e4f};
        phases = 50;
    }
    for (float r : {0.5f, 0.05f}) {
        for (float v : speeds) {
            float deepest = -1e30f, fastest = 0;
            for (int p = 0; p < phases; ++p) {
                ShotResult s = shootAtWall(r, v, float(p) / float(phases));
                deepest = std::max(deepest, s.deepest);
                fastest = std::max(fastest, s.maxSpeed);
            }
            const std::string name = "ball r " + std::to_string(r) + " at " + std::to_string(int(v)) + " m/s";
            report(name + ": deepest into the wall (m)", deepest);
            EXPECT_LT(deepest, 0.01f) << name;
            EXPECT_LE(fastest, v * 1.0001f) << name;
        }
    }
}

// Straight down onto the ground plane at 10^4 m/s (gravity on): it ends above the plane, at rest or
// bouncing, never below it.
TEST(ExtremeSpeed, BallIntoTheGroundDoesNotPass) {
    for (float v : {1e3f, 1e4f}) {
        Bench b(4);
        b.world->ground();
        RBDynamics* d = b.world->sphere(Vector(0, 0.5f + 2.5f * v / 60.0f, 0), 0.5f, 1.0f)->getDynamics();
        d->velocity = Vector(0, -v, 0);
        float lowest = 1e30f;
        b.steps(120, [&] {
            lowest = std::min(lowest, d->position.y - 0.5f);
            return true;
        });
        report("ball into ground at " + std::to_string(int(v)) + " m/s: lowest point (m)", lowest);
        EXPECT_TRUE(allFinite(*b.world));
        EXPECT_GT(lowest, -0.01f) << v;
    }
}
