"""assert_same_faces(): silent on a right answer; on a wrong one, a message
with the graph (readable back), the reference, the answer, every difference
and an SVG drawing with the differing cycles highlighted."""
import json
import os
import re

import pytest

import dcel
from dcel.hypothesis import assert_same_faces

TRIANGLE = dcel.Graph([(0, 0), (4, 0), (0, 3)], [(0, 1), (1, 2), (2, 0)])


def test_a_right_answer_passes():
    assert_same_faces(TRIANGLE, [[0, 1, 2], [1, 0, 2]])
    assert_same_faces(TRIANGLE, dcel.build(TRIANGLE).to_dump(), kind="dump")
    assert_same_faces(dcel.build(TRIANGLE), [[2, 0, 1], [0, 2, 1]])


def test_a_wrong_answer_shows_everything():
    with pytest.raises(AssertionError) as caught:
        assert_same_faces(TRIANGLE, [[0, 1, 2], [0, 1, 2]])
    lines = str(caught.value).splitlines()
    assert lines[0] == "the answer differs from the reference (1 difference)"
    assert lines[1] == "graph (3 vertices, 3 edges):"
    graph = dcel.read_graph(lines[2].strip())
    assert graph.vertices.tolist() == [[0, 0], [4, 0], [0, 3]] and graph.edges.tolist() == [[0, 1], [1, 2], [2, 0]]
    assert lines[3:7] == ["reference (dcel faces):", "  [[0, 1, 2], [1, 0, 2]]", "answer:", "  [[0, 1, 2], [0, 1, 2]]"]
    assert lines[7] == "differences:" and lines[8].startswith("  reversed-cycle: answer cycle 1 [0, 1, 2]")
    path = re.fullmatch(r"drawn in (.*\.svg)", lines[-1]).group(1)
    assert os.path.isfile(path)
    assert "test_a_wrong_answer_shows_everything" in os.path.basename(path)  # one file per test
    svg = open(path, encoding="utf-8").read()
    assert svg.startswith("<svg") or svg.startswith("<?xml")
    assert 'id="highlight"' in svg and "reversed-cycle, 1 in all" in svg


def test_a_crash_in_the_answer_is_not_hidden_and_a_dump_is_checked_whole():
    dump = dcel.build(TRIANGLE).to_dump()
    dump["faces"][0]["inner"] = []
    with pytest.raises(AssertionError, match="broken-invariant"):
        assert_same_faces(TRIANGLE, dump)
    with pytest.raises(AssertionError, match="unreadable-answer"):
        assert_same_faces(TRIANGLE, [[0, 1, "two"]])


def test_long_graphs_are_shortened():
    g = dcel.Graph([(i, 0) for i in range(1000)], [(i, i + 1) for i in range(999)])
    with pytest.raises(AssertionError) as caught:
        assert_same_faces(g, [])
    assert "more characters)" in str(caught.value) and len(str(caught.value)) < 20000
    assert json.loads(json.dumps(str(caught.value)))
