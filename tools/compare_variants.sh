#!/usr/bin/env bash
# Renders the references, all 12 RSAA variants of the paper and RSAA's defaults of a scene and compares each with 64x SSAA
# (rsaa compare). Prints a Markdown table and keeps the images in OUT_DIR.
# Usage: tools/compare_variants.sh [SCENE] [WIDTH] [HEIGHT] [OUT_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
scene=${1:-builtin:default}
width=${2:-640}
height=${3:-480}
name=$(basename "${scene#builtin:}")
name=${name%.*}
out=${4:-out/compare/$name}
mkdir -p "$out"
rsaa=./build/rsaa

techniques=(
  "noaa" "msaa --samples 4" "ssaa --samples 8" "ssaa --samples 16" "dyncov" "dcaa" "agaa --samples 4" "agaa --samples 8"
)
# The paper's variants: its split and its single fetch (ours are the defaults).
paper="--split-cap 0 --multi-surface fetch --split-check off --fetch-check off --material-edges off"
for samples in 4 8; do
  for similarity in sadp depth; do
    for auth in 0 1 2; do
      techniques+=("rsaa --samples $samples --similarity $similarity --auth $auth $paper")
    done
  done
  techniques+=("rsaa --samples $samples")  # the defaults: sadp-plane, auth 1, split cap, multi-surface, split check
done

file_of() {
  echo "$out/$(echo "$1" | sed "s/ $paper//; s/--samples /x/; s/--similarity //; s/--auth /auth/; s/ //g").png"
}

echo "rendering $scene at ${width}x${height} into $out" >&2
$rsaa render --scene "$scene" --technique ssaa --samples 64 --width "$width" --height "$height" \
  --out "$out/reference.png" >/dev/null
noaa_psnr=""
noaa_ms=""
{
echo "| technique | PSNR dB | gain over noaa | SSIM | luma error > 1/64 | frame ms (ratio to noaa) | bytes/px |"
echo "| --- | --- | --- | --- | --- | --- | --- |"
for t in "${techniques[@]}"; do
  file=$(file_of "$t")
  # Every step says what failed (a failing command substitution would end the script silently).
  # shellcheck disable=SC2086
  log=$($rsaa render --scene "$scene" --technique $t --width "$width" --height "$height" --out "$file") ||
    { echo "compare_variants: rsaa render --technique $t failed (exit $?)" >&2; exit 1; }
  label=${log%%:*}
  ms=$(awk '/GL timer query/ {sum += $2} END {printf "%.1f", sum}' <<<"$log")
  bytes=$(awk '/bytes\/pixel/ {print $2}' <<<"$log")
  comparison=$($rsaa compare "$file" "$out/reference.png") ||
    { echo "compare_variants: rsaa compare $file failed (exit $?)" >&2; exit 1; }
  read -r psnr ssim luma <<<"$(awk 'NR == 2 {print $2, $5, $10}' <<<"$comparison")"
  luma=${luma%\%}
  [ -n "$noaa_psnr" ] || { noaa_psnr=$psnr; noaa_ms=$ms; }
  gain=$(awk -v a="$psnr" -v b="$noaa_psnr" 'BEGIN {printf "%+.2f", a - b}')
  ratio=$(awk -v a="$ms" -v b="$noaa_ms" 'BEGIN {if (b > 0) printf "%.2f", a / b; else printf "-"}')
  echo "| $label | $psnr | $gain | $ssim | $luma% | $ms ($ratio) | $bytes |"
done
} | tee "$out/table.md"
