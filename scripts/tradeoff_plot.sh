#!/usr/bin/env bash
# Plots bench_tradeoff's CSV: one PNG per scene (OUTDIR/tradeoff-SCENE.png) and all scenes on one page
# (OUTDIR/tradeoff-all.png). x: cost ratio to the scene's baseline, y: error against the truth, both log;
# an error of exactly 0 is drawn at 1e-9. The Pareto front (the CSV's pareto column, computed by the
# tool) is joined by a line and labelled with what its settings vary;
# the baseline, run against itself, is circled (its cost ratio shows the run's noise). Usage: tradeoff_plot.sh CSV OUTDIR
set -euo pipefail
csv=$1
out=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# Per scene: all.dat (cost error) and front.dat (cost error label), sorted by cost.
awk -F, -v dir="$tmp" '
  NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
  {
    s = $col["scene"]; cost = $col["cost_ratio"]; err = $col["error"] + 0
    if (err <= 0) err = 1e-9
    if (!(s in seen)) { seen[s] = 1; order[++n] = s; unit[s] = $col["error_unit"] }
    print cost, err > (dir "/" s ".all")
    if ($col["varied"] == "baseline") print cost, err > (dir "/" s ".base")
    if ($col["pareto"] == 1) {
      label = ""
      if ($col["varied"] == "baseline") label = "baseline"
      else {
        m = split($col["varied"], knobs, "*")
        for (k = 1; k <= m; ++k) label = label (k > 1 ? " " : "") knobs[k] "=" $col[knobs[k]]
      }
      print cost, err, "\"" label "\"" > (dir "/" s ".front.unsorted")
    }
  }
  END { for (i = 1; i <= n; ++i) print order[i] "\t" unit[order[i]] > (dir "/scenes") }
' "$csv"
for f in "$tmp"/*.front.unsorted; do sort -g -k1,1 "$f" > "${f%.unsorted}"; done
plot_scene() { # scene unit
  printf 'set title "%s" noenhanced\nset xlabel "cost ratio to the baseline (same engine time)"\n' "$1"
  printf 'set ylabel "error (%s)" noenhanced\n' "$2"
  printf 'plot "%s/%s.all" using 1:2 with points pt 7 ps 0.6 lc rgb "#888888" title "settings", ' "$tmp" "$1"
  printf '"%s/%s.front" using 1:2 with linespoints pt 7 ps 0.9 lw 2 lc rgb "#c0392b" title "Pareto front", ' "$tmp" "$1"
  printf '"%s/%s.base" using 1:2 with points pt 6 ps 2 lw 2 lc rgb "#2471a3" title "baseline (against itself)", ' "$tmp" "$1"
  printf '"%s/%s.front" using 1:2:3 with labels offset 0.6,0.5 left font ",7" noenhanced notitle\n' "$tmp" "$1"
}
common='set logscale xy; set grid; set key below font ",8"; set format y "%.0e"'
while IFS=$'\t' read -r scene unit; do
  {
    echo "set terminal pngcairo size 800,560 font ',10'"
    echo "set output '$out/tradeoff-$scene.png'"
    echo "$common"
    plot_scene "$scene" "$unit"
  } | gnuplot
done < "$tmp/scenes"
{
  echo "set terminal pngcairo size 1500,1300 font ',8'"
  echo "set output '$out/tradeoff-all.png'"
  echo "$common"
  echo "set multiplot layout 4,3"
  while IFS=$'\t' read -r scene unit; do plot_scene "$scene" "$unit"; done < "$tmp/scenes"
  echo "unset multiplot"
} | gnuplot
echo "tradeoff_plot.sh: $(wc -l < "$tmp/scenes") scenes plotted into $out" >&2
