#!/usr/bin/env bash
# dcel diff --jobs: throughput against an implementation that takes 20 ms a
# case and answers right (tests/data/impls/sleep_20ms_correct.py, streamed),
# with --jobs 1, 2 and the number of cores, and the ratio to --jobs 1.
#
#   bench/diff_jobs.sh [DCEL] [CASES]     defaults: build/bin/dcel, 400
#
# Prints one line per N: wall seconds, cases per second, and the speed-up.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
dcel=${1:-$here/build/bin/dcel}
cases=${2:-400}
impl="/usr/bin/python3 $here/tests/data/impls/sleep_20ms_correct.py"
cores=$(nproc)
base=""
for jobs in $(printf '%s\n' 1 2 "$cores" | sort -nu); do
  start=$(date +%s.%N)
  "$dcel" diff --impl "$impl" --stream --cases "$cases" --jobs "$jobs" > /dev/null 2>&1
  end=$(date +%s.%N)
  awk -v j="$jobs" -v s="$start" -v e="$end" -v n="$cases" -v b="$base" 'BEGIN {
    t = e - s; rate = n / t
    printf "--jobs %-3d %7.2f s  %7.1f cases/s", j, t, rate
    if (b != "") printf "  %.2fx of --jobs 1", rate / b
    printf "\n" }'
  [ -n "$base" ] || base=$(awk -v s="$start" -v e="$end" -v n="$cases" 'BEGIN { print n / (e - s) }')
done
