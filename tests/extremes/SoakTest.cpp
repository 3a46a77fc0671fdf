// SoakTest.cpp - a box pile run for 10^4 steps (CI) or 10^6 (GUARDIAN_EXTREMES=full), sleeping off so the
// solver works every step: its mechanical energy never rises above the start, nothing turns non-finite,
// and it ends at rest.
#include "ExtremesSupport.h"

#include "Scenes.h"

#include <algorithm>

using namespace extremes;

// Energy bound: a pile dropped from rest only loses energy (contacts and friction dissipate); the solver's
// position projection may add a little as it pushes overlap out, asserted under 1 % of the potential energy
// the pile starts with above its rest. Once settled (after 10 s) the pile's energy may not climb back more
// than 1 mJ a box (no jitter pumping energy in), and the kinetic energy at the end is under 1 mJ a box.
constexpr long kSettleSteps = 600;

TEST(ExtremeSoak, ABoxPileKeepsBoundedEnergy) {
    const long steps = fullRun() ? 1000000 : 10000;
    const int boxes = 20;
    Bench b(4);
    settingsOf(b.scene)->setSleepingEnabled(false);
    buildBoxPile(*b.world, boxes, 5);
    const float e0 = b.world->mechanicalEnergy();
    float worstRise = -1e30f, lastKinetic = 0, settled = 0, worstRiseSettled = -1e30f;
    bool finite = true;
    long n = 0;
    b.steps(steps, [&] {
        ++n;
        const float e = b.world->mechanicalEnergy();
        worstRise = std::max(worstRise, e - e0);
        if (n == kSettleSteps) settled = e;
        if (n > kSettleSteps) worstRiseSettled = std::max(worstRiseSettled, e - settled);
        if (n % 100 == 0 && !allFinite(*b.world)) finite = false;
        lastKinetic = b.world->kineticEnergy();
        return finite;
    });
    const float settledE = b.world->mechanicalEnergy();
    report("soak " + std::to_string(steps) + " steps: worst energy rise (J)", worstRise);
    report("soak: energy lost (J)", e0 - settledE);
    report("soak: final kinetic energy (J)", lastKinetic);
    report("soak: worst rise above the settled energy after 10 s (J)", worstRiseSettled);
    EXPECT_TRUE(finite) << "at step " << n;
    EXPECT_LT(worstRise, 0.01f * (e0 - settledE));
    EXPECT_LT(lastKinetic, 1e-3f * boxes);
    EXPECT_LT(worstRiseSettled, 1e-3f * boxes);
}
