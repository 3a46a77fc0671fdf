#!/usr/bin/env bash
# Reads bench_tradeoff's CSV and names, per scene, two settings on its Pareto front: "casual game", the
# cheapest front setting whose error is within 1 cm (or 1 cm/s, or 1e-3 relative energy), and "precise
# simulation", the cheapest within 1 mm (1 mm/s, 1e-5). Prints a Markdown table. Usage: tradeoff_pick.sh CSV
set -euo pipefail
awk -F, '
  NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
  $col["pareto"] == 1 {
    s = $col["scene"]
    if (!(s in seen)) { seen[s] = 1; order[++n] = s }
    u = $col["error_unit"]
    casual = (u == "relative energy") ? 1e-3 : 1e-2
    precise = (u == "relative energy") ? 1e-5 : 1e-3
    label = $col["varied"]
    if (label != "baseline") {
      m = split(label, knobs, "*"); label = ""
      for (k = 1; k <= m; ++k) label = label (k > 1 ? ", " : "") knobs[k] " " $col[knobs[k]]
    }
    cost = $col["cost_ratio"] + 0; err = $col["error"] + 0
    line = sprintf("%s (x%.2f, %.3g %s)", label, cost, err, u)
    if (err <= casual && (!(s in cc) || cost < cc[s])) { cc[s] = cost; ct[s] = line }
    if (err <= precise && (!(s in pc) || cost < pc[s])) { pc[s] = cost; pt[s] = line }
  }
  END {
    print "| scene | casual game | precise simulation |"
    print "|---|---|---|"
    for (i = 1; i <= n; ++i) {
      s = order[i]
      print "| " s " | " (s in ct ? ct[s] : "none within 1 cm") " | " (s in pt ? pt[s] : "none within 1 mm") " |"
    }
  }
' "$1"
