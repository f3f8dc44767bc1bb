#!/usr/bin/env bash
# The README's summary of the cell patterns, condensed from the per-scene table that
# tools/cell_patterns.sh writes (OUT_DIR/cell-patterns.md): per table its subsamples and draws,
# line RMS, PSNR on the named scenes (default: the bench's four, default, 2CylinderEngine,
# CesiumMilkTruck and spider, those in the table), the mean over every scene, the mean and lowest
# difference to d3d8x, and the scenes where it is below hardware 4x MSAA.
# Usage: tools/cell_patterns_summary.sh CELL_PATTERNS_MD [SCENE...]
set -euo pipefail
[[ $# -ge 1 && -f $1 ]] || { sed -n 2,7p "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
file=$1
shift
[[ $# -gt 0 ]] || set -- default 2CylinderEngine CesiumMilkTruck spider
awk -v shown_names="$*" '
  function trim(s) { gsub(/^ +| +$/, "", s); return s }
  BEGIN {
    draws["d3d8x"] = "8, 8 jittered draws writing records"; draws["custom-gl4x-union"] = "8, two 4x draws"
    draws["custom-gl4x-wide"] = "8, one 4x draw at 2W x H"; draws["custom-gl4x-tall"] = "8, one 4x draw at W x 2H"
    draws["custom-gl4x-quad"] = "16, one 4x draw at 2W x 2H"; draws["d3d16x"] = "16, 16 jittered draws writing records"
  }
  /^\| table \| subsamples \| line RMS \|/ {
    n = split($0, c, "|"); scenes = n - 7  # "", table, subsamples, line RMS, scenes..., mean, lowest, ""
    for (i = 1; i <= scenes; ++i) name[i] = trim(c[4 + i])
    header = 1; next
  }
  header && /^\| ---/ { next }
  header && /^\|/ {
    split($0, c, "|"); label = trim(c[2]); rows[++count] = label
    rms[label] = trim(c[4])
    for (i = 1; i <= scenes; ++i) db[label, i] = trim(c[4 + i])
    next
  }
  header && !/^\|/ { header = 0 }
  END {
    if (!scenes || !("d3d8x" in rms)) { print "cell_patterns_summary.sh: no cell-patterns table with a d3d8x row" > "/dev/stderr"; exit 1 }
    first = 0
    m = split(shown_names, wanted, " ")
    for (k = 1; k <= m; ++k) for (i = 1; i <= scenes; ++i) if (name[i] == wanted[k]) shown[++first] = i
    msaa = rows[1]
    printf "| table | subsamples, draws | line RMS |"
    for (i = 1; i <= first; ++i) printf " %s |", name[shown[i]]
    printf " mean of %d scenes | mean - d3d8x | lowest - d3d8x | below 4x MSAA |\n", scenes
    printf "| --- | --- | --- |"; for (i = 1; i <= first; ++i) printf " --- |"; print " --- | --- | --- | --- |"
    printf "| hardware 4x MSAA | 4 | - |"; for (i = 1; i <= first; ++i) printf " %s |", db[msaa, shown[i]]; print " - | - | - | - |"
    for (r = 2; r <= count; ++r) {
      label = rows[r]; sum = 0; diff = 0; low = 1e9; below = ""
      for (i = 1; i <= scenes; ++i) {
        sum += db[label, i]; d = db[label, i] - db["d3d8x", i]; diff += d; if (d < low) low = d
        if (db[label, i] < db[msaa, i]) below = below (below == "" ? "" : ", ") name[i]
      }
      title = label (label == "d3d8x" ? " (RSAA 8x'"'"'s default)" : "")
      printf "| %s | %s | %s |", title, (label in draws ? draws[label] : "-"), rms[label]
      for (i = 1; i <= first; ++i) printf " %s |", db[label, shown[i]]
      if (label == "d3d8x") printf " %.2f | 0 | 0 |", sum / scenes
      else printf " %.2f | %+.2f | %+.2f |", sum / scenes, diff / scenes, low
      printf " %s |\n", below == "" ? "none" : below
    }
  }' "$file"
