// CsvLog.h - the reference game's --csv: its measurements (GameSample.h) as CSV, one row per sample, for
// plotting (scripts/plot.sh) and for tests that read numbers rather than text.
//
// Columns (GameSample.h says what each is): time_s, sim_time_s, frame, kinetic_energy_J, mechanical_energy_J,
// awake_bodies, moving_bodies, bodies, contacts, overlap_m, worst_overlap_m, hits, then NAME_x_m, NAME_y_m,
// NAME_z_m for each tracked body, then ms_per_frame (wall time: the only column that is not deterministic).
// Rows: one at t = 0, then one with each per-second summary line, or one every --csv-every frames (and the
// last frame).
#pragma once

#include "GameSample.h"
#include "MathDeclarations.h"

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

class CsvLog {
public:
    CsvLog() = default;
    CsvLog(const CsvLog&) = delete;
    CsvLog& operator=(const CsvLog&) = delete;
    ~CsvLog(); // closes the file

    // Opens (truncates) path for writing; false when it cannot.
    bool open(const std::string& path);
    // The header row, naming a column triple for each tracked body.
    void header(const std::vector<std::string>& tracked);
    // One row; positions in the order of the header's tracked names.
    void row(const GameSample& s, const std::vector<Vector>& positions);

private:
    std::FILE* m_file = nullptr;
    std::chrono::steady_clock::time_point m_wall;
    int m_lastFrame = 0;
};

// Where --csv FILE puts a scene's rows when one run writes several scenes (--scene all): the scene's name
// joined to FILE before its ".csv" (runs.csv, tower -> runs-tower.csv; runs -> runs-tower.csv).
std::string csvPathFor(const std::string& file, const std::string& scene);
// The same rule for any extension (--record: ext ".rec"; runs.rec, tower -> runs-tower.rec).
std::string scenePathFor(const std::string& file, const std::string& scene, const std::string& ext);
