#!/usr/bin/env bash
# Builds the reference game (Release) and runs it headless; arguments go to the game.
# Usage: scripts/game.sh [--scene NAME|all] [--frames N] [--csv FILE] [--csv-every N] [--track NAME]...
#                       [--image DIR] [--image-every N] [--profile] [--record FILE] [--list] [--help]
#        scripts/game.sh --replay FILE [--image DIR] [--image-every N]
# (scripts/plot.sh CSV OUTDIR plots a --csv file.)
set -euo pipefail
cd "$(dirname "$0")/.."
for arg in "$@"; do
  if [ "$arg" = "--help" ] || [ "$arg" = "-h" ]; then
    cat <<'USAGE'
usage: scripts/game.sh [--scene NAME|all] [--frames N] [--csv FILE] [--csv-every N] [--track NAME]...
                       [--image DIR] [--image-every N] [--profile] [--record FILE] [--list] [--help]
       scripts/game.sh --replay FILE [--image DIR] [--image-every N]
Builds the reference game (Release, in build-release/) and runs it headless with these arguments
(--help builds nothing):
  --scene NAME|all  the scene to run, or every scene in turn (default: pyramid)
  --frames N        frames per scene on a stepped 16 ms clock, N > 0 (default: 600, about 10 s)
  --csv FILE        also write the measurements as CSV to FILE: a header row, a row at t = 0 and one
                    with each summary line; with --scene all one file per scene, the scene's name
                    joined before .csv (runs.csv: runs-tower.csv, runs-pyramid.csv, ...)
  --csv-every N     a CSV row every N frames instead, N > 0 (1: every frame)
  --track NAME      print a body's position each second (and add x, y, z columns to the CSV): a name
                    the scene gave it (--list shows them) or its index; may be repeated
  --image DIR       write the scene's debug drawing as DIR/<scene>_<frame>.svg (DIR must exist)
  --image-every N   ... every N frames, N > 0, and at the last frame (default: 60)
  --profile         print each second where the last frame's step time went, phase by phase
  --record FILE     write every frame (poses, shapes, contacts, hits) to FILE as text; with --scene
                    all one file per scene, the scene's name joined before .rec (as --csv)
  --replay FILE     play a --record file back without running the engine: its summary lines and
                    verdict, with --image its pictures; only --image and --image-every go with it
  --list            name and describe the scenes, then exit
  --help            print this and exit
Each second: t, awake/moving bodies ("asleep" when all sleep), contacts, KE, deepest overlap, hits.
Each scene ends with "OK <scene>" or "FAIL <scene>: <reason>".
scripts/plot.sh CSV OUTDIR plots a --csv file.
Exit status: 0 every scene held together, 1 a scene blew up, 2 bad arguments (or a damaged recording).
USAGE
    exit 0
  fi
done
scripts/install-deps.sh
echo "game.sh: building the reference game (Release, build-release/; a first build takes minutes)" >&2
cmake -S . -B build-release -DCMAKE_BUILD_TYPE=Release -DGUARDIAN_BUILD_TESTS=OFF >/dev/null
cmake --build build-release --target ReferenceGame -j "$(nproc 2>/dev/null || echo 2)" >/dev/null
exec build-release/ReferenceGame/ReferenceGame "$@"
