#!/usr/bin/env bash
# The reference side of a session against `dcel edit` on the same steps: one
# generated session cut down to what both run (accepted edits and locates;
# bench/session_vs_edit.cpp), each command timed as a whole (reading, the
# steps, writing its answer): CPU time, the least of five runs (on a shared
# machine wall time measures the neighbours).
#   bench/session_vs_edit.sh [BUILD_DIR] [FAMILY VERTICES STEPS SEED]
#   (default: build triangulation 10000 10000 1)
set -euo pipefail
build=${1:-build}
family=${2:-triangulation} vertices=${3:-10000} steps=${4:-10000} seed=${5:-1}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$build/bin/dcel_session_vs_edit" "$family" "$vertices" "$steps" "$seed" "$dir"
kept=$(/usr/bin/python3 -c 'import json,sys; print(len(json.load(open(sys.argv[1]))["steps"]))' "$dir/session.json")
best() {  # the least CPU time (user + system) of five runs, in seconds; fails when the command does
  local b=""
  for _ in 1 2 3 4 5; do
    /usr/bin/time -f "%U %S" -o "$dir/time" "$@" >"$dir/out" 2>"$dir/err" ||
      { echo "failed: $* ($(head -c 300 "$dir/err"))" >&2; exit 1; }
    b=$(awk -v b="$b" '{ t = $1 + $2; if (b == "" || t < b) print t; else print b }' "$dir/time")
  done
  echo "$b"
}
session=$(best "$build/bin/dcel" session "$dir/session.json")
edit=$(best "$build/bin/dcel" edit "$dir/graph.json" "$dir/script.json")
awk -v n="$kept" -v s="$session" -v e="$edit" 'BEGIN {
  if (s == 0 || e == 0) {  # /usr/bin/time counts in 10 ms steps
    printf "session / edit steps per second: not measured (a run under the timer'"'"'s 10 ms)\n"
    exit
  }
  printf "dcel session: %.2f s of CPU, %.0f steps/s\n", s, n / s
  printf "dcel edit:    %.2f s of CPU, %.0f steps/s\n", e, n / e
  printf "session / edit steps per second: %.2fx\n", e / s
}'
