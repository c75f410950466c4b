"""Shared by the binding's tests (ctest runs each file as python.<name>).

Environment, set by python/tests/CMakeLists.txt: PYTHONPATH (the staged
package), DCEL_CLI (the dcel executable, for the comparisons with the CLI),
DCEL_SOURCE_DIR (the repository), DCEL_ACCEPTANCE_DIR (the shared acceptance
fixtures, used only where that directory exists).
"""
import json
import os
import subprocess

import pytest
from hypothesis import settings

# No example database (each run starts afresh, as in CI) and no deadline (the
# machine is shared: a slow example is not a failure).
settings.register_profile("ctest", database=None, deadline=None)
settings.load_profile("ctest")

SOURCE_DIR = os.environ.get("DCEL_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))


def cli_path():
    path = os.environ.get("DCEL_CLI", "")
    if not path or not os.access(path, os.X_OK):
        pytest.skip("DCEL_CLI does not name the dcel executable")
    return path


def run_cli(*args, stdin=None, expect=(0,)):
    """stdout of `dcel ARGS...` (text); fails the test on an unexpected exit status."""
    done = subprocess.run([cli_path(), *args], input=stdin, capture_output=True, text=True, timeout=120)
    assert done.returncode in expect, f"dcel {' '.join(args)}: exit {done.returncode}: {done.stderr}"
    return done.stdout


def graph_json(vertices, edges):
    return json.dumps({"vertices": [list(map(float, p)) for p in vertices], "edges": [list(map(int, e)) for e in edges]})


def canonical_cycles(cycles):
    """The cycles up to order and rotation (direction kept): each rotated to its smallest vertex
    at the front (and, among those, the lexicographically smallest rotation), then sorted."""
    out = []
    for c in cycles:
        c = list(c)
        rotations = [c[i:] + c[:i] for i in range(len(c))] or [[]]
        out.append(min(rotations))
    return sorted(out)
