#!/usr/bin/env bash
# The trainer's trades, as Markdown tables: table accuracy and training time against the number
# of training cases; image PSNR of RSAA 8x SADP against the similarity threshold and the bits
# per stored similarity code. Usage: tools/trainer_trades.sh [SCENE]   (default builtin:default)
set -euo pipefail
cd "$(dirname "$0")/.."
scene=${1:-builtin:default}
out=out/trainer-trades
mkdir -p "$out"
rsaa=./build/rsaa

echo "### Table accuracy against training cases (d3d8x, evaluated on 10^6 fresh cases, seed 2)"
echo
echo "| training cases | train time s | masks reached | RMS one-line | RMS two-line | RMS mix |"
echo "| --- | --- | --- | --- | --- | --- |"
for cases in 1000 10000 100000 1000000 10000000; do
  dir=$out/cases-$cases
  mkdir -p "$dir"
  log=$($rsaa train --pattern d3d8x --cases "$cases" --quiet --out-dir "$dir")
  seconds=$(echo "$log" | awk '/time:/ {print $2}')
  fitted=$(echo "$log" | awk '/masks reached/ {print $2}')
  read -r one two mix < <($rsaa eval-table "$dir/d3d8x.json" 2>/dev/null |
    awk '/^  one-line cases/ {k=1} /^  two-line cases/ {k=2} /^  mix cases/ {k=3}
         /^    table / {r[k]=$2} END {print r[1], r[2], r[3]}')
  echo "| $cases | $seconds | $fitted | $one | $two | $mix |"
done

ref=$out/reference.png
$rsaa render --scene "$scene" --technique ssaa --samples 64 --out "$ref" >/dev/null
psnr() { $rsaa compare "$1" "$ref" | awk 'NR == 2 {print $2}'; }

echo
echo "### RSAA 8x SADP (auth 0) on $scene against the similarity threshold"
echo
echo "| threshold | PSNR dB |"
echo "| --- | --- |"
for threshold in 0.05 0.1 0.2 0.4 0.8 1.6; do
  $rsaa render --scene "$scene" --technique rsaa --threshold "$threshold" --out "$out/t$threshold.png" >/dev/null
  echo "| $threshold | $(psnr "$out/t$threshold.png") |"
done

echo
echo "### RSAA 8x SADP (auth 0) on $scene against the bits per stored similarity"
echo
echo "| code bits | bytes/px of codes | PSNR dB |"
echo "| --- | --- | --- |"
for bits in 8 16 32; do
  $rsaa render --scene "$scene" --technique rsaa --code-bits "$bits" --out "$out/b$bits.png" >/dev/null
  echo "| $bits | $((bits)) | $(psnr "$out/b$bits.png") |"
done
