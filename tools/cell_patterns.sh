#!/usr/bin/env bash
# 8 (and 16) subsamples on a 4-sample driver from one multisample draw: the cell patterns (the
# driver's 4x positions in each cell of the pixel split 2 x 1 (tables/custom-gl4x-wide.json, a draw
# at twice the width), 1 x 2 (custom-gl4x-tall.json, twice the height) or 2 x 2
# (custom-gl4x-quad.json, 16 subsamples, twice both)) against d3d8x (RSAA 8x's default table), the
# union pattern (tables/custom-gl4x-union.json, two draws) and d3d16x: line-case RMS on fresh cases
# (rsaa eval-table's mix RMS) and PSNR dB against 64x SSAA per scene with today's defaults and
# `auto`'s pre-pass, beside hardware 4x MSAA; the last columns: each table minus d3d8x, the mean
# over the scenes and the lowest. Writes OUT_DIR/cell-patterns.md and the renders.
# Usage: tools/cell_patterns.sh [--width W] [--height H] [--cases N] [--out-dir DIR] SCENE...
#   Default 640x480, 10^6 fresh cases for the line RMS, OUT_DIR out/cell-patterns. About 20
#   seconds a scene. The cell tables are checked first: trained again from the driver's 4x
#   pattern (rsaa train --pattern gl4x --cells CxR), each must be the checked-in file.
set -euo pipefail
cd "$(dirname "$0")/.."
width=640 height=480 out=out/cell-patterns cases=1000000
while [[ $# -gt 0 ]]; do
  case $1 in
    --width) width=${2:?--width needs a value}; shift 2 ;;
    --height) height=${2:?--height needs a value}; shift 2 ;;
    --out-dir) out=${2:?--out-dir needs a directory}; shift 2 ;;
    --cases) cases=${2:?--cases needs a count}; shift 2 ;;
    -h | --help) sed -n 2,12p "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "cell_patterns.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
    *) break ;;
  esac
done
script=cell_patterns.sh
# shellcheck source=tools/scene_images.sh
source tools/scene_images.sh
check_scenes_and_build "$@"
mkdir -p "$out/tables"

# The checked-in cell tables are the cells of this driver's 4x pattern, trained again here
# (rsaa train --cells; about a second each): a driver with other positions needs its own.
for shape in 2x1:wide 1x2:tall 2x2:quad; do
  $rsaa train --pattern gl4x --cells "${shape%:*}" --quiet --out-dir "$out/tables" >/dev/null ||
    { echo "$script: rsaa train --pattern gl4x --cells ${shape%:*} failed" >&2; exit 1; }
  cmp -s "$out/tables/custom-gl4x-${shape#*:}.json" "tables/custom-gl4x-${shape#*:}.json" ||
    { echo "$script: tables/custom-gl4x-${shape#*:}.json is not the ${shape%:*} cells of this driver's 4x pattern" \
        "(rsaa train --pattern gl4x --cells ${shape%:*})" >&2; exit 1; }
done

labels=(d3d8x custom-gl4x-union custom-gl4x-wide custom-gl4x-tall custom-gl4x-quad d3d16x)
declare -A table_file=([d3d8x]=tables/d3d8x.json [custom-gl4x-union]=tables/custom-gl4x-union.json
  [custom-gl4x-wide]=tables/custom-gl4x-wide.json [custom-gl4x-tall]=tables/custom-gl4x-tall.json
  [custom-gl4x-quad]=tables/custom-gl4x-quad.json [d3d16x]=tables/d3d16x.json)
declare -A subsamples=([d3d8x]=8 [custom-gl4x-union]=8 [custom-gl4x-wide]=8 [custom-gl4x-tall]=8
  [custom-gl4x-quad]=16 [d3d16x]=16)
declare -A rms psnrs
for label in "${labels[@]}"; do
  rms[$label]=$($rsaa eval-table "${table_file[$label]}" --cases "$cases" 2>/dev/null | awk '/mix cases/ {m = 1} m && $1 == "table" {print $2; exit}')
  [[ ${rms[$label]} =~ ^[0-9.]+$ ]] || { echo "$script: rsaa eval-table ${table_file[$label]} gave no RMS" >&2; exit 1; }
done

names=() msaa=()
for scene in "$@"; do
  name=$(basename "${scene#builtin:}"); name=${name%.*}
  dir=$out/$name
  mkdir -p "$dir"
  echo "$script: $scene" >&2
  render "$scene" "$dir/reference.png" --technique ssaa --samples 64
  render "$scene" "$dir/msaa4.png" --technique msaa --samples 4
  msaa+=("$(psnr "$dir/msaa4.png" "$dir/reference.png")")
  for label in "${labels[@]}"; do
    render "$scene" "$dir/$label.png" --technique rsaa --table "${table_file[$label]}"
    psnrs[$label]+="$(psnr "$dir/$label.png" "$dir/reference.png") "
  done
  names+=("$name")
done

{
  echo "${width}x$height, PSNR dB against 64x SSAA; RSAA with today's defaults, each table's pre-pass as \`auto\`"
  echo "takes it on this driver (d3d8x and d3d16x: jittered draws writing records; union: two 4x draws;"
  echo "wide, tall: one 4x draw at twice the width or height; quad: one at twice both; the one-draw and"
  echo "records pre-passes within auto's 256 MiB of records, 12 B a subsample: 16 subsamples up to about"
  echo "1.4 Mpx, 8 up to 2.8 Mpx; jittered draws beyond); line RMS: mix cases,"
  echo "\`rsaa eval-table\` on $cases fresh cases."
  echo
  printf '| table | subsamples | line RMS |'; printf ' %s |' "${names[@]}"; echo ' mean - d3d8x | lowest - d3d8x |'
  printf '| --- | --- | --- |'; printf ' --- |%.0s' "${names[@]}"; echo ' --- | --- |'
  printf '| msaa 4x (hardware) | 4 | - |'; printf ' %s |' "${msaa[@]}"; echo ' | |'
  read -ra base <<<"${psnrs[d3d8x]}"
  for label in "${labels[@]}"; do
    read -ra row <<<"${psnrs[$label]}"
    printf '| %s | %s | %s |' "$label" "${subsamples[$label]}" "${rms[$label]}"
    printf ' %s |' "${row[@]}"
    awk -v a="${row[*]}" -v b="${base[*]}" 'BEGIN {
      n = split(a, x, " "); split(b, y, " "); low = 1e9
      for (i = 1; i <= n; ++i) { d = x[i] - y[i]; s += d; if (d < low) low = d }
      printf " %+.2f | %+.2f |\n", s / n, low }'
  done
} >"$out/cell-patterns.md"
cat "$out/cell-patterns.md"
