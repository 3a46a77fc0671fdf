#!/usr/bin/env bash
# Runs the full extremes suite (tests/extremes, ctest label `extremes`) with GUARDIAN_EXTREMES=full: wider
# ranges (mass ratios 1:10 to 1:10^4, speeds 10^2 to 10^4 m/s at 50 start phases, cubes of 1 mm to 1 km,
# offsets 10^2 to 10^6 m) and a 10^6-step soak. CI runs the short version (same tests, GUARDIAN_EXTREMES
# unset) with everything else. Each measured number is printed as a line "extremes: <case> = <value>".
# Usage: scripts/extremes.sh [BUILD_DIR]   (default build; configured RelWithDebInfo and built if needed)
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-build}
scripts/install-deps.sh
cmake -S . -B "$dir" -DGUARDIAN_WERROR=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$dir" -j "$(nproc 2>/dev/null || echo 2)" --target extremes_tests
log="$dir/extremes-full.log"
status=0
GUARDIAN_EXTREMES=full ctest --test-dir "$dir" -L extremes --output-on-failure -V >"$log" 2>&1 || status=$?
grep -E "extremes: |tests passed|\(Failed\)" "$log" | sed -E 's/^[0-9]+: //'
echo "full log: $log"
exit $status
