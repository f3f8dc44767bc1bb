#!/usr/bin/env bash
# Benchmark (not a test): wall time and peak memory of training a table on this machine.
# Usage: tools/bench_train.sh [PATTERN] [CASES] [RUNS]   (default d3d8x 1000000 3)
set -euo pipefail
cd "$(dirname "$0")/.."
pattern=${1:-d3d8x}
cases=${2:-1000000}
runs=${3:-3}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "rsaa train --pattern $pattern --cases $cases: $runs runs on $(nproc) cores"
for i in $(seq "$runs"); do
  /usr/bin/time -f "%e %M" -o "$out/time" ./build/rsaa train --pattern "$pattern" --cases "$cases" \
    --quiet --out-dir "$out" >/dev/null
  read -r seconds kib <"$out/time"
  printf "  run %d: %6.2f s wall, peak memory %4d MiB\n" "$i" "$seconds" $((kib / 1024))
  echo "$seconds" >>"$out/all"
done
median=$(sort -n "$out/all" | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
echo "median wall time: $median s (target: under 30 s)"
