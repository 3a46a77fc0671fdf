#!/usr/bin/env bash
# Plots a CSV written by `ReferenceGame --csv FILE` with gnuplot: kinetic energy, awake bodies and the deepest
# overlap over time, as PNG (pngcairo) files in OUTDIR: NAME-kinetic.png, NAME-awake.png, NAME-overlap.png
# and the three stacked in NAME.png, NAME being the CSV's file name without .csv.
# Installs nothing: it needs gnuplot (Debian: apt-get install gnuplot-nox).
set -euo pipefail
usage() {
  cat <<'USAGE'
usage: scripts/plot.sh CSV OUTDIR
Plots a ReferenceGame --csv file (kinetic energy, awake bodies, deepest overlap against time) as PNG
files in OUTDIR: NAME-kinetic.png, NAME-awake.png, NAME-overlap.png and all three in NAME.png.
Needs gnuplot with pngcairo (Debian: apt-get install gnuplot-nox).
Exit status: 0 plotted, 2 bad arguments or an unreadable CSV, 3 gnuplot missing.
USAGE
}
if [ $# -eq 1 ] && { [ "$1" = "--help" ] || [ "$1" = "-h" ]; }; then usage; exit 0; fi
if [ $# -ne 2 ]; then usage >&2; exit 2; fi
csv=$1 out=$2
if [ ! -r "$csv" ] || ! head -n 1 "$csv" | grep -q '^time_s,.*kinetic_energy_J.*awake_bodies.*overlap_m'; then
  echo "plot.sh: $csv is not a readable ReferenceGame --csv file" >&2
  exit 2
fi
case "$csv$out" in *'"'*) echo "plot.sh: no double quotes in file names, please" >&2; exit 2 ;; esac
if ! command -v gnuplot >/dev/null 2>&1; then
  echo "plot.sh: gnuplot is missing; install it with: sudo apt-get install gnuplot-nox" >&2
  exit 3
fi
mkdir -p "$out"
name=$(basename "$csv" .csv)
gnuplot <<GNUPLOT
set datafile separator ","
set key off
set grid
set xlabel "time (s)"
set style data lines
ke = 'plot "$csv" using "time_s":"kinetic_energy_J" lw 2 lc rgb "#1f77b4"'
awake = 'plot "$csv" using "time_s":"awake_bodies" lw 2 lc rgb "#2ca02c", "" using "time_s":"moving_bodies" dt 2 lc rgb "gray"'
overlap = 'plot "$csv" using "time_s":(1000*column("overlap_m")) lw 2 lc rgb "#d62728"'
set terminal pngcairo size 800,360 font ",10"
set output "$out/$name-kinetic.png"
set title "$name: kinetic energy (J)"
@ke
set output "$out/$name-awake.png"
set title "$name: awake bodies (dashed: all moving bodies)"
set yrange [0:*]
@awake
set output "$out/$name-overlap.png"
set title "$name: deepest overlap left by the solver (mm)"
@overlap
set autoscale y
set terminal pngcairo size 640,720 font ",9"
set output "$out/$name.png"
set multiplot layout 3,1 title "$name (ReferenceGame --csv)"
set title "kinetic energy (J)"
@ke
set title "awake bodies (dashed: all moving bodies)"
set yrange [0:*]
@awake
set autoscale y
set title "deepest overlap left by the solver (mm)"
@overlap
unset multiplot
GNUPLOT
echo "plot.sh: wrote $out/$name.png, $out/$name-kinetic.png, $out/$name-awake.png, $out/$name-overlap.png"
