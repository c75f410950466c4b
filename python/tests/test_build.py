"""build(): the arrays of a DCEL derived by hand, the numpy views (no copies,
read-only, copy on write under edits), every input form, and the errors."""
import gc

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import dcel

# A square with one diagonal (tests/consumer/square.json). Half-edges: h0 0->1,
# h1 1->0, h2 1->2, h3 2->1, h4 2->3, h5 3->2, h6 3->0, h7 0->3, h8 0->2,
# h9 2->0. By hand: the lower triangle 0->1->2 is h0 h2 h9 (face 1, smallest
# half-edge h0), the upper 0->2->3 is h8 h4 h6 (face 2), the outside 0->3->2->1
# is h7 h5 h3 h1 (face 0's hole).
SQUARE = ([(0, 0), (4, 0), (4, 4), (0, 4)], [(0, 1), (1, 2), (2, 3), (3, 0), (0, 2)])
NEXT = {0: 2, 2: 9, 9: 0, 8: 4, 4: 6, 6: 8, 7: 5, 5: 3, 3: 1, 1: 7}
FACE = {0: 1, 2: 1, 9: 1, 4: 2, 6: 2, 8: 2, 1: 0, 3: 0, 5: 0, 7: 0}


def test_arrays_of_a_square_with_a_diagonal():
    d = dcel.build(*SQUARE)
    assert (d.num_vertices, d.num_edges, d.num_half_edges, d.num_faces) == (4, 5, 10, 3)
    assert d.origin.tolist() == [0, 1, 1, 2, 2, 3, 3, 0, 0, 2]
    assert d.twin.tolist() == [1, 0, 3, 2, 5, 4, 7, 6, 9, 8]
    assert d.target.tolist() == [1, 0, 2, 1, 3, 2, 0, 3, 2, 0]
    assert d.next.tolist() == [NEXT[h] for h in range(10)]
    assert d.prev.tolist() == [next(g for g in NEXT if NEXT[g] == h) for h in range(10)]
    assert d.face.tolist() == [FACE[h] for h in range(10)]
    assert d.out.tolist() == [0, 1, 3, 5]  # the smallest half-edge leaving each vertex
    assert d.points.tolist() == [[0, 0], [4, 0], [4, 4], [0, 4]]
    f0, f1, f2 = d.faces
    assert f0 == dcel.Face(0, None, [1], [])
    assert f1.outer in (0, 2, 9) and f1.holes == [] and f2.outer in (4, 6, 8)
    assert d.outer.tolist() == [dcel.NULL, f1.outer, f2.outer]
    assert d.cycle(0) == [0, 2, 9] and d.cycle_vertices(7) == [0, 3, 2, 1]
    assert d.around(0) == [0, 7, 8]  # leaving (0,0): east, then clockwise north, then north-east
    assert d.boundary_cycles() == [[0, 1, 2], [1, 0, 3, 2], [2, 3, 0]]
    assert dcel.faces(*SQUARE) == d.boundary_cycles()
    assert d.face_area(1) == dcel.Area(8.0, 1) and d.cycle_area(1) == dcel.Area(-16.0, -1)
    assert d.neighbours(1) == [0, 2] and d.count_components() == 1
    assert d.validate() == []


def test_arrays_are_read_only_views_without_copies():
    d = dcel.build(*SQUARE)
    a, b = d.next, d.next
    assert a.ctypes.data == b.ctypes.data  # one buffer, the C++ vector's
    assert not a.flags.writeable and not a.flags.owndata
    for name in ("points", "origin", "next", "prev", "face", "out"):
        view = getattr(d, name)
        assert not view.flags.owndata and not view.flags.writeable, name
        with pytest.raises(ValueError):
            view[0] = 0
    assert d.points.dtype == np.float64 and d.origin.dtype == np.uint32


def test_a_view_outlives_its_dcel_and_never_changes_under_edits():
    d = dcel.build(*SQUARE)
    origin, points = d.origin, d.points
    change = d.split_edge(0, (2, 0))  # while views exist: the edit works on a copy
    assert change.vertices.added == 4 and change.edges.added == 5 and change.edges.added_from == 0
    assert origin.tolist() == [0, 1, 1, 2, 2, 3, 3, 0, 0, 2] and len(points) == 4
    assert d.origin.tolist()[-2:] == [4, 1] and d.points.tolist()[-1] == [2, 0]
    del d
    gc.collect()
    assert origin.sum() == 14 and points[1].tolist() == [4, 0]  # still valid memory


def test_every_input_form_gives_the_same_dcel():
    vertices, edges = SQUARE
    expected = dcel.build(vertices, edges).boundary_cycles()
    forms = [
        (np.array(vertices, dtype=np.float64), np.array(edges, dtype=np.int64)),
        (np.array(vertices, dtype=np.int32), np.array(edges, dtype=np.uint32)),
        (np.array(vertices, dtype=np.float32), np.array(edges, dtype=np.int32)),
        ([list(p) for p in vertices], [list(e) for e in edges]),
        (tuple(vertices), tuple(edges)),
        (vertices, [(float(u), float(v)) for u, v in edges]),  # integral floats are indexes
        (vertices, [(np.int16(u), np.uint64(v)) for u, v in edges]),
        (np.asfortranarray(np.array(vertices, dtype=float)), np.array(edges)[:, ::-1][:, ::-1]),
    ]
    for v, e in forms:
        assert dcel.build(v, e).boundary_cycles() == expected
    assert dcel.build(dcel.Graph(vertices, edges)).boundary_cycles() == expected
    assert dcel.build({"vertices": vertices, "edges": edges}).boundary_cycles() == expected
    assert dcel.build((vertices, edges)).boundary_cycles() == expected
    assert dcel.build([], []).num_faces == 1 and dcel.build([(1, 2)], []).faces[0].isolated == [0]
    assert dcel.build(np.zeros((0, 2)), np.zeros((0, 2), dtype=int)).num_vertices == 0


def test_check_crossings_off_still_places_holes():
    g = ([(0, 0), (9, 0), (0, 9), (1, 1), (2, 1), (1, 2)], [(0, 1), (1, 2), (2, 0), (3, 4), (4, 5), (5, 3)])
    assert dcel.build(*g, check_crossings=False).faces[1].holes == dcel.build(*g).faces[1].holes != []


@pytest.mark.parametrize(
    "vertices, edges, kind, bad_vertices, bad_edges, words",
    [
        ([(0, 0), (2, 2), (0, 2), (2, 0)], [(0, 1), (2, 3)], "crossing", [], [0, 1], "cross"),
        ([(0, 0), (1, 1), (0, 0)], [], "duplicate-point", [0, 2], [], "same point"),
        ([(0, 0), (1, 1)], [(0, 1), (1, 0)], "duplicate-edge", [0, 1], [0, 1], "both join"),
        ([(0, 0), (1, 1)], [(1, 1)], "self-loop", [1], [0], ""),
        ([(0, 0), (2, 0), (1, 0)], [(0, 1)], "vertex-on-edge", [2], [0], ""),
        ([(0, 0), (1, 1)], [(0, 5)], "bad-index", [], [0], "5"),
        ([(0, 0), (1, 1)], [(0, -1)], "bad-index", [], [0], "edges[0][1]: vertex index -1 is negative"),
        ([(0, 0), (1, 1)], [(0, 0.5)], "bad-index", [], [0], "edges[0][1]: vertex index 0.5 is not an integer"),
        ([(0, 0), (1, 1)], np.array([[0, 2**40]]), "bad-index", [], [0], "is too large"),
        ([(0, 0), (float("nan"), 1)], [], "bad-coordinate", [1], [], ""),
        ([(0, 0), (1, "a")], [], "shape", [], [], "vertices[1][1]: expected a number, found 'a'"),
        ([(0, 0), (1, 1, 1)], [], "shape", [], [], "vertices[1]: expected a point (x, y)"),
        (np.zeros((3, 3)), [], "shape", [], [], "found shape (3, 3)"),
        ([(0, 0), (1, 1)], [(0, None)], "bad-index", [], [0], "None is not an integer"),
        ([(0, 0), (1, 1)], np.array([[True, False]]), "shape", [], [], "dtype bool"),
    ],
)
def test_invalid_input_names_what_and_where(vertices, edges, kind, bad_vertices, bad_edges, words):
    with pytest.raises(dcel.InvalidInput) as caught:
        dcel.build(vertices, edges)
    e = caught.value
    assert isinstance(e, ValueError)
    assert (e.kind, sorted(e.vertices), sorted(e.edges)) == (kind, bad_vertices, bad_edges), str(e)
    assert words in str(e) and "\n" not in str(e)


def test_ids_out_of_range_are_refused_before_the_library_sees_them():
    d = dcel.build(*SQUARE)
    for call in (lambda: d.cycle(10), lambda: d.cycle(-1), lambda: d.face_area(3), lambda: d.around(4),
                 lambda: d.split_edge(5, (0, 0)), lambda: d.remove_isolated_vertex(-3)):
        with pytest.raises(dcel.InvalidInput) as caught:
            call()
        assert caught.value.kind == "bad-index" and "does not exist" in str(caught.value)
    with pytest.raises(dcel.InvalidInput, match="finite"):
        d.locate((float("inf"), 0))


JUNK = st.recursive(
    st.none() | st.booleans() | st.integers(-(2**70), 2**70) | st.floats() | st.text(max_size=3),
    lambda inner: st.lists(inner, max_size=4) | st.tuples(inner, inner),
    max_leaves=12,
)


@settings(max_examples=400)
@given(JUNK, JUNK)
def test_junk_input_is_refused_cleanly(vertices, edges):
    """Whatever Python hands it, build() returns a Dcel or raises InvalidInput (one line)."""
    try:
        d = dcel.build(vertices, edges)
    except dcel.InvalidInput as e:
        assert str(e) and "\n" not in str(e)
    else:
        assert d.validate() == []


@settings(max_examples=200)
@given(st.lists(st.tuples(st.integers(-3, 3), st.integers(-3, 3)), max_size=8, unique=True),
       st.lists(st.tuples(st.integers(-2, 9), st.integers(-2, 9)), max_size=8))
def test_small_graphs_build_or_are_refused_with_their_ids(vertices, edges):
    try:
        d = dcel.build(vertices, edges)
    except dcel.InvalidInput as e:
        assert e.vertices or e.edges, str(e)
        assert all(0 <= v < len(vertices) for v in e.vertices) and all(0 <= k < len(edges) for k in e.edges)
    else:
        assert d.validate() == [] and d.num_edges == len(edges)
