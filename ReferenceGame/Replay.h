// Replay.h - the reference game's --replay FILE: a recording (RecordingWriter.h) played back headless with no
// physics engine running (no scene is built or stepped): the per-second summary lines recomputed from the
// recorded frames, the recorded verdict, and with --image the same SVG pictures a live run writes
// (RecordingDraw.h).
#pragma once

#include "GameRun.h"

// Plays options.replay back, printing on options.out and writing pictures as options.imageDir and
// options.imageEvery ask. RUN_BAD_ARGUMENTS (with "ReferenceGame: --replay: FILE:LINE: what" on options.err)
// when the file cannot be read or is not a whole, well-formed recording; lines printed and pictures written
// before the fault stay. Else RUN_OK, or RUN_BLEW_UP when the recorded run failed.
RunStatus replayRecording(const GameOptions& options);
