#!/usr/bin/env bash
# The trainer's trades: table accuracy and training time against the number of training cases;
# image PSNR of RSAA 8x (the defaults) against the similarity threshold and the bits per stored similarity
# code. Prints Markdown tables, writes CSVs and PNG charts (rsaa plot) into OUT_DIR.
# Usage: tools/trainer_trades.sh [SCENE] [OUT_DIR]   (default builtin:default out/trainer-trades)
set -euo pipefail
cd "$(dirname "$0")/.."
scene=${1:-builtin:default}
out=${2:-out/trainer-trades}
mkdir -p "$out"
rsaa=./build/rsaa

echo "### Table accuracy against training cases (d3d8x, evaluated on 10^6 fresh cases, seed 2)"
echo
echo "| training cases | train time s | masks reached | RMS one-line | RMS two-line | RMS mix |"
echo "| --- | --- | --- | --- | --- | --- |"
echo "cases,train_seconds,rms_one_line,rms_two_line,rms_mix" >"$out/cases.csv"
for cases in 1000 10000 100000 1000000 10000000; do
  dir=$out/cases-$cases
  mkdir -p "$dir"
  log=$($rsaa train --pattern d3d8x --cases "$cases" --quiet --out-dir "$dir")
  seconds=$(echo "$log" | awk '/time:/ {print $2}')
  reached=$(echo "$log" | awk '/masks reached/ {print $2}')
  read -r one two mix < <($rsaa eval-table "$dir/d3d8x.json" 2>/dev/null |
    awk '/^  one-line cases/ {k=1} /^  two-line cases/ {k=2} /^  mix cases/ {k=3}
         /^    table / {r[k]=$2} END {print r[1], r[2], r[3]}')
  echo "| $cases | $seconds | $reached | $one | $two | $mix |"
  echo "$cases,$seconds,$one,$two,$mix" >>"$out/cases.csv"
done

ref=$out/reference.png
$rsaa render --scene "$scene" --technique ssaa --samples 64 --out "$ref" >/dev/null
psnr() { $rsaa compare "$1" "$ref" | awk 'NR == 2 {print $2}'; }

echo
echo "### RSAA 8x (the defaults) on $scene against the similarity threshold"
echo
echo "| threshold | PSNR dB |"
echo "| --- | --- |"
echo "threshold,psnr_db" >"$out/threshold.csv"
for threshold in 0.05 0.1 0.2 0.4 0.8 1.6; do
  $rsaa render --scene "$scene" --technique rsaa --threshold "$threshold" --out "$out/t$threshold.png" >/dev/null
  value=$(psnr "$out/t$threshold.png")
  echo "| $threshold | $value |"
  echo "$threshold,$value" >>"$out/threshold.csv"
done

echo
echo "### RSAA 8x (the defaults) on $scene against the bits per stored similarity"
echo
echo "| code bits | bytes/px of codes | PSNR dB |"
echo "| --- | --- | --- |"
echo "code_bits,psnr_db" >"$out/bits.csv"
for bits in 8 16 32; do
  $rsaa render --scene "$scene" --technique rsaa --code-bits "$bits" --out "$out/b$bits.png" >/dev/null
  value=$(psnr "$out/b$bits.png")
  echo "| $bits | $bits | $value |"
  echo "$bits,$value" >>"$out/bits.csv"
done

$rsaa plot "$out/cases.csv" --x cases --y rms_one_line,rms_two_line,rms_mix --log-x \
  --title "d3d8x table RMS error on fresh line cases against training cases" --out "$out/cases.png" >&2
$rsaa plot "$out/cases.csv" --x cases --y train_seconds --log-x \
  --title "training time (s) against training cases, 2 cores" --out "$out/train_time.png" >&2
$rsaa plot "$out/threshold.csv" --x threshold --y psnr_db --log-x \
  --title "RSAA 8x (defaults) PSNR (dB) against the similarity threshold, $scene" --out "$out/threshold.png" >&2
$rsaa plot "$out/bits.csv" --x code_bits --y psnr_db \
  --title "RSAA 8x (defaults) PSNR (dB) against bits per similarity code, $scene" --out "$out/bits.png" >&2
