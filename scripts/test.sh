#!/usr/bin/env bash
# Builds and runs every test: a warnings-as-errors build, then an AddressSanitizer+UBSan build.
# Usage: scripts/test.sh [--quick]   (--quick: skip the sanitizer build)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)

run_suite() { # NAME BUILD_DIR CMAKE_ARGS...
  local name=$1 dir=$2
  shift 2
  echo "== $name: configure, build, test ($dir)"
  cmake -S . -B "$dir" -DGUARDIAN_WERROR=ON "$@" >/dev/null
  cmake --build "$dir" -j "$jobs"
  ctest --test-dir "$dir" -j "$jobs" --output-on-failure
}

run_suite "warnings-as-errors" build -DCMAKE_BUILD_TYPE=RelWithDebInfo
if [ "${1:-}" != "--quick" ]; then
  run_suite "sanitizers (ASan+UBSan)" build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGUARDIAN_SANITIZE=ON
fi
