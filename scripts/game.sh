#!/usr/bin/env bash
# Builds the reference game (Release) and runs it headless; arguments go to the game.
# Usage: scripts/game.sh [--scene NAME] [--frames N]
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build-release -DCMAKE_BUILD_TYPE=Release -DGUARDIAN_BUILD_TESTS=OFF >/dev/null
cmake --build build-release --target ReferenceGame -j "$(nproc 2>/dev/null || echo 2)" >/dev/null
exec build-release/ReferenceGame/ReferenceGame "$@"
