#!/usr/bin/env bash
# The coverage family's goals (issue 14) on any scenes, held-out models included: against 64x SSAA,
# dynamic coverage (default rules) within 1.5 dB of hardware 4x MSAA and never below no AA, DCAA at
# or above 4x MSAA, AGAA 8x at or above 4x MSAA - 0.25 dB, each at least 3 dB over no AA; and with
# --scale, every technique's image of the scene scaled by 10^3 and 10^-3 against its unscaled
# image (goal: >= 50 dB). Prints Markdown tables (a failed goal is marked with "!") and keeps the
# images in OUT_DIR/<scene>/.
# Usage: tools/coverage_goals.sh [--width W] [--height H] [--scale] [--out-dir DIR] SCENE...
set -euo pipefail
cd "$(dirname "$0")/.."
width=640 height=480 scale=0 out=out/coverage-goals
while [[ $# -gt 0 ]]; do
  case $1 in
    --width) width=${2:?}; shift 2 ;;
    --height) height=${2:?}; shift 2 ;;
    --scale) scale=1; shift ;;
    --out-dir) out=${2:?}; shift 2 ;;
    -h | --help) sed -n 2,8p "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "coverage_goals.sh: unknown option $1" >&2; exit 2 ;;
    *) break ;;
  esac
done
script=coverage_goals.sh
# shellcheck source=tools/scene_images.sh
source tools/scene_images.sh
check_scenes_and_build "$@"
mark() { awk -v v="$1" -v ok="$2" 'BEGIN {printf "%.2f%s", v, (ok ? "" : " !")}'; }

quality=("noaa" "msaa --samples 4" "dyncov" "dcaa" "agaa --samples 8")
scaled=("noaa" "fxaa" "msaa --samples 4" "ssaa --samples 8" "ssaa-filtered" "rsaa --samples 8" "rsaa --samples 4"
  "dcaa" "dcaa --shade surface" "dyncov" "dyncov --rules seed" "agaa --samples 4" "agaa --samples 8")
quality_rows=() scale_rows=()
for scene in "$@"; do
  name=$(basename "${scene#builtin:}"); name=${name%.*}
  dir=$out/$name
  mkdir -p "$dir"
  echo "coverage_goals: $scene" >&2
  render "$scene" "$dir/reference.png" --technique ssaa --samples 64
  declare -A p=()
  for t in "${quality[@]}"; do
    file=$dir/$(tr -d ' -' <<<"$t").png
    # shellcheck disable=SC2086
    render "$scene" "$file" --technique $t
    p[$t]=$(psnr "$file" "$dir/reference.png")
  done
  n=${p[noaa]} m=${p[msaa --samples 4]} y=${p[dyncov]} d=${p[dcaa]} a=${p[agaa --samples 8]}
  ok() { awk "BEGIN {exit !($1)}" && echo 1 || echo 0; }
  quality_rows+=("| $name | $n | $m | $(mark "$y" "$(ok "$y >= $m - 1.5 && $y >= $n + 3")") | $(mark "$d" "$(ok "$d >= $m && $d >= $n + 3")") | $(mark "$a" "$(ok "$a >= $m - 0.25 && $a >= $n + 3")") |")
  echo "  ${quality_rows[-1]}" >&2
  if [[ $scale == 1 ]]; then
    row="| $name |"
    for t in "${scaled[@]}"; do
      file=$dir/scale1-$(tr -d ' -' <<<"$t").png
      # shellcheck disable=SC2086
      render "$scene" "$file" --technique $t
      worst=""
      for factor in 1000 0.001; do
        # shellcheck disable=SC2086
        render "$scene" "$dir/scaled.png" --technique $t --scene-scale $factor
        q=$(psnr "$dir/scaled.png" "$file")
        worst=$(awk -v a="$worst" -v b="$q" 'BEGIN {print (a == "" || b + 0 < a + 0) ? b : a}')
      done
      row+=" $(mark "$worst" "$(ok "$worst >= 50")") |"
    done
    scale_rows+=("$row")
    echo "  scaled: $row" >&2
  fi
done

echo "PSNR dB against 64x SSAA at ${width}x${height} (! = goal missed: dyncov >= msaa - 1.5 and >= noaa + 3;"
echo "dcaa >= msaa and >= noaa + 3; agaa 8x >= msaa - 0.25 and >= noaa + 3):"
echo
echo "| scene | noaa | msaa 4x | dyncov | dcaa | agaa 8x |"
echo "| --- | --- | --- | --- | --- | --- |"
printf '%s\n' "${quality_rows[@]}"
if [[ $scale == 1 ]]; then
  echo
  echo "The scene scaled by 10^3 and 10^-3 against the unscaled image, the lower of the two PSNR dB (! = below 50):"
  echo
  header="| scene |" rule="| --- |"
  for t in "${scaled[@]}"; do header+=" ${t//--samples /} |"; rule+=" --- |"; done
  echo "$header"
  echo "$rule"
  printf '%s\n' "${scale_rows[@]}"
fi
