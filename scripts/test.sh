#!/usr/bin/env bash
# Builds and runs every test: a warnings-as-errors build (g++), then the same with clang++ (portable C++17),
# instrumented with AddressSanitizer+UBSan and built for AVX when the CPU has it. The g++ build compiles each
# shipped file (Interfaces/, Physics/, Collision/, Framework/, ReferenceGame/) on its own, so a missing include
# fails there; the test programs, the double-precision companion library and the clang++ pass are unity builds
# (several files per compiler run, which saves most of the time spent parsing and instantiating Eigen and
# GoogleTest again), and the package tests' own projects are compiled by clang++ (tests/integration). Each pass
# prints how long it took to build and to test.
# Usage: scripts/test.sh [--quick]   (--quick: the g++ build only, no clang++ build)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
echo "== dependencies ready after $SECONDS s"
jobs=$(nproc 2>/dev/null || echo 2)

run_suite() { # NAME BUILD_DIR CTEST_ARGS -- CMAKE_ARGS...
  local name=$1 dir=$2 ctest_args=$3
  shift 4
  echo "== $name: configure, build, test ($dir)"
  local start=$SECONDS
  cmake -S . -B "$dir" -DGUARDIAN_WERROR=ON "$@" >/dev/null
  cmake --build "$dir" -j "$jobs"
  local built=$SECONDS
  # shellcheck disable=SC2086
  ctest --test-dir "$dir" -j "$jobs" --output-on-failure $ctest_args
  echo "== $name: built in $((built - start)) s, tested in $((SECONDS - built)) s"
}

# Line tables only (-g1, not -g): a failure's backtrace keeps its file and line, and the compiler writes a
# fifth less (variable and type information is what takes the time).
lines_only=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG")
run_suite "warnings-as-errors" build "" -- "${lines_only[@]}"
if [ "${1:-}" != "--quick" ]; then
  # Everything compiles warning-free with clang++ too (Debian 12: clang 14), instrumented with AddressSanitizer
  # and UBSan, the reference implementations; clang++ builds the instrumented code three times faster than g++
  # (a unity file of Physics/: 22 s against 65 s). On a CPU with AVX this pass is built for it (GUARDIAN_AVX:
  # the contact solver's eight-lane blocks), so the determinism hashes are checked at both widths (the g++
  # pass keeps the default four) and the eight-lane code runs under the sanitizers. UBSan skips Eigen's
  # headers (scripts/ubsan-ignore.txt): this pass's tests in half the CPU time.
  # The package and install tests build projects of their own without sanitizers; they and the testbed window
  # ran in the g++ pass: not run again. The double-precision companion library and its tests ran above too
  # (GUARDIAN_DOUBLE_COMPANION). So did the ten-second awake pyramid (13 s under ASan+UBSan, as long as the
  # rest of this pass's tests together): its solver code runs here in shorter tests, and the determinism hashes
  # checked here say the eight lanes give the four lanes' bits (for the two reference scenes). The extremes
  # suite (NaN, mass ratios, sizes, speeds, degenerate shapes and steps, the soak) runs here: 2.3 s since UBSan
  # left Eigen's headers (its soak alone had taken 41 s).
  avx=OFF
  if grep -qw avx /proc/cpuinfo 2>/dev/null; then avx=ON; fi
  run_suite "clang++ with sanitizers (ASan+UBSan, AVX $avx)" build-asan "-LE integration -E ^Resolution.PyramidOf210Boxes" -- \
    "${lines_only[@]}" -DCMAKE_CXX_COMPILER=clang++ -DGUARDIAN_SANITIZE=ON -DCMAKE_UNITY_BUILD=ON \
    -DGUARDIAN_BUILD_TESTBED=OFF -DGUARDIAN_DOUBLE_COMPANION=OFF -DGUARDIAN_AVX=$avx
fi
