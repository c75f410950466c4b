#!/usr/bin/env python3
"""dcel diff-merge on what it must refuse and what it must carry: each case
prints one line "ok ..." or "FAIL ...", then a count; exit 1 on a failure.

    merge_test.py DCEL IMPLS_DIR VALIDATOR

Refused, with one line and exit 2: a missing shard, a shard given twice, a
report that is no shard's, a file that is not JSON, shards of two campaigns,
a report missing a field, a "shard" that is not K/N. Carried: the skip reasons of a program that skips
(summed across shards, a run that agrees), and JUnit and JSON that the
schema validator accepts.
"""
import json
import os
import subprocess
import sys
import tempfile

dcel, impls, validator = sys.argv[1:4]
failures = 0


def check(name, ok, detail=""):
    global failures
    print(("ok   " if ok else "FAIL ") + name + ("" if ok else ": " + detail))
    failures += 0 if ok else 1


def run(*args):
    return subprocess.run([dcel, *args], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def shards(tmp, impl, count, name, *extra):
    paths = []
    for k in range(1, count + 1):
        path = os.path.join(tmp, f"{name}-{k}.json")
        run("diff", "--impl", impl, "--stream", "--cases", "24", "--shard", f"{k}/{count}", "--report", path, *extra)
        paths.append(path)
    return paths


def refused(name, paths, words):
    r = run("diff-merge", *paths)
    line = r.stderr.strip()
    check(name, r.returncode == 2 and "\n" not in line and words in line and r.stdout == "",
          f"exit {r.returncode}, stderr {line!r}")


with tempfile.TemporaryDirectory() as tmp:
    two = f"/usr/bin/python3 {impls}/two_bugs.py"
    a = shards(tmp, two, 3, "a")
    refused("a missing shard", a[:2], "shard 3/3 is missing")
    refused("a shard twice", [a[0], a[0], a[2]], "shard 1/3 again")
    b = shards(tmp, two, 2, "b")
    refused("shards of another N", [a[0], a[1], b[1]], "a shard of 2")
    c = shards(tmp, two, 3, "c", "--seed", "7")
    refused("another campaign", [a[0], a[1], c[2]], "another campaign")
    whole = os.path.join(tmp, "whole.json")
    run("diff", "--impl", two, "--stream", "--cases", "24", "--keep-going", "--report", whole)
    refused("a report that is no shard's", [whole], "not the report of a shard")
    text = os.path.join(tmp, "text.json")
    with open(text, "w") as f:
        f.write("not json\n")
    refused("not JSON", [text], "not a JSON report")
    broken = os.path.join(tmp, "broken.json")
    with open(a[0]) as f:
        doc = json.load(f)
    del doc["cases_run"]
    with open(broken, "w") as f:
        json.dump(doc, f)
    refused("a field missing", [broken, a[1], a[2]], 'no "cases_run"')
    doc = json.load(open(a[0]))
    doc["format"] = "something else"
    with open(broken, "w") as f:
        json.dump(doc, f)
    refused("another format", [broken, a[1], a[2]], "not a dcel diff report")
    for shard in ("1x/3", "-1/3", "1/3/3", "0/3", "4/3", "/3"):
        doc = json.load(open(a[0]))
        doc["shard"] = shard
        with open(broken, "w") as f:
            json.dump(doc, f)
        refused(f"shard {shard!r}", [broken, a[1], a[2]], '"shard" is not K/N')

    # Carried: JSON and JUnit valid; a failing campaign exits 1.
    merged, junit = os.path.join(tmp, "merged.json"), os.path.join(tmp, "merged.xml")
    r = run("diff-merge", *a, "--report", merged, "--junit", junit)
    v = subprocess.run(["/usr/bin/python3", validator, merged, junit], stdout=subprocess.PIPE, text=True)
    check("merged JSON and JUnit valid", r.returncode == 1 and v.returncode == 0, f"exit {r.returncode}, {v.stdout}")
    report = json.load(open(merged))
    check("the merged report names its shards", report["shards"] == 3 and report["shard"] is None, str(report["shards"]))

    # Skips summed by reason; a campaign that agrees exits 0.
    skip = f"/usr/bin/python3 {impls}/skip_negative.py"
    s = shards(tmp, skip, 2, "s")
    r = run("diff-merge", *s, "--report", merged)
    report = json.load(open(merged))
    parts = [json.load(open(p)) for p in s]
    want = sum(p["skipped_by_impl"] for p in parts)
    got = sum(x["cases"] for x in report["skip_reasons"])
    check("skips summed, agreeing", r.returncode == 0 and report["agrees"] and got == want and want > 0,
          f"exit {r.returncode}, {got} vs {want}")

print(f"{failures} failed" if failures else "all merge checks passed")
sys.exit(1 if failures else 0)
