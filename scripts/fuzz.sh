#!/usr/bin/env bash
# Runs a fuzz campaign: guardian_fuzz (tests/fuzz) over seeds FIRST .. FIRST+COUNT-1 in chunks of 500, JOBS
# chunks at a time, at low priority. Build the ASan+UBSan fuzzer first:
#   cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGUARDIAN_SANITIZE=ON
#   cmake --build build-asan --target guardian_fuzz
# Usage: scripts/fuzz.sh FIRST COUNT [JOBS] [BUILD_DIR]   e.g. scripts/fuzz.sh 100000 20000 2
# Each chunk's output is in fuzz-logs/FIRST.log; a failed chunk is listed at the end (rerun it with
# guardian_fuzz --first-seed S --count 500 --verbose to see which seed). Exit status 1 if any failed.
set -uo pipefail
cd "$(dirname "$0")/.."
first=${1:?FIRST seed}
count=${2:?COUNT}
jobs=${3:-2}
dir=${4:-build-asan}
fuzz="$dir/tests/fuzz/guardian_fuzz"
[ -x "$fuzz" ] || { echo "no $fuzz: build the guardian_fuzz target first" >&2; exit 2; }
mkdir -p fuzz-logs
rm -f fuzz-logs/FAILED
chunk=500
seq "$first" "$chunk" $((first + count - 1)) |
  xargs -P "$jobs" -I{} sh -c "n=\$(( $first + $count - {} )); [ \$n -gt $chunk ] && n=$chunk; \
    nice -n 10 '$fuzz' --first-seed {} --count \$n --calls 300 > fuzz-logs/{}.log 2>&1 || echo {} >> fuzz-logs/FAILED"
if [ -s fuzz-logs/FAILED ]; then
  echo "failed chunks (first seed of each):"
  sort -n fuzz-logs/FAILED
  exit 1
fi
echo "all $count sequences passed (seeds $first..$((first + count - 1)))"
