#!/usr/bin/env bash
# Measures the fit rules against each other: trains d3d8x (or $1) with the paper's ockham rule
# and with mixed fits of several two-line weights on the same 10^6 cases, then evaluates all
# tables on the same 10^6 fresh cases (seed 2). Usage: tools/fit_trade.sh [PATTERN] [CASES]
set -euo pipefail
cd "$(dirname "$0")/.."
pattern=${1:-d3d8x}
cases=${2:-1000000}
out=out/fit-trade/$pattern
rm -rf "$out"
tables=()
train() {
  local name=$1; shift
  mkdir -p "$out/$name"
  ./build/rsaa train --pattern "$pattern" --cases "$cases" --quiet --out-dir "$out/$name" "$@" >/dev/null
  tables+=("$out/$name/$pattern.json")
}
train ockham --fit ockham
for w in 0.1 0.25 0.5 0.75; do train "mixed-w$w" --fit mixed --two-line-weight "$w"; done
./build/rsaa eval-table --cases "$cases" --seed 2 "${tables[@]}"
