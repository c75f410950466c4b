"""pure_dcel.py checked against the reference with pytest and Hypothesis
(docs/python.md). Run from the repository root:

    python3 -m pytest examples/python/test_pure_dcel.py
"""
from hypothesis import given

import dcel
from dcel.hypothesis import assert_same_faces, planar_graphs
from pure_dcel import PureDcel


@given(planar_graphs())
def test_boundary_cycles(graph):
    mine = PureDcel(graph.vertices, graph.edges)
    assert_same_faces(graph, mine.cycles())


@given(planar_graphs(max_vertices=20))
def test_whole_dcel(graph):
    mine = PureDcel(graph.vertices, graph.edges)
    report = dcel.check(graph, mine.to_dump(), kind="dump")
    assert report.agrees, report.text


def test_a_square_with_a_hole_and_an_isolated_vertex():
    vertices = [(0, 0), (6, 0), (6, 6), (0, 6), (2, 2), (4, 2), (3, 4), (5, 5)]
    edges = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 4)]
    mine = PureDcel(vertices, edges)
    square = next(f for f in mine.faces if f["outer"] is not None and f["inner"])
    assert square["isolated"] == [7]
    assert dcel.check((vertices, edges), mine.to_dump()).agrees
