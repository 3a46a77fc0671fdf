// MassRatioExtremesTest.cpp - mass ratios to 1:10^4 both ways: stacks (light on heavy, heavy on light) hold
// their resting height, and pairs of balls colliding (heavy into light and light into heavy) conserve
// momentum and give the analytic one-dimensional outcome.
#include "ExtremesSupport.h"

#include <algorithm>
#include <vector>

using namespace extremes;

namespace {

// A unit box of `bottom` kg on the floor and one of `top` kg on it, `seconds` at `iterations`: how far the
// top box's centre strayed from its resting height 1.5 m after the first half second.
float stackStray(float bottom, float top, int iterations, float seconds) {
    Bench b(iterations);
    b.world->ground();
    b.world->box(Vector(0, 0.5f, 0), Vector(0.5f, 0.5f, 0.5f), bottom);
    RBDynamics* d = b.world->box(Vector(0, 1.5f, 0), Vector(0.5f, 0.5f, 0.5f), top)->getDynamics();
    float worst = 0;
    long n = 0;
    b.steps(long(seconds * 60), [&] {
        if (++n > 30) worst = std::max(worst, (d->position - Vector(0, 1.5f, 0)).length());
        return true;
    });
    EXPECT_TRUE(allFinite(*b.world));
    return worst;
}

struct PairResult {
    float momentumError; // |p_after - p_before| / |p_before|
    float v1, v2;        // final velocities along x
};

// Ball 1 (m1, radius 0.5) at 2 m/s into ball 2 (m2) at rest, head on along x, no gravity, restitution e;
// measured 2 s later. Sleeping is off: an island asleep has its velocities zeroed, momentum and all (the
// 10^4 kg ball hit by a 1 kg one moves at 0.3 mm/s, under the 5 cm/s threshold).
PairResult collidePair(float m1, float m2, float e) {
    Bench b(4);
    settingsOf(b.scene)->setGravity(Vector());
    settingsOf(b.scene)->setSleepingEnabled(false); // falling asleep zeroes a slow body's momentum
    RBDynamics* d1 = b.world->sphere(Vector(-2, 0, 0), 0.5f, m1)->getDynamics();
    RBDynamics* d2 = b.world->sphere(Vector(0, 0, 0), 0.5f, m2)->getDynamics();
    d1->restitution = d2->restitution = e;
    d1->velocity = Vector(2, 0, 0);
    const double p0 = double(m1) * 2.0;
    b.steps(120);
    EXPECT_TRUE(allFinite(*b.world));
    const Vector p = d1->velocity * m1 + d2->velocity * m2;
    return {float(std::sqrt(std::pow(p.x - p0, 2) + double(p.y) * p.y + double(p.z) * p.z) / p0),
            d1->velocity.x, d2->velocity.x};
}

} // namespace

// Light on heavy is easy for any solver; heavy on light needs shock propagation and a contact stiffness that
// follows the load: at 1:10^4 and 16 iterations within 5 cm (measured 6.3 mm). The full run adds 1:10^2,
// 1:10^3 and 1:10^4 at the default 4 iterations (20 s: 4.0, 2.8 and 3.8 mm; 1:10^4 fell off, 3.0 m, before
// the stiffness followed the load).
TEST(ExtremeMassRatio, StacksHoldBothWays) {
    const float seconds = fullRun() ? 20.0f : 3.0f;
    const float lightOnHeavy = stackStray(1e4f, 1.0f, 4, seconds);
    report("stack 1 kg on 10^4 kg, 4 iterations: top strayed (m)", lightOnHeavy);
    EXPECT_LT(lightOnHeavy, 0.01f);
    const float heavyOnLight = stackStray(1.0f, 1e4f, 16, seconds);
    report("stack 10^4 kg on 1 kg, 16 iterations: top strayed (m)", heavyOnLight);
    EXPECT_LT(heavyOnLight, 0.05f);
    if (fullRun()) {
        for (float ratio : {1e2f, 1e3f, 1e4f}) {
            const float s = stackStray(1.0f, ratio, 4, seconds);
            report("stack " + std::to_string(int(ratio)) + " kg on 1 kg, 4 iterations: top strayed (m)", s);
            EXPECT_TRUE(std::isfinite(s));
        }
    }
}

// Head on, 1D: v1' = (m1 - e m2) v / (m1 + m2), v2' = (1 + e) m1 v / (m1 + m2). Momentum is conserved
// by equal and opposite impulses: to float round-off of the heavy body's momentum (1e-4 asked). The
// velocities match the analytic ones within 2 % of the incoming speed.
TEST(ExtremeMassRatio, PairsConserveMomentumBothWays) {
    std::vector<float> ratios = {1e4f};
    if (fullRun()) ratios = {1e1f, 1e2f, 1e3f, 1e4f};
    for (float ratio : ratios) {
        for (bool heavyMoves : {true, false}) {
            const float m1 = heavyMoves ? ratio : 1.0f, m2 = heavyMoves ? 1.0f : ratio, e = 0.5f;
            PairResult r = collidePair(m1, m2, e);
            const float v1 = (m1 - e * m2) * 2.0f / (m1 + m2), v2 = (1 + e) * m1 * 2.0f / (m1 + m2);
            const std::string name = std::string(heavyMoves ? "heavy into light" : "light into heavy") +
                                     " 1:" + std::to_string(int(ratio));
            report(name + ": momentum error (relative)", r.momentumError);
            report(name + ": v1 error (m/s)", r.v1 - v1);
            report(name + ": v2 error (m/s)", r.v2 - v2);
            EXPECT_LT(r.momentumError, 1e-4f) << name;
            EXPECT_NEAR(r.v1, v1, 0.04f) << name;
            EXPECT_NEAR(r.v2, v2, 0.04f) << name;
        }
    }
}
