#!/usr/bin/env bash
# Set-up, build, the whole test suite, then the sanitizer build of core/trainer and its tests
# (the README's test command; CI runs exactly this).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
ctest --test-dir build --output-on-failure --parallel "$(nproc)"
# core/ and trainer/ again under AddressSanitizer + UndefinedBehaviorSanitizer.
bash tools/sanitize.sh
