// GameRun.h - one scene run as the reference game runs it: the course engine loop (physicsScene->update(now),
// then design->update(now)) on a stepped 16 ms clock, with the command line's options. main.cpp and the
// game tests (tests/game) share it, so a scene a game registers (Scenes.h) runs the same way in both.
#pragma once

#include "Scenes.h"

#include <cstdio>
#include <string>
#include <vector>

struct GameOptions {
    int frames = 600;               // frames to run, > 0
    std::string csv;                // --csv: the CSV file to write ("" none; CsvLog.h)
    int csvEvery = 0;               // --csv-every: a CSV row every N frames; 0: with each summary line
    std::vector<std::string> track; // --track: body names (World::name) or indices, printed each second
    std::string imageDir;           // --image: debug drawings as DIR/<scene>_<frame>.svg ("" none)
    int imageEvery = 60;            // --image-every: a picture every N frames and at the last
    bool profile = false;           // --profile: the step's phases under each summary line
    std::string record;             // --record: every frame written to this file ("" none; RecordingWriter.h)
    std::string replay;             // --replay: the recording to play back instead of running (Replay.h)
    std::FILE* out = stdout;        // the summary, track and verdict lines
    std::FILE* err = stderr;        // notes (a tracked body a scene lacks, a CSV file that cannot be written)
};

// Exit statuses of the game.
enum RunStatus { RUN_OK = 0, RUN_BLEW_UP = 1, RUN_BAD_ARGUMENTS = 2 };

// Runs spec for options.frames frames, ending with "OK <scene>" or "FAIL <scene>: <reason>" on options.out.
// RUN_BAD_ARGUMENTS (nothing run) when the CSV or recording file cannot be opened.
RunStatus runScene(const SceneSpec& spec, const GameOptions& options);
