# Sourced by the goal scripts (tools/coverage_goals.sh, tools/rsaa_goals.sh): one image rendered
# and compared at a time, each failure naming its command. Expects `script` (the caller's name),
# `width` and `height`; check_scenes_and_build "$@" first.
rsaa=./build/rsaa

check_scenes_and_build() {
  [[ $# -gt 0 ]] || { echo "$script: name at least one scene (builtin:NAME or a model file)" >&2; exit 2; }
  [[ -x $rsaa ]] || { echo "$script: $rsaa is missing: run tools/build.sh first" >&2; exit 2; }
}

# render SCENE OUT [technique options...]: one image.
render() {
  local scene=$1 file=$2; shift 2
  $rsaa render --scene "$scene" --width "$width" --height "$height" "$@" --out "$file" >/dev/null ||
    { echo "$script: rsaa render --scene $scene $* failed (exit $?)" >&2; exit 1; }
}

# psnr IMAGE REFERENCE: the PSNR in dB.
psnr() {
  local text
  text=$($rsaa compare "$1" "$2") || { echo "$script: rsaa compare $1 $2 failed" >&2; exit 1; }
  # "PSNR identical images": no error to take a logarithm of; 99.99, the figure the tables use.
  awk 'NR == 2 {print ($2 == "identical" ? "99.99" : $2)}' <<<"$text"
}
