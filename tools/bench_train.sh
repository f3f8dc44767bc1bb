#!/usr/bin/env bash
# Benchmark (not a test): wall time, CPU time and peak memory of training a table on this machine.
# Usage: tools/bench_train.sh [PATTERN] [CASES] [RUNS]   (default d3d8x 1000000 3)
# Targets: d3d8x 10^6 under 30 s; d3d16x 10^8 under 5 min and 1 GiB (issue 12). CPU time and the
# load average are printed because wall time on a shared machine says little on its own.
set -euo pipefail
cd "$(dirname "$0")/.."
pattern=${1:-d3d8x}
cases=${2:-1000000}
runs=${3:-3}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "rsaa train --pattern $pattern --cases $cases: $runs runs on $(nproc) cores" \
  "(load average before: $(cut -d' ' -f1-3 /proc/loadavg))"
for i in $(seq "$runs"); do
  /usr/bin/time -f "%e %U %S %M" -o "$out/time" ./build/rsaa train --pattern "$pattern" \
    --cases "$cases" --quiet --out-dir "$out" >"$out/log"
  read -r seconds user system kib <"$out/time"
  printf "  run %d: %7.2f s wall, %7.2f s CPU, peak memory %4d MiB, %s\n" "$i" "$seconds" \
    "$(awk -v u="$user" -v s="$system" 'BEGIN {print u + s}')" $((kib / 1024)) "$(awk '/masks reached/ {print $2}' "$out/log") masks reached"
  echo "$seconds" >>"$out/all"
done
median=$(sort -n "$out/all" | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
echo "median wall time: $median s"
