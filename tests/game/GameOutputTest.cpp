// GameOutputTest.cpp - the reference game's numbers against physics, not against themselves: the CSV's
// kinetic energy and position of a ball in free fall (KE = m g^2 t^2 / 2, y = h - g t^2 / 2), --track's
// printed positions until the ball lands, a dropped pile that falls asleep with its energy gone, and a CSV
// whose header and rows agree.
#include "GameTestSupport.h"

#include "CsvLog.h"

#include <cmath>
#include <cstdio>
#include <regex>

using namespace game_test;

TEST(GameCsv, FreeFallKineticEnergyIsHalfMG2T2AndHeightFollowsTheFormula) {
    const std::string path = scratch("fall.csv");
    GameOptions o;
    o.frames = 120; // 1.92 s: the ball is still falling
    o.csv = path;
    o.csvEvery = 1;
    o.track = {"ball"};
    o.out = std::tmpfile();
    ASSERT_EQ(runScene(dropScene(), o), RUN_OK);
    std::fclose(o.out);
    Csv csv = readCsv(path);
    std::remove(path.c_str());
    ASSERT_EQ(csv.cells.size(), 121u); // t = 0 and every frame
    for (size_t r = 0; r < csv.cells.size(); ++r) {
        const double game = csv.at(r, "time_s"), t = csv.at(r, "sim_time_s");
        // The physics runs fixed 1/60 s steps up to the game's clock: at most one step behind it.
        EXPECT_LE(t, game + 1e-9);
        EXPECT_GT(t, game - kStep - 1e-9);
        // v = g t exactly under constant acceleration (any of the integrators), so KE = m g^2 t^2 / 2: within
        // 0.05 % (float state) + 1 uJ.
        const double ke = 0.5 * kBallMass * kG * kG * t * t;
        EXPECT_NEAR(csv.at(r, "kinetic_energy_J"), ke, 5e-4 * ke + 1e-6) << "t = " << t;
        // Height: the analytic h - g t^2 / 2, less semi-implicit Euler's g dt t / 2 (its exact result under
        // constant gravity is h - g dt^2 n (n + 1) / 2 after n steps); within 2 mm of that.
        const double y = kDropHeight - 0.5 * kG * t * t;
        EXPECT_NEAR(csv.at(r, "ball_y_m"), y - 0.5 * kG * kStep * t, 2e-3) << "t = " << t;
        EXPECT_EQ(csv.at(r, "ball_x_m"), 0.0);
        EXPECT_EQ(csv.at(r, "awake_bodies"), r == 0 ? csv.at(r, "awake_bodies") : 1.0);
    }
}

TEST(GameTrack, AFallingBallIsPrintedAtHMinusHalfGT2UntilItLands) {
    GameOptions o;
    o.frames = 330; // 5.28 s: it lands at about 4.5 s
    o.track = {"ball"};
    o.out = std::tmpfile();
    ASSERT_EQ(runScene(dropScene(), o), RUN_OK);
    const std::string text = readBack(o.out);
    std::fclose(o.out);
    // Each summary line "t   1.01 s ..." is followed by "  track ball     pos (x, y, z) m ...".
    const std::regex line(
        R"(t +([0-9.]+) s [^\n]*\n  track ball +pos \( *([-0-9.]+), +([-0-9.]+), +([-0-9.]+)\) m)");
    int seconds = 0;
    bool landed = false;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), line); it != std::sregex_iterator(); ++it) {
        ++seconds;
        const double t = std::stod((*it)[1]), y = std::stod((*it)[3]);
        const double free = kDropHeight - 0.5 * kG * t * t;
        if (free > kBallRadius + 0.5) {
            // Still falling: within one physics step's lag (the ball is up to g t dt higher) plus
            // semi-implicit Euler's g dt t / 2 (lower), plus the 1 mm the line rounds to.
            EXPECT_NEAR(y, free, kG * kStep * t + 1e-3) << "t = " << t;
        } else {
            landed = true;
            EXPECT_GE(y, kBallRadius - 0.01) << "below the floor at t = " << t; // and never through it
        }
        EXPECT_NEAR(std::stod((*it)[2]), 0.0, 1e-3);
    }
    EXPECT_EQ(seconds, 6) << text; // 1 s .. 5 s and the last frame
    EXPECT_TRUE(landed);
}

TEST(GameCsv, ADroppedPileFallsAsleepWithNoEnergyLeftAndSaysSo) {
    registerScene(
        {"pile20", "20 boxes dropped, turned at random", [](World& w) { buildBoxPile(w, 20, 3); }, nullptr});
    const std::string path = scratch("pile.csv");
    GameOptions o;
    o.frames = 600;
    o.csv = path;
    o.out = std::tmpfile();
    ASSERT_EQ(runScene(*findScene("pile20"), o), RUN_OK);
    const std::string text = readBack(o.out);
    std::fclose(o.out);
    Csv csv = readCsv(path);
    std::remove(path.c_str());
    ASSERT_GE(csv.cells.size(), 3u);
    // At the start every box is awake and the pile has potential energy to lose.
    EXPECT_EQ(csv.at(0, "awake_bodies"), 20);
    EXPECT_EQ(csv.at(0, "moving_bodies"), 20);
    const size_t last = csv.cells.size() - 1;
    // At the end: all asleep, so no kinetic energy, no contacts tested, and the summary line says "asleep".
    EXPECT_EQ(csv.at(last, "awake_bodies"), 0) << text;
    EXPECT_LT(csv.at(last, "kinetic_energy_J"), 1e-6);
    EXPECT_EQ(csv.at(last, "contacts"), 0);
    EXPECT_LT(csv.at(last, "mechanical_energy_J"), csv.at(0, "mechanical_energy_J"));
    EXPECT_NE(text.find("awake    0/20   asleep"), std::string::npos) << text;
}

TEST(GameCsv, HeaderAndRowsAgreeAndRowsComeWhenAsked) {
    const std::string path = scratch("tower.csv");
    GameOptions o;
    o.frames = 130; // summaries at 1.008 s, 2.000 s and the last frame, 2.080 s
    o.csv = path;
    o.track = {"top", "0"};
    o.out = std::tmpfile();
    ASSERT_EQ(runScene(*findScene("tower"), o), RUN_OK);
    std::fclose(o.out);
    Csv csv = readCsv(path);
    const std::vector<std::string> header = {
        "time_s",          "sim_time_s",    "frame",   "kinetic_energy_J", "mechanical_energy_J",
        "awake_bodies",    "moving_bodies", "bodies",  "contacts",         "overlap_m",
        "worst_overlap_m", "hits",          "top_x_m", "top_y_m",          "top_z_m",
        "0_x_m",           "0_y_m",         "0_z_m",   "ms_per_frame"};
    EXPECT_EQ(csv.header, header);
    ASSERT_EQ(csv.cells.size(), 4u);
    const double times[] = {0, 1.008, 2.0, 2.08};
    for (size_t r = 0; r < csv.cells.size(); ++r) {
        EXPECT_EQ(csv.cells[r].size(), header.size()) << "row " << r;
        EXPECT_NEAR(csv.at(r, "time_s"), times[r], 1e-9);
        EXPECT_EQ(csv.at(r, "bodies"), 10);
        EXPECT_NEAR(csv.at(r, "top_y_m"), 9.5, 0.02); // the tower stands: its top box at 9.5 m
        EXPECT_NEAR(csv.at(r, "0_y_m"), 0.5, 0.02);   // body 0, the bottom one
    }
    // Every N frames instead: rows at frames 0, 10, ..., 90 and the last, 95.
    o.frames = 95;
    o.csvEvery = 10;
    o.out = std::tmpfile();
    ASSERT_EQ(runScene(*findScene("tower"), o), RUN_OK);
    std::fclose(o.out);
    csv = readCsv(path);
    std::remove(path.c_str());
    ASSERT_EQ(csv.cells.size(), 11u);
    for (size_t r = 0; r + 1 < csv.cells.size(); ++r) EXPECT_EQ(csv.at(r, "frame"), 10.0 * r);
    EXPECT_EQ(csv.at(10, "frame"), 95);
}
