#!/usr/bin/env bash
# RSAA's image-quality goals (issue 11) on any scenes, held-out models included, and what one set
# of options changes: against 64x SSAA, RSAA 4x and 8x with the defaults beside no AA, the
# FXAA-style pass and hardware 4x MSAA, each RSAA column "without -> defaults" where WITHOUT are
# options turning one default off (for example "--material-edges off"), or "defaults -> with"
# where WITH are options beyond the defaults (for example "--split-cap 3"). Prints a Markdown
# table (8x below 4x MSAA marked "!") and the summary lines: mean gain over no AA, 8x over 4x,
# against FXAA, the lowest change (with --with: the same for the options' column, and the
# highest change). Keeps the images in OUT_DIR/<scene>/.
# Usage: tools/rsaa_goals.sh [--width W] [--height H] [--out-dir DIR] [--without|--with "OPTIONS"] SCENE...
set -euo pipefail
cd "$(dirname "$0")/.."
width=640 height=480 out=out/rsaa-goals without="" with=""
while [[ $# -gt 0 ]]; do
  case $1 in
    --width) width=${2:?}; shift 2 ;;
    --height) height=${2:?}; shift 2 ;;
    --out-dir) out=${2:?}; shift 2 ;;
    --without) without=${2:?}; shift 2 ;;
    --with) with=${2:?}; shift 2 ;;
    -h | --help) sed -n 2,8p "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "rsaa_goals.sh: unknown option $1" >&2; exit 2 ;;
    *) break ;;
  esac
done
if [[ -n $without && -n $with ]]; then echo "rsaa_goals.sh: give --without or --with, not both" >&2; exit 2; fi
variant=${without:-$with}
script=rsaa_goals.sh
# shellcheck source=tools/scene_images.sh
source tools/scene_images.sh
check_scenes_and_build "$@"

rows=() summary=()
declare -A used=()
for scene in "$@"; do
  name=$(basename "${scene#builtin:}"); name=${name%.*}
  # Files of one base name (spider.fbx, spider.mdc) keep their rows and images apart; a name is
  # one word (the summary's fields are split on blanks).
  [[ -z ${used[$name]:-} ]] || name=$(basename "$scene")
  [[ -z ${used[$name]:-} ]] || name=$(basename "$(dirname "$scene")")_$(basename "$scene")
  name=${name//[[:space:]]/_}
  base=$name
  for ((k = 2; ${used[$name]:-0} == 1; ++k)); do name=${base}_$k; done
  used[$name]=1
  dir=$out/$name
  mkdir -p "$dir"
  echo "rsaa_goals: $scene" >&2
  render "$scene" "$dir/reference.png" --technique ssaa --samples 64
  declare -A p=()
  for t in noaa fxaa "msaa --samples 4" "rsaa --samples 4" "rsaa --samples 8"; do
    file=$dir/$(tr -d ' -' <<<"$t").png
    # shellcheck disable=SC2086
    render "$scene" "$file" --technique $t
    p[$t]=$(psnr "$file" "$dir/reference.png")
    if [[ $t == rsaa* && -n $variant ]]; then
      suffix=${without:+without}${with:+with}
      # shellcheck disable=SC2086
      render "$scene" "${file%.png}-$suffix.png" --technique $t $variant
      p[$t variant]=$(psnr "${file%.png}-$suffix.png" "$dir/reference.png")
    fi
  done
  n=${p[noaa]} f=${p[fxaa]} m=${p[msaa --samples 4]} r4=${p[rsaa --samples 4]} r8=${p[rsaa --samples 8]}
  cell() {
    if [[ -n $without ]]; then echo "${p[$1 variant]} -> ${p[$1]}"
    elif [[ -n $with ]]; then echo "${p[$1]} -> ${p[$1 variant]}"
    else echo "${p[$1]}"; fi
  }
  delta=$(awk -v a="$r8" -v b="$m" 'BEGIN {printf "%+.2f%s", a - b, (a < b ? " !" : "")}')
  rows+=("| $name | $n | $f | $m | $(cell "rsaa --samples 4") | $(cell "rsaa --samples 8") | $delta |")
  echo "  ${rows[-1]}" >&2
  summary+=("$name $n $f $m $r4 $r8 ${p[rsaa --samples 4 variant]:-$r4} ${p[rsaa --samples 8 variant]:-$r8}")
  unset p
done

echo "${width}x${height}, PSNR dB against 64x SSAA; RSAA with the defaults${without:+ (without -> with: \`$without\` -> defaults)}${with:+ (defaults -> with \`$with\`)}; ! = RSAA 8x below 4x MSAA:"
echo
echo "| scene | noaa | fxaa | msaa 4x | RSAA 4x | RSAA 8x | 8x - msaa 4x |"
echo "| --- | --- | --- | --- | --- | --- | --- |"
printf '%s\n' "${rows[@]}"
echo
printf '%s\n' "${summary[@]}" | awk -v without="$without" -v with="$with" '
  { count++; gain += $6 - $2; step += $6 - $5; fxaa += $3; rsaa += $6;
    if ($6 < $4) below = below " " $1;
    change8 = $6 - $8; change4 = $5 - $7;
    if (with != "") { change8 = -change8; change4 = -change4; gain_with += $8 - $2; step_with += $8 - $7;
                      rsaa_with += $8; if ($8 < $4) below_with = below_with " " $1 }
    if (count == 1 || change8 < low8) { low8 = change8; low8_at = $1 }
    if (count == 1 || change8 > high8) { high8 = change8; high8_at = $1 }
    if (count == 1 || change4 < low4) { low4 = change4; low4_at = $1 } }
  END {
    printf "- mean gain of RSAA 8x over no AA: %+.2f dB; 8x over 4x: %+.2f dB; mean PSNR RSAA 8x %.2f, FXAA %.2f (%d scenes)\n",
           gain / count, step / count, rsaa / count, fxaa / count, count;
    printf "- RSAA 8x below 4x MSAA on:%s\n", below == "" ? " none" : below;
    if (without != "")
      printf "- lowest change from `%s` to the defaults: 8x %+.2f dB (%s), 4x %+.2f dB (%s)\n",
             without, low8, low8_at, low4, low4_at;
    if (with != "") {
      printf "- with `%s`: mean gain of RSAA 8x over no AA %+.2f dB; 8x over 4x %+.2f dB; mean PSNR RSAA 8x %.2f\n",
             with, gain_with / count, step_with / count, rsaa_with / count;
      printf "- with `%s`, RSAA 8x below 4x MSAA on:%s\n", with, below_with == "" ? " none" : below_with;
      printf "- change from the defaults to `%s`: 8x lowest %+.2f dB (%s), highest %+.2f dB (%s); 4x lowest %+.2f dB (%s)\n",
             with, low8, low8_at, high8, high8_at, low4, low4_at;
    }
  }'
