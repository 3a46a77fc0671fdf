// GameDesign.h - the reference game's Design: builds a named scene, counts hits with a listener, prints a
// per-second summary (and the tracked bodies), writes the CSV rows and the recording, and judges whether the
// scene blew up.
#pragma once

#include "GameRun.h"
#include "GameSample.h"
#include "Scenes.h"
#include "Tracking.h"
#include "iDesign.h"

#include <chrono>
#include <string>

class CsvLog;
class RecordingWriter;
class World;
class iPhysicsScene;

class GameDesign final : public iDesign {
public:
    // csv: where rows go (nullptr: none); it must outlive the design.
    GameDesign(iPhysicsScene* scene, const SceneSpec& spec, const GameOptions& options, CsvLog* csv);
    void initialize(int now) override;
    void update(int now) override;
    void reset(int) override {}
    void restore(int) override {}
    void suspend() override {}
    void release() override {}
    bool finished() const override { return m_frame >= m_frames || m_failure; }
    void Delete() const override { delete this; }

    // Writes the scene's debug drawing as dir/<scene>_<frame>.svg every `every` frames and at the last one.
    void writeImages(const std::string& dir, int every) {
        m_imageDir = dir;
        m_imageEvery = every;
    }

    // Writes every frame to recording (RecordingWriter.h; it must outlive the design).
    void record(RecordingWriter* recording) { m_recording = recording; }

    // Why the scene failed, or nullptr when it held together.
    const char* failure() const { return m_failure; }

private:
    ~GameDesign();
    GameSample measure(int now, float penetration) const;
    void summarise(const GameSample& s);
    void writeImage();
    void printProfile() const;

    iPhysicsScene* m_scene;
    const SceneSpec& m_spec;
    const GameOptions& m_options;
    CsvLog* m_csv;
    RecordingWriter* m_recording = nullptr;
    BodyTracker m_tracker;
    World* m_world = nullptr;
    struct HitCounter* m_hits = nullptr;
    int m_frames, m_csvEvery, m_frame = 0, m_start = 0, m_lastSecond = 0;
    float m_energyBudget = 0; // the mechanical energy the scene may have: initial plus what shots inject
    float m_worstPenetration = 0;
    const char* m_failure = nullptr;
    std::chrono::steady_clock::time_point m_wallStart;
    int m_framesThisSecond = 0;
    std::string m_imageDir; // empty: no pictures
    int m_imageEvery = 60;
};
