#!/usr/bin/env bash
# Installs every Debian package rsaa needs. Idempotent: safe to run again.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git time
  libceres-dev libeigen3-dev            # trainer: the per-mask least-squares fits
  nlohmann-json3-dev                    # table files (JSON)
  libcli11-dev                          # the rsaa command line
  libgtest-dev libgmock-dev libbenchmark-dev
  glslang-tools                         # compile-check generated GLSL/HLSL tables and shaders
  spirv-cross                           # tests: the HLSL post-process translated to GLSL and run
  libopencv-dev libopencv-contrib-dev   # image metrics (PSNR, SSIM in quality), plots
  libglm-dev libopenimageio-dev openimageio-tools
  libglfw3-dev libepoxy-dev libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri
  libopengl-dev                         # examples/: GL through libOpenGL, not epoxy
  libassimp-dev assimp-testmodels
  libcsv-dev                            # rsaa plot: CSV with quoted fields
  zlib1g-dev                            # rsaa_reliability: a compressed hostile model
  xvfb xauth
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages already installed"
  exit 0
fi

SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
echo "setup: installing ${#missing[@]} packages: ${missing[*]}"
$SUDO apt-get update -q
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
echo "setup: done"
