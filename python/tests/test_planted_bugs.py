"""Hypothesis with dcel.hypothesis finds each bug planted in the pure-Python
DCEL (examples/python/pure_dcel.py) within its default 100 examples, on
each of the seeds 0..9, and shrinks it to a graph of at most 5 vertices (a
tiny-coordinate one for "tiny"); "recursive" needs one cycle of about a
thousand half-edges, so its graph only shrinks to no larger than the first
failing one, and still fails with RecursionError. The same test passes on
the correct solver."""
import math
import os
import sys
from fractions import Fraction

import pytest
from hypothesis import given, seed, settings

import dcel
from dcel.hypothesis import assert_same_faces, planar_graphs
from conftest import SOURCE_DIR

sys.path.insert(0, os.path.join(SOURCE_DIR, "examples", "python"))
from pure_dcel import PureDcel  # noqa: E402

# What each bug looks like when found: the first difference's kind, or the
# exception. A wrong order of three edges around a vertex is the reversed
# order, so a shrunk atan2 failure often reads as a reversed cycle.
EXPECTED = {"atan2": ("wrong-next", "reversed-cycle"), "ccw": ("wrong-next", "reversed-cycle"),
            "isolated": ("IndexError",),
            "tiny": ("wrong-next", "reversed-cycle", "missing-cycle", "extra-cycle"), "recursive": ("RecursionError",)}


def atan2_tie(graph):
    """Two edges leaving one vertex in different directions that math.atan2 cannot tell apart."""
    angles = {}
    for u, v in graph.edges:
        for a, b in ((u, v), (v, u)):
            (x0, y0), (x1, y1) = (map(Fraction, graph.vertices[a])), (map(Fraction, graph.vertices[b]))
            d = (x1 - x0, y1 - y0)
            angles.setdefault((a, math.atan2(float(d[1]), float(d[0]))), []).append(d)
    return any(p[0] * q[1] != p[1] * q[0] for ds in angles.values() for p in ds for q in ds)


def hunt(bug, hypothesis_seed):
    """Runs the property once as a user would (default 100 examples); returns (index of the first
    failing example or None, the first failing graph, the final shrunk graph, how that one failed)."""
    calls, first, failing = [0], [], []

    @settings(max_examples=100, database=None, deadline=None)
    @seed(hypothesis_seed)
    @given(planar_graphs())
    def property_(graph):
        calls[0] += 1
        try:
            assert_same_faces(graph, PureDcel(graph.vertices, graph.edges, bug=bug).cycles())
        except BaseException as e:
            if not first:
                first.extend([calls[0], graph])
            failing.append((graph, e))
            raise

    try:
        property_()
    except (AssertionError, IndexError, RecursionError):
        graph, error = failing[-1]  # Hypothesis replays the shrunk example last
        how = dcel.check(graph, PureDcel(graph.vertices, graph.edges, bug=bug).cycles())[0].kind if isinstance(
            error, AssertionError) else type(error).__name__
        return first[0], first[1], graph, how
    return None, None, None, None


@pytest.mark.parametrize("bug", sorted(EXPECTED))
@pytest.mark.parametrize("hypothesis_seed", range(10))
def test_each_planted_bug_is_found_and_shrunk(bug, hypothesis_seed):
    first, first_graph, graph, how = hunt(bug, hypothesis_seed)
    assert first is not None and first <= 100, f"{bug} not found in 100 examples with seed {hypothesis_seed}"
    assert how in EXPECTED[bug], how
    if bug == "recursive":
        # Its smallest graph has one cycle of about a thousand half-edges:
        # shrinking only goes down to there, and the graph still fails.
        assert len(graph.vertices) <= len(first_graph.vertices), (len(graph.vertices), len(first_graph.vertices))
    else:
        assert len(graph.vertices) <= 5, graph
    if bug == "atan2":
        assert atan2_tie(graph), graph
    if bug == "tiny":
        assert any(0 < abs(c) < 1e-200 for p in graph.vertices for c in p), graph
    shown = f"{len(graph.vertices)} vertices, {len(graph.edges)} edges" if bug == "recursive" else graph
    print(f"{bug} seed {hypothesis_seed}: found at example {first} ({len(first_graph.vertices)} vertices), "
          f"shrunk to {len(graph.vertices)} vertices: {shown}")


CORRECT_EXAMPLES = int(os.environ.get("DCEL_CORRECT_EXAMPLES", "500"))


@settings(max_examples=CORRECT_EXAMPLES, database=None, deadline=None)
@given(planar_graphs())
def test_the_correct_solver_passes(graph):
    mine = PureDcel(graph.vertices, graph.edges, bug="")
    assert_same_faces(graph, mine.cycles())
    assert_same_faces(graph, mine.to_dump(), kind="dump")
