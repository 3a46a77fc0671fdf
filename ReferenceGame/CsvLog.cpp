// CsvLog.cpp - writing the game's samples as CSV (comma separated, '.' decimals, one header row).
#include "CsvLog.h"

#include "MathDefinitions.h"

CsvLog::~CsvLog() {
    if (m_file) std::fclose(m_file);
}

bool CsvLog::open(const std::string& path) {
    m_file = std::fopen(path.c_str(), "w");
    m_wall = std::chrono::steady_clock::now();
    return m_file != nullptr;
}

void CsvLog::header(const std::vector<std::string>& tracked) {
    if (!m_file) return;
    std::fputs("time_s,sim_time_s,frame,kinetic_energy_J,mechanical_energy_J,awake_bodies,moving_bodies,"
               "bodies,contacts,"
               "overlap_m,worst_overlap_m,hits",
               m_file);
    for (const std::string& n : tracked)
        std::fprintf(m_file, ",%s_x_m,%s_y_m,%s_z_m", n.c_str(), n.c_str(), n.c_str());
    std::fputs(",ms_per_frame\n", m_file);
}

void CsvLog::row(const GameSample& s, const std::vector<Vector>& positions) {
    if (!m_file) return;
    auto wall = std::chrono::steady_clock::now();
    double ms = std::chrono::duration<double, std::milli>(wall - m_wall).count();
    int frames = s.frame - m_lastFrame;
    m_wall = wall;
    m_lastFrame = s.frame;
    std::fprintf(m_file, "%.3f,%.6f,%d,%.7g,%.7g,%zu,%zu,%zu,%zu,%.7g,%.7g,%ld", s.time, s.simTime, s.frame,
                 s.kinetic, s.mechanical, s.awake, s.moving, s.bodies, s.contacts, s.overlap, s.worstOverlap,
                 s.hits);
    for (const Vector& p : positions) std::fprintf(m_file, ",%.7g,%.7g,%.7g", p.x, p.y, p.z);
    std::fprintf(m_file, ",%.4f\n", frames > 0 ? ms / frames : 0.0);
}

std::string csvPathFor(const std::string& file, const std::string& scene) {
    return scenePathFor(file, scene, ".csv");
}

std::string scenePathFor(const std::string& file, const std::string& scene, const std::string& ext) {
    bool hasExt = file.size() >= ext.size() && file.compare(file.size() - ext.size(), ext.size(), ext) == 0;
    std::string stem = hasExt ? file.substr(0, file.size() - ext.size()) : file;
    return stem + "-" + scene + ext;
}
