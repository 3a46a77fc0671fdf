#!/usr/bin/env bash
# Measures what the double-precision simulator (GUARDIAN_DOUBLE) buys and costs: builds precision_report
# against the float and the double library (Release, build-rel) and runs them back to back, the pyramid's
# timing interleaved (float, double, float, double ...) so that both see the same machine load.
# Usage: scripts/precision.sh [ROUNDS]   (ROUNDS of the awake-pyramid timing per build, default 3)
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-3}
cmake -S . -B build-rel -DCMAKE_BUILD_TYPE=Release -DGUARDIAN_WERROR=OFF -DGUARDIAN_BUILD_TESTBED=OFF >/dev/null
cmake --build build-rel -j "$(nproc 2>/dev/null || echo 2)" --target precision_report precision_report_double
dir=build-rel/tests/double
"$dir/precision_report" 1
"$dir/precision_report_double" 1
for _ in $(seq "$rounds"); do
  "$dir/precision_report" pyramid
  "$dir/precision_report_double" pyramid
done
