#!/usr/bin/env python3
"""The per-file coverage table of src/ and the floor check, for scripts/coverage.

    coverage-report.py SUMMARY_JSON FLOOR_FILE PREFIX [--update-floor]

SUMMARY_JSON is `llvm-cov export -summary-only` output; PREFIX is stripped from
file names. FLOOR_FILE holds lines such as `lines 97.5` and `branches 88.0`
(percentages; `#` starts a comment). Prints one row per file, lowest line
coverage first, then the totals; exits 1 when a total is below its floor.
With --update-floor it rewrites the numbers in FLOOR_FILE with the totals,
rounded down to 0.1, keeping the comments.
"""
import json
import math
import re
import sys


def pct(covered, count):
    return 100.0 * covered / count if count else 100.0


def main(argv):
    if len(argv) < 4:
        print(__doc__, file=sys.stderr)
        return 2
    summary_path, floor_path, prefix = argv[1:4]
    update = "--update-floor" in argv[4:]
    data = json.load(open(summary_path))["data"][0]
    rows = []
    for f in data["files"]:
        name = f["filename"]
        if name.startswith(prefix):
            name = name[len(prefix):]
        s = f["summary"]
        rows.append((name, s["lines"]["count"], s["lines"]["covered"], s["branches"]["count"], s["branches"]["covered"]))
    rows.sort(key=lambda r: (pct(r[2], r[1]), pct(r[4], r[3]), r[0]))

    width = max([len(r[0]) for r in rows] + [5])
    head = f"{'file':<{width}} {'lines':>6} {'missed':>6} {'line%':>7} {'branches':>8} {'missed':>6} {'branch%':>7}"
    print(head)
    print("-" * len(head))
    for name, lc, lcov, bc, bcov in rows:
        print(f"{name:<{width}} {lc:>6} {lc - lcov:>6} {pct(lcov, lc):>6.2f}% {bc:>8} {bc - bcov:>6} {pct(bcov, bc):>6.2f}%")
    t = data["totals"]
    lines = pct(t["lines"]["covered"], t["lines"]["count"])
    branches = pct(t["branches"]["covered"], t["branches"]["count"])
    print("-" * len(head))
    print(f"{'TOTAL (' + str(len(rows)) + ' files)':<{width}} {t['lines']['count']:>6} "
          f"{t['lines']['count'] - t['lines']['covered']:>6} {lines:>6.2f}% {t['branches']['count']:>8} "
          f"{t['branches']['count'] - t['branches']['covered']:>6} {branches:>6.2f}%")

    measured = {"lines": lines, "branches": branches}
    text = open(floor_path).read()
    floor = {k: float(v) for k, v in re.findall(r"^(lines|branches)\s+([0-9.]+)\s*$", text, re.M)}
    if set(floor) != {"lines", "branches"}:
        print(f"coverage: {floor_path} must give 'lines N' and 'branches N'", file=sys.stderr)
        return 1
    if update:
        for k, v in measured.items():
            text = re.sub(rf"^{k}\s+[0-9.]+\s*$", f"{k} {math.floor(v * 10) / 10:.1f}", text, flags=re.M)
        open(floor_path, "w").write(text)
        print(f"coverage: floor updated in {floor_path}: lines {math.floor(lines * 10) / 10:.1f}%, "
              f"branches {math.floor(branches * 10) / 10:.1f}%")
        return 0
    failed = False
    for k in ("lines", "branches"):
        ok = measured[k] >= floor[k]
        failed |= not ok
        print(f"coverage: {k} {measured[k]:.2f}% {'>=' if ok else 'is BELOW'} the floor {floor[k]:.1f}% ({floor_path})",
              file=sys.stdout if ok else sys.stderr)
    if failed:
        print("coverage: add tests for the new code, or record why it stays uncovered in "
              ".ci/coverage-uncovered.md and lower the floor with scripts/coverage --update-floor", file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
