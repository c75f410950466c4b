#!/usr/bin/env python3
"""Runs `dcel diff` on the same cases in several ways and checks that the
reports are the same: the same distinct failures, counterexamples, counts
and order. Left out is only what depends on the clock or on how the run was
made: times, the command line and the stream restarts. Shrinking's attempt
counts are compared: shrinking is deterministic when it ends by itself,
which the caller's program and cases must ensure (a time budget spent would
make them differ).

    same_report.py DCEL WAY... -- DIFF-ARGS...

Each WAY is a few extra arguments in one word, split at spaces, such as
"--jobs 1" or "--jobs 2"; or "shards N": N runs with --shard 1/N .. N/N,
joined by `dcel diff-merge` (whose report also says "shards": N, left out).
Prints one line per way and "same" when all agree; otherwise the first
field that differs, and exits 1.
"""
import json
import os
import subprocess
import sys
import tempfile

VARYING = {"elapsed_ms", "reference_cpu_ms", "found_after_ms", "command", "restarts"}


def normalized(value):
    if isinstance(value, dict):
        return {k: normalized(v) for k, v in value.items() if k not in VARYING}
    if isinstance(value, list):
        return [normalized(v) for v in value]
    return value


def first_difference(a, b, path="report"):
    if type(a) is not type(b):
        return f"{path}: {json.dumps(a)[:200]} vs {json.dumps(b)[:200]}"
    if isinstance(a, dict):
        for k in sorted(set(a) | set(b)):
            if k not in a or k not in b:
                return f"{path}.{k}: present in only one"
            d = first_difference(a[k], b[k], f"{path}.{k}")
            if d:
                return d
        return None
    if isinstance(a, list):
        if len(a) != len(b):
            return f"{path}: {len(a)} entries vs {len(b)}"
        for i, (x, y) in enumerate(zip(a, b)):
            d = first_difference(x, y, f"{path}[{i}]")
            if d:
                return d
        return None
    return None if a == b else f"{path}: {json.dumps(a)[:200]} vs {json.dumps(b)[:200]}"


def main():
    dcel, rest = sys.argv[1], sys.argv[2:]
    split = rest.index("--")
    ways, args = rest[:split], rest[split + 1:]
    reports = []
    with tempfile.TemporaryDirectory() as tmp:
        for n, way in enumerate(ways):
            path = os.path.join(tmp, f"report-{n}.json")
            if way.startswith("shards "):
                count = int(way.split()[1])
                parts = [os.path.join(tmp, f"report-{n}-{k}.json") for k in range(1, count + 1)]
                for k, part in enumerate(parts, 1):
                    subprocess.run([dcel, "diff", *args, "--shard", f"{k}/{count}", "--report", part],
                                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
                run = subprocess.run([dcel, "diff-merge", *parts, "--report", path],
                                     stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
                if run.returncode == 2:
                    print(f"{way}: dcel diff-merge failed: {run.stderr.strip()}")
                    return 1
            else:
                run = subprocess.run([dcel, "diff", *args, *way.split(), "--report", path],
                                     stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
            with open(path, encoding="utf-8") as f:
                report = json.load(f)
            report.pop("shards", None)
            summary = run.stdout.splitlines()[0] if run.stdout else ""
            print(f"{way}: exit {run.returncode}, {len(report['failures'])} failures; {summary}")
            reports.append((way, run.returncode, normalized(report)))
    first_way, first_code, first = reports[0]
    for way, code, report in reports[1:]:
        d = first_difference(first, report) or (None if code == first_code else f"exit {first_code} vs {code}")
        if d:
            print(f"differs between {first_way!r} and {way!r}: {d}")
            return 1
    print("same")
    return 0


if __name__ == "__main__":
    sys.exit(main())
