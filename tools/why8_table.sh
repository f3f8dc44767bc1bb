#!/usr/bin/env bash
# The README's *Why 8 subsamples gain about 1 dB over 4* table, condensed from the diagnoses
# `tools/readme_figures.sh` writes (DIR/NAME-samples4.md and DIR/NAME-samples8.md, from
# `rsaa diagnose --scene S --samples 4|8`): per scene RSAA 4x -> 8x, the exact coverage of the 1x
# colours, its room over 4x, and RSAA's squared error per pixel class in percent of no AA's
# whole-image error (the class's share of RSAA's error times RSAA's error over no AA's).
# Usage: tools/why8_table.sh DIR NAME...   (e.g. out/figures/diagnosis default 2CylinderEngine)
set -euo pipefail
[[ $# -ge 2 ]] || { sed -n 2,7p "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
dir=$1
shift
# Prints, for one diagnosis file: RSAA dB, exact coverage dB, then the five class columns.
summary() {
  awk '
    function db(text, name,   i, n, f) {  # the number before " dB" after `name` in the headline
      i = index(text, name); if (!i) return ""
      n = split(substr(text, i + length(name)), f, " "); return f[1]
    }
    /^rsaa .* on .*: RSAA / { rsaa = db($0, ": RSAA "); noaa = db($0, "no AA "); exact = db($0, "colours ") }
    /^\| [123]/ {
      split($0, c, "|"); name = c[2]; gsub(/^ +| +$/, "", name); share = c[4]; sub(/%.*/, "", share)
      if (name ~ /unseen/) unseen += share
      else if (name ~ /^2 surfaces/) edges += share
      else if (name ~ /^3\+/) three += share
      else rest += share
      classes++
    }
    END {
      if (rsaa == "" || noaa == "" || exact == "" || classes == 0) { print "no diagnosis table in " FILENAME > "/dev/stderr"; exit 1 }
      all = 100 * exp((noaa - rsaa) / 10 * log(10))
      printf "%s %s %.1f %.1f %.1f %.1f %.1f\n", rsaa, exact, all, all * unseen / 100, all * edges / 100,
             all * three / 100, all * rest / 100
    }' "$1"
}
for name in "$@"; do
  for n in 4 8; do
    [[ -f $dir/$name-samples$n.md ]] || { echo "why8_table.sh: no $dir/$name-samples$n.md" >&2; exit 1; }
  done
done
echo "| scene | RSAA 4x -> 8x | exact coverage | room over 4x | all pixels | unseen by the subsamples | 2-surface edges | 3+ surfaces | one surface, or no other colour nearby |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
for name in "$@"; do
  four=$(summary "$dir/$name-samples4.md")
  eight=$(summary "$dir/$name-samples8.md")
  read -r db4 exact a4 u4 e4 t4 r4 <<<"$four"
  read -r db8 _ a8 u8 e8 t8 r8 <<<"$eight"
  room=$(awk -v e="$exact" -v r="$db4" 'BEGIN {printf "%.2f", e - r}')
  echo "| $name | $db4 -> $db8 dB | $exact dB | $room dB | $a4 -> $a8 | $u4 -> $u8 | $e4 -> $e8 | $t4 -> $t8 | $r4 -> $r8 |"
done
