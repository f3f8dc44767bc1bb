#!/usr/bin/env bash
# AddressSanitizer + UndefinedBehaviorSanitizer build of core/, trainer/ and their tests (and the
# short table-reader fuzz run), in build-asan/. Any report fails the run.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRSAA_SANITIZE=ON \
  -DRSAA_WITH_RUNTIME=OFF
cmake --build build-asan --parallel "$(nproc)"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:halt_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir build-asan --output-on-failure --parallel "$(nproc)"
