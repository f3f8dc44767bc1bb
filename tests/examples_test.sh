#!/usr/bin/env bash
# The three ways an engine uses rsaa, each built and run as a user would:
#   package     the README's libraries-only build, installed into a temporary prefix, moved;
#               examples/ finds it with find_package; each installed header compiles alone
#   subproject  examples/ pulls the source tree in with add_subdirectory (tools and tests off:
#               the configure must not look for the tools' dependencies)
#   tables only example 03 uses an installed .glsl table and no rsaa library
# Each example must exit 0 and its image must match tests/data/examples/ (PSNR >= 45 dB) and
# differ from its own no-AA image (PSNR <= 45 dB: the edges were resampled).
# Usage: examples_test.sh BUILD_DIR WORK_DIR MODE   (MODE: package | subproject)
set -euo pipefail
build_dir=$1 work=$2 mode=$3
source_dir=$(cd "$(dirname "$0")/.." && pwd)
rsaa=$build_dir/rsaa
rm -rf "$work"
mkdir -p "$work/out"

configure=(-G Ninja -DCMAKE_BUILD_TYPE=Release)
command -v ccache >/dev/null && configure+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
if [ "$mode" = package ]; then
  # The README's commands: a libraries-only build, installed into a prefix, which is then moved
  # (the package config must be relocatable: the examples find it where it was moved to).
  cmake -S "$source_dir" -B "$work/build-lib" "${configure[@]}" -DRSAA_BUILD_TOOLS=OFF -DRSAA_BUILD_TESTS=OFF \
    >"$work/configure-lib.log"
  cmake --build "$work/build-lib" --parallel 2 >"$work/build-lib.log" || { tail -40 "$work/build-lib.log"; exit 1; }
  cmake --install "$work/build-lib" --prefix "$work/installed" >/dev/null
  mv "$work/installed" "$work/prefix"
  for file in include/rsaa/runtime/rsaa_pass.h share/rsaa/tables/d3d8x.glsl share/rsaa/shaders/rsaa_prepass.glsl \
              share/rsaa/LICENSE lib/cmake/rsaa/rsaaConfig.cmake lib/cmake/rsaa/rsaaConfigVersion.cmake; do
    test -f "$work/prefix/$file" || { echo "examples_test: the install has no $file" >&2; exit 1; }
  done
  # Every installed header compiles on its own (its includes all installed, none missing).
  (cd "$work/prefix/include/rsaa" && find . -name '*.h' | sed 's|^\./||' | sort) |
    xargs -P2 -I{} sh -c 'echo "#include \"{}\"" | "${CXX:-c++}" -std=c++17 -fsyntax-only -Wall -Wextra -Werror \
      -I"$1" -x c++ - || { echo "examples_test: the installed {} does not compile alone" >&2; exit 255; }' \
      sh "$work/prefix/include/rsaa"
  # The full build's install (with the rsaa command), moved too: the command loads its own image
  # module, not the build tree's.
  cmake --install "$build_dir" --prefix "$work/installed-tools" >/dev/null
  mv "$work/installed-tools" "$work/prefix-tools"
  golden=$source_dir/tests/data/examples/01_rsaa.png
  LD_DEBUG=libs "$work/prefix-tools/bin/rsaa" compare "$golden" "$golden" >/dev/null 2>"$work/rsaa-libs.log"
  grep -q "calling init: $work/prefix-tools/lib/rsaa/librsaa_oiio" "$work/rsaa-libs.log" || {
    grep 'calling init: .*rsaa_oiio' "$work/rsaa-libs.log" >&2
    echo "examples_test: the installed rsaa did not load the image module of its own prefix" >&2
    exit 1
  }
  configure+=(-DCMAKE_PREFIX_PATH="$work/prefix")
  # A component the package does not have is an error at find_package (the examples ask for pass).
  mkdir -p "$work/no-such-component"
  printf 'cmake_minimum_required(VERSION 3.16)\nproject(c LANGUAGES CXX)\nfind_package(rsaa REQUIRED COMPONENTS nosuch)\n' \
    >"$work/no-such-component/CMakeLists.txt"
  if cmake -S "$work/no-such-component" -B "$work/no-such-component/build" -DCMAKE_PREFIX_PATH="$work/prefix" \
    >"$work/no-such-component.log" 2>&1; then
    echo "examples_test: find_package(rsaa COMPONENTS nosuch) succeeded" >&2; exit 1
  fi
else
  configure+=(-DRSAA_SOURCE_DIR="$source_dir")
fi
cmake -S "$source_dir/examples" -B "$work/build" "${configure[@]}" >"$work/configure.log"
if [ "$mode" = subproject ] &&
   grep -E '^(Ceres|OpenCV|OpenImageIO|assimp|glfw3|CLI11|GTest)_DIR:' "$work/build/CMakeCache.txt"; then
  echo "examples_test: the subproject configure looked for a tools-only dependency (above)" >&2
  exit 1
fi
cmake --build "$work/build" --parallel 2 >"$work/build.log" || { tail -40 "$work/build.log"; exit 1; }
# rsaa::pass brings GL, EGL, epoxy and the C++ runtime, none of the tools' libraries.
if grep -iE '^ *LINK_LIBRARIES = .*(opencv|ceres|openimageio|assimp|glfw|glog|gflags)' "$work/build/build.ninja"; then
  echo "examples_test: an example links a tools-only library (above)" >&2
  exit 1
fi

psnr() { "$rsaa" compare "$1" "$2" --json | sed -n 's/.*"psnr_db": "\{0,1\}\([^",]*\)"\{0,1\},*$/\1/p'; }
for example in 01_drop_in_rsaa 02_own_vertex_stage 03_tables_only; do
  n=${example%%_*}
  "$work/build/$example" "$work/out"
  to_golden=$(psnr "$work/out/${n}_rsaa.ppm" "$source_dir/tests/data/examples/${n}_rsaa.png")
  to_noaa=$(psnr "$work/out/${n}_rsaa.ppm" "$work/out/${n}_noaa.ppm")
  echo "$example: PSNR $to_golden dB against tests/data/examples/${n}_rsaa.png, $to_noaa dB against its no-AA image"
  awk -v g="$to_golden" -v a="$to_noaa" 'BEGIN { exit !((g == "inf" || g >= 45) && a != "inf" && a <= 45) }' || {
    echo "examples_test: $example is out of bounds" >&2
    exit 1
  }
done
