#!/usr/bin/env bash
# Set-up, build, and the main job on the built-in default: train the D3D 8x offset table on
# 10^6 line cases, show that it reproduces the checked-in table byte for byte, and measure it
# on 10^6 fresh cases.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
mkdir -p out/tables
./build/rsaa train --pattern d3d8x --out-dir out/tables
for ext in json glsl hlsl; do
  if cmp -s "out/tables/d3d8x.$ext" "tables/d3d8x.$ext"; then
    echo "out/tables/d3d8x.$ext is byte-identical to the checked-in tables/d3d8x.$ext"
  else
    echo "out/tables/d3d8x.$ext differs from tables/d3d8x.$ext" >&2
    exit 1
  fi
done
./build/rsaa eval-table out/tables/d3d8x.json
