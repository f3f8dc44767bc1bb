#!/usr/bin/env bash
# Which shift makes the best union pattern (8 subsamples as two draws of the driver's 4x pattern,
# the second shifted and wrapped into the pixel)? For each candidate shift: train the union table
# (1e6 cases), its line-case RMS on fresh cases (rsaa eval-table), and RSAA's PSNR against 64x
# SSAA on each scene with that table and the two-draw pre-pass, beside d3d8x's 8 jittered draws.
# Line-case RMS and images need not rank the shifts alike; tables/custom-gl4x-union.json is the shift
# the images prefer. Writes OUT_DIR/union-shifts.md (a Markdown table) and the renders.
# Usage: tools/union_shifts.sh [--width W] [--height H] [--shifts "dx,dy ..."] [--scene S]... [OUT_DIR]
#   Default: 640x480, shifts "0.5,0.5 -0.125,-0.125 0.125,0.125 0.5,0 -0.25,0", eight scenes
#   (two built-in, six assimp test models; --scene, repeated, names others), OUT_DIR
#   out/union-shifts (relative paths from where it is run). Pixel units, +y down
#   (docs/conventions.md). About 3 minutes.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
width=640
height=480
chosen_scenes=()
shifts="0.5,0.5 -0.125,-0.125 0.125,0.125 0.5,0 -0.25,0"
while [[ $# -gt 0 ]]; do
  case $1 in
    --width) width=${2:?--width needs a value}; shift 2 ;;
    --height) height=${2:?--height needs a value}; shift 2 ;;
    --shifts) shifts=${2:?--shifts needs a list}; shift 2 ;;
    --scene) chosen_scenes+=("${2:?--scene needs a scene}"); shift 2 ;;
    -h | --help) sed -n 2,12p "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "union_shifts.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
    *) break ;;
  esac
done
[[ $# -le 1 ]] || { echo "union_shifts.sh: one output directory, then nothing (options go before it): $*" >&2; exit 2; }
out=$(realpath -m "${1:-out/union-shifts}")
[[ -n ${shifts// /} ]] || { echo "union_shifts.sh: --shifts: no shift" >&2; exit 2; }
for shift in $shifts; do
  [[ $shift =~ ^-?[0-9]*\.?[0-9]+,-?[0-9]*\.?[0-9]+$ ]] ||
    { echo "union_shifts.sh: --shifts: '$shift' is not dx,dy (pixels, e.g. -0.125,-0.125)" >&2; exit 2; }
done
models=/usr/share/assimp/models
scenes=(builtin:default builtin:grazing "$models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"
        "$models/glTF/CesiumMilkTruck/CesiumMilkTruck.gltf" "$models/OBJ/spider.obj"
        "$models/Q3D/E-AT-AT.q3o" "$models/3DS/fels.3ds" "$models/COB/dwarf.cob")
if [[ ${#chosen_scenes[@]} -gt 0 ]]; then
  scenes=()
  for scene in "${chosen_scenes[@]}"; do
    [[ $scene == builtin:* ]] && scenes+=("$scene") || scenes+=("$(realpath -m "$scene")")
  done
fi
scene_name() { local n; n=$(basename "${1#builtin:}"); echo "${n%.*}"; }
declare -A seen
for scene in "${scenes[@]}"; do  # a scene's renders and column are named after it
  name=$(scene_name "$scene")
  [[ -z ${seen[$name]:-} ]] || { echo "union_shifts.sh: $scene and ${seen[$name]} share the name $name" >&2; exit 2; }
  seen[$name]=$scene
done
cd "$repo"
rsaa=./build/rsaa
[[ -x $rsaa ]] || bash tools/build.sh
mkdir -p "$out/tables" "$out/images"
# A number or an error naming what failed (an empty cell would read as a measurement).
number_or_fail() { [[ $1 =~ ^-?[0-9.]+$ ]] || { echo "union_shifts.sh: $2 gave no number" >&2; exit 1; }; echo "$1"; }
psnr() {
  number_or_fail "$($rsaa compare --json "$1" "$2" | awk -F'[:,]' '/"psnr_db"/ {printf "%.2f", $2}')" "compare $1 $2"
}
mix_rms() {
  number_or_fail "$($rsaa eval-table "$1" | awk '/mix cases/ {m = 1} m && $1 == "table" {print $2; exit}')" "eval-table $1"
}

# The driver's 4x positions, as the checked-in gl4x table records them (pixel units, +y down).
driver=$(sed -n 's/.*"samples": *\[\(.*\)\],*$/\1/p' tables/gl4x.json | tr -d '[] ' | tr ',' ' ')
[[ $(wc -w <<<"$driver") == 8 ]] || { echo "union_shifts.sh: tables/gl4x.json: no 4 sample positions" >&2; exit 1; }
# Positions of the union pattern for shift (dx, dy): the driver's, then the same shifted and
# wrapped into [-0.5, 0.5) as the pre-pass wraps them.
union_positions() {
  awk -v d="$driver" -v s="$1" 'function floor(v,  f) { f = int(v); return f > v ? f - 1 : f }
  BEGIN {
    n = split(d, p, " "); split(s, t, ",")
    for (i = 1; i <= n; i += 2) printf "%s%g,%g", (i > 1 ? " " : ""), p[i], p[i + 1]
    for (i = 1; i <= n; i += 2) {
      x = p[i] + t[1]; y = p[i + 1] + t[2]
      x -= floor(x + 0.5); y -= floor(y + 0.5)
      printf " %g,%g", x, y
    }
  }'
}

echo "references (64x SSAA) and d3d8x, ${width}x$height" >&2
declare -A reference d3d8x
for scene in "${scenes[@]}"; do
  name=$(scene_name "$scene")
  [[ $scene == builtin:* || -f $scene ]] || { echo "  $name: not installed, left out" >&2; continue; }
  $rsaa render --scene "$scene" --technique ssaa --samples 64 --width "$width" --height "$height" \
    --out "$out/images/$name-ssaa64.png" >/dev/null
  $rsaa render --scene "$scene" --technique rsaa --samples 8 --prepass jittered --width "$width" \
    --height "$height" --out "$out/images/$name-d3d8x.png" >/dev/null
  reference[$name]=$out/images/$name-ssaa64.png
  d3d8x[$name]=$(psnr "$out/images/$name-d3d8x.png" "${reference[$name]}")
done
names=()
for scene in "${scenes[@]}"; do
  name=$(scene_name "$scene"); [[ -n ${reference[$name]:-} ]] && names+=("$name")
done
[[ ${#names[@]} -gt 0 ]] || { echo "union_shifts.sh: none of the scenes is installed" >&2; exit 1; }

{
  echo "Union patterns: the driver's 4x positions plus the same shifted by (dx, dy) px (+y down),"
  echo "wrapped into the pixel; 1e6 training cases; line RMS = eval-table's mix RMS on fresh cases;"
  echo "PSNR dB against 64x SSAA at ${width}x$height with the two-draw pre-pass (--prepass msaa) and"
  echo "today's defaults; the last columns: the mean of union minus d3d8x over every scene, and over"
  echo "the model files only (the built-in scenes are synthetic)."
  echo
  printf '| shift | line RMS |'; printf ' %s |' "${names[@]}"; echo ' mean vs d3d8x | models only |'
  printf '| --- | --- |'; printf ' --- |%.0s' "${names[@]}"; echo ' --- | --- |'
  rms=$(mix_rms tables/d3d8x.json)
  printf '| d3d8x (8 jittered draws) | %s |' "$rms"
  for name in "${names[@]}"; do printf ' %s |' "${d3d8x[$name]}"; done
  echo ' 0 | 0 |'
  for shift in $shifts; do
    echo "shift $shift" >&2
    tag=$(tr ".,-" "p_m" <<<"shift$shift")
    # A shift that puts a shifted sample on a driver sample makes no 8-sample pattern: a row saying so.
    if ! error=$($rsaa train --pattern "custom-$tag" --positions "$(union_positions "$shift")" --cases 1000000 \
                   --out-dir "$out/tables" --quiet 2>&1 >/dev/null); then
      [[ $error == *coincident* ]] || { echo "union_shifts.sh: shift $shift: $error" >&2; exit 1; }
      echo "| $shift | not a pattern: $(head -n 1 <<<"${error#*: error: }") |"
      continue
    fi
    table=$out/tables/custom-$tag.json
    rms=$(mix_rms "$table")
    printf '| %s | %s |' "$shift" "$rms"
    deltas=""  # "builtin|model difference" per scene
    for scene in "${scenes[@]}"; do
      name=$(scene_name "$scene"); [[ -n ${reference[$name]:-} ]] || continue
      $rsaa render --scene "$scene" --technique rsaa --table "$table" --prepass msaa --width "$width" \
        --height "$height" --out "$out/images/$name-$tag.png" >/dev/null
      p=$(psnr "$out/images/$name-$tag.png" "${reference[$name]}")
      printf ' %s |' "$p"
      kind=model; [[ $scene == builtin:* ]] && kind=builtin
      deltas+="$kind $(awk -v p="$p" -v d="${d3d8x[$name]}" 'BEGIN {print p - d}')"$'\n'
    done
    awk '{ all += $2; n++ } $1 == "model" { models += $2; m++ }
         END { printf " %+.2f | %s |\n", all / n, m ? sprintf("%+.2f", models / m) : "-" }' <<<"${deltas%$'\n'}"
  done
} >"$out/union-shifts.md.partial"
# The table whole or not at all (a failure above leaves the last complete one).
mv "$out/union-shifts.md.partial" "$out/union-shifts.md"
cat "$out/union-shifts.md"
