#!/usr/bin/env bash
# Builds bench_tradeoff (Release, build-rel/), runs it and plots its CSV with gnuplot: for each scene, the
# error against the truth over the cost ratio to the baseline (log scales), the Pareto front joined and
# labelled. Usage: scripts/tradeoff.sh [--quick] OUTDIR   (writes OUTDIR/tradeoff.csv and OUTDIR/*.png)
set -euo pipefail
cd "$(dirname "$0")/.."
quick=()
if [ "${1:-}" = "--quick" ]; then
  quick=(--quick)
  shift
fi
if [ $# -ne 1 ] || [ "$1" = "--help" ] || [ "$1" = "-h" ]; then
  echo "usage: scripts/tradeoff.sh [--quick] OUTDIR" >&2
  exit 2
fi
out=$1
mkdir -p "$out"
command -v gnuplot >/dev/null || apt-get install -y gnuplot-nox >/dev/null
cmake -S . -B build-rel -DCMAKE_BUILD_TYPE=Release -DGUARDIAN_BUILD_BENCH=ON >/dev/null
cmake --build build-rel -j2 --target bench_tradeoff >/dev/null
build-rel/bench/tradeoff/bench_tradeoff "${quick[@]}" --out "$out/tradeoff.csv"
scripts/tradeoff_plot.sh "$out/tradeoff.csv" "$out"
