// GameTestSupport.h - for the game tests: a scratch file path, a CSV read into numbers, a FILE* read back as
// text, and the "drop" scene (one ball falling from a known height) that the tests register.
#pragma once

#include "GameRun.h"
#include "MathDefinitions.h"
#include "Scenes.h"
#include "World.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace game_test {

const float kG = 9.81f, kDropHeight = 100.0f, kBallMass = 2.0f, kBallRadius = 0.5f;
const double kStep = 1.0 / 60; // the scene's default step rate

// A 2 kg ball 100 m above a floor, named "ball".
inline void buildDrop(World& w) {
    w.ground();
    w.name(w.sphere(Vector(0, kDropHeight, 0), kBallRadius, kBallMass), "ball");
}

// The tests' own scene "drop", registered from here like a game's (once a process).
inline const SceneSpec& dropScene() {
    registerScene({"drop", "a 2 kg ball dropped from 100 m (named: ball)", buildDrop, nullptr});
    return *findScene("drop");
}

// A path for a scratch file, unique to this process (ctest runs tests side by side).
inline std::string scratch(const std::string& name) {
    return ::testing::TempDir() + "guardian_game_" + std::to_string(::getpid()) + "_" + name;
}

// Everything written to f so far.
inline std::string readBack(std::FILE* f) {
    std::fflush(f);
    std::rewind(f);
    std::string text;
    char buf[4096];
    for (size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) text.append(buf, n);
    return text;
}

struct Csv {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> cells; // as written, one vector per row
    // The column named name (-1 when none).
    int col(const std::string& name) const {
        for (size_t i = 0; i < header.size(); ++i)
            if (header[i] == name) return int(i);
        return -1;
    }
    double at(size_t row, const std::string& name) const {
        return std::atof(cells[row][size_t(col(name))].c_str());
    }
};

inline std::vector<std::string> splitCommas(const std::string& line) {
    std::vector<std::string> out;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) out.push_back(cell);
    if (!line.empty() && line.back() == ',') out.push_back("");
    return out;
}

inline Csv readCsv(const std::string& path) {
    Csv csv;
    std::ifstream in(path);
    std::string line;
    if (std::getline(in, line)) csv.header = splitCommas(line);
    while (std::getline(in, line)) csv.cells.push_back(splitCommas(line));
    return csv;
}

} // namespace game_test
