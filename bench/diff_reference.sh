#!/usr/bin/env bash
# What the reference side of `dcel diff` costs (generating, writing, building
# and judging each case: the report's reference_cpu_ms, dcel's own CPU time),
# in cases per second, on the default small cases and on cases of 10^4
# vertices, beside the whole run's rate with the exact Python example as the
# implementation. The ratio says how much of a run is the implementation's.
#
#   bench/diff_reference.sh [DCEL] [SMALL_CASES] [LARGE_CASES]   defaults: build/bin/dcel, 400, 10
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
dcel=${1:-$here/build/bin/dcel}
small=${2:-400}
large=${3:-10}
impl="/usr/bin/python3 $here/examples/python/dcel_faces.py"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$dcel" diff --impl "$impl" --stream --cases "$small" --large-vertices 0 --report "$tmp/small.json" > /dev/null 2>&1
# Every 50th case is a large one: cases 49, 99, ... with --large-vertices 10000.
for k in $(seq 1 "$large"); do
  "$dcel" diff --impl "$impl" --stream --case $((50 * k - 1)) --large-vertices 10000 --report "$tmp/large-$k.json" > /dev/null 2>&1
done

/usr/bin/python3 - "$tmp" "$large" <<'PY'
import glob, json, sys
tmp, large = sys.argv[1], int(sys.argv[2])
def row(name, reports):
    cases = sum(r["cases_run"] for r in reports)
    cpu = sum(r["reference_cpu_ms"] for r in reports) / 1000
    wall = sum(r["elapsed_ms"] for r in reports) / 1000
    print(f"{name:32} {cases:5d} cases  reference side {cases / max(cpu, 1e-3):9.1f} cases/s ({cpu:6.2f} s CPU)"
          f"  whole run {cases / max(wall, 1e-3):7.1f} cases/s  reference share {cpu / max(wall, 1e-3):5.1%}")
row("small (2 to 60 vertices)", [json.load(open(f"{tmp}/small.json"))])
row("large (10^4 vertices)", [json.load(open(p)) for p in sorted(glob.glob(f"{tmp}/large-*.json"))])
PY
