#!/usr/bin/env bash
# Side-by-side crops (nearest-neighbour, 4x) of images made by tools/compare_variants.sh:
# noaa | rsaa 8x SADP auth 0 | auth 1 | auth 2 | 64x SSAA.
# Usage: tools/crops.sh [COMPARE_DIR] [WxH+X+Y] [OUT.png]
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-out/compare/default}
region=${2:-100x75+250+40}
out=${3:-docs/images/default_crops.png}
size=${region%%+*}
w=${size%x*}
h=${size#*x}
mkdir -p "$(dirname "$out")"
args=()
for f in noaa rsaax8sadpauth0 rsaax8sadpauth1 rsaax8sadpauth2 reference; do
  args+=("$dir/$f.png" --cut "$region" --resample "$((w * 4))x$((h * 4))")
done
oiiotool "${args[@]}" --mosaic:pad=8 5x1 -o "$out"
echo "wrote $out (left to right: noaa, RSAA 8x SADP auth 0, auth 1, auth 2, 64x SSAA)"
