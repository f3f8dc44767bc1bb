#!/usr/bin/env bash
# Side-by-side crops (nearest-neighbour, 4x) of images made by tools/compare_variants.sh:
# noaa | rsaa 8x SADP auth 0 | auth 1 | auth 2 | 64x SSAA; or of the images NAME.png of DIR named.
# Usage: tools/crops.sh [COMPARE_DIR] [WxH+X+Y] [OUT.png] [NAME...]
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-out/compare/default}
region=${2:-100x75+250+40}
out=${3:-docs/images/default_crops.png}
names=(noaa rsaax8sadpauth0 rsaax8sadpauth1 rsaax8sadpauth2 reference)
[[ $# -gt 3 ]] && names=("${@:4}")
size=${region%%+*}
w=${size%x*}
h=${size#*x}
mkdir -p "$(dirname "$out")"
args=()
for f in "${names[@]}"; do
  args+=("$dir/$f.png" --cut "$region" --resample "$((w * 4))x$((h * 4))")
done
oiiotool "${args[@]}" --mosaic:pad=8 "${#names[@]}x1" -o "$out"
echo "wrote $out (left to right: ${names[*]})"
