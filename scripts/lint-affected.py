#!/usr/bin/env python3
"""Which translation units a change touches, for `scripts/lint --since`.

stdin: changed paths relative to the repository root (git diff --name-only).
argv:  the translation units (absolute paths).
stdout: the units to lint: those changed, those that include a changed
header of src/ directly or through other headers, or every unit when
.clang-tidy changed. Includes are followed by reading `#include "..."`
lines, resolved beside the including file, then under src/.
"""
import os
import re
import sys

ROOT = os.path.realpath(os.path.join(os.path.dirname(__file__), ".."))
SRC = os.path.join(ROOT, "src")
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.M)


def includes(path, cache={}):
    if path not in cache:
        found = []
        try:
            text = open(path, encoding="utf-8", errors="replace").read()
        except OSError:
            text = ""
        for name in INCLUDE.findall(text):
            for base in (os.path.dirname(path), SRC):
                candidate = os.path.realpath(os.path.join(base, name))
                if os.path.isfile(candidate):
                    found.append(candidate)
                    break
        cache[path] = found
    return cache[path]


def reaches(unit, changed):
    seen, todo = set(), [unit]
    while todo:
        f = todo.pop()
        if f in seen:
            continue
        seen.add(f)
        if f in changed:
            return True
        todo.extend(includes(f))
    return False


def main():
    changed_rel = [line.strip() for line in sys.stdin if line.strip()]
    units = [os.path.realpath(u) for u in sys.argv[1:]]
    if ".clang-tidy" in changed_rel:
        print("\n".join(units))
        return
    changed = {os.path.realpath(os.path.join(ROOT, p)) for p in changed_rel}
    for unit in units:
        if reaches(unit, changed):
            print(unit)


if __name__ == "__main__":
    main()
