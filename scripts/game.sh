#!/usr/bin/env bash
# Builds the reference game (Release) and runs it headless; arguments go to the game.
# Usage: scripts/game.sh [--scene NAME|all] [--frames N] [--image DIR [--image-every N]] [--list] [--help]
set -euo pipefail
cd "$(dirname "$0")/.."
for arg in "$@"; do
  if [ "$arg" = "--help" ] || [ "$arg" = "-h" ]; then
    cat <<'USAGE'
usage: scripts/game.sh [--scene NAME|all] [--frames N] [--image DIR [--image-every N]] [--list] [--help]
Builds the reference game (Release, in build-release/) and runs it headless with these arguments
(--help builds nothing):
  --scene NAME|all  the scene to run, or every scene in turn (default: pyramid)
  --frames N        frames per scene on a stepped 16 ms clock, N > 0 (default: 600, about 10 s)
  --image DIR       write the scene's debug drawing as DIR/<scene>_<frame>.svg (DIR must exist)
  --image-every N   ... every N frames, N > 0, and at the last frame (default: 60)
  --list            name and describe the scenes, then exit
  --help            print this and exit
Each scene ends with "OK <scene>" or "FAIL <scene>: <reason>".
Exit status: 0 every scene held together, 1 a scene blew up, 2 bad arguments.
USAGE
    exit 0
  fi
done
scripts/install-deps.sh
echo "game.sh: building the reference game (Release, build-release/; a first build takes minutes)" >&2
cmake -S . -B build-release -DCMAKE_BUILD_TYPE=Release -DGUARDIAN_BUILD_TESTS=OFF >/dev/null
cmake --build build-release --target ReferenceGame -j "$(nproc 2>/dev/null || echo 2)" >/dev/null
exec build-release/ReferenceGame/ReferenceGame "$@"
