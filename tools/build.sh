#!/usr/bin/env bash
# Installs the dependencies (tools/setup.sh) and builds everything into build/ (Release).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build --parallel "$(nproc)"
