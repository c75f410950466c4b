"""check() and validate(): every answer form the docs promise, each kind of
difference on a hand-made wrong answer, and each validate checker on a
hand-made corruption of a dump (the expected kind derived by hand)."""
import json

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import dcel

TRIANGLE = ([(0, 0), (4, 0), (0, 3)], [(0, 1), (1, 2), (2, 0)])
RIGHT = [[0, 1, 2], [1, 0, 2]]  # inside counterclockwise, outside clockwise
# A square with a triangle hole and an isolated vertex inside, and one outside.
NESTED = (
    [(0, 0), (10, 0), (10, 10), (0, 10), (2, 2), (5, 2), (2, 5), (8, 8), (20, 20)],
    [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 4)],
)


def kinds(report):
    return [d.kind for d in report]


def test_every_faces_answer_form_agrees():
    text = json.dumps({"faces": RIGHT})
    for answer in (RIGHT, {"faces": RIGHT}, [tuple(c) for c in RIGHT], [np.array(c) for c in RIGHT],
                   np.array(RIGHT), [[1, 2, 0], [0, 2, 1]], text, text.encode(), [RIGHT[1], RIGHT[0]]):
        report = dcel.check(TRIANGLE, answer)
        assert report.agrees and len(report) == 0 and report.kind == "faces", (answer, report.text)
    assert dcel.check(dcel.build(*TRIANGLE), RIGHT, kind="faces").agrees  # a Dcel as the reference
    assert dcel.check(dcel.Graph(*TRIANGLE), RIGHT).agrees
    assert dcel.check({"vertices": TRIANGLE[0], "edges": TRIANGLE[1]}, RIGHT).agrees


@pytest.mark.parametrize(
    "answer, expected",
    [
        ([[0, 1, 2], [0, 1, 2]], ["reversed-cycle"]),  # the outside walked the wrong way round
        ([[0, 1, 2]], ["missing-cycle"]),
        ([[0, 1, 2], [1, 0, 2], [1, 0, 2]], ["extra-cycle"]),
        ([[0, 1, 2], [1, 0, 2], [3]], ["vertex-count"]),
        ([[0, -1]], ["unreadable-answer"]),
        ([[0, "x"]], ["unreadable-answer"]),
        ({"cycles": RIGHT}, ["unreadable-answer"]),
        ("[[0, 1, 2], [1, 0", ["unreadable-answer"]),
    ],
)
def test_each_kind_of_difference(answer, expected):
    report = dcel.check(TRIANGLE, answer)
    assert not report.agrees
    assert sorted(set(kinds(report))) == sorted(expected), report.text
    assert report.text.splitlines()[0].endswith("difference" if len(report) == 1 else "differences")
    for d in report:
        assert d.message and "\n" not in d.message


def test_not_an_edge_on_a_path():
    path = ([(0, 0), (1, 0), (2, 0)], [(0, 1), (1, 2)])
    report = dcel.check(path, [[0, 2, 1, 0]])
    assert "not-an-edge" in kinds(report), report.text


def test_wrong_next_and_reversed_cycle_on_stars():
    # Centre 0, arms 1 east, 2 north, 3 west. By hand: next(1->0) leaves 0 just
    # clockwise from east, which is west (nothing points south): 0->3; then
    # 3->0, clockwise from west is north: 0->2; then 2->0, clockwise from north
    # is east: 0->1. One cycle from h0: 0, 1, 0, 3, 0, 2. Counterclockwise
    # turns walk it backwards.
    star = ([(0, 0), (1, 0), (0, 1), (-1, 0)], [(0, 1), (0, 2), (0, 3)])
    assert dcel.faces(*star) == [[0, 1, 0, 3, 0, 2]]
    assert kinds(dcel.check(star, [[0, 1, 0, 2, 0, 3]])) == ["reversed-cycle"]
    # With a fourth arm, 4 south, clockwise from east is south: 0, 1, 0, 4, 0, 3, 0, 2.
    # West before south at v0 (two arms swapped) is a wrong turn, not a reversal.
    star4 = (star[0] + [(0, -1)], star[1] + [(0, 4)])
    assert dcel.faces(*star4) == [[0, 1, 0, 4, 0, 3, 0, 2]]
    report = dcel.check(star4, [[0, 1, 0, 3, 0, 4, 0, 2]])
    first = report[0]
    assert first.kind == "wrong-next", report.text
    assert "at v1->v0 the answer continues to v0->v3" in first.message and "the reference to v0->v4" in first.message


def test_dumps_in_every_form():
    d = dcel.build(*NESTED)
    columns = {"vertices": d.points, "origin": d.origin, "twin": d.twin, "next": d.next, "prev": d.prev,
               "face": d.face, "faces": d.faces, "out": d.out}
    minus_one = dict(columns, out=np.where(d.out == dcel.NULL, -1, d.out.astype(np.int64)),
                     faces=[{"outer": -1 if f.outer is None else f.outer, "holes": f.holes, "isolated": f.isolated}
                            for f in d.faces])
    for answer in (d, d.to_dump(), d.to_json(), d.to_json(compact=True), columns, minus_one,
                   dict(columns, out=None)):
        report = dcel.check(NESTED, answer)
        assert report.agrees and report.kind == "dump", report.text
        assert dcel.validate(answer) == []
    assert dcel.check(NESTED, d.to_dump(), kind="faces").kind == "faces"  # told: read as faces, so unreadable
    assert kinds(dcel.check(NESTED, d.to_dump(), kind="faces")) == ["unreadable-answer"]


def corrupted(edit):
    dump = dcel.build(*NESTED).to_dump()
    edit(dump)
    return dump


def swap_next(dump):
    h = dump["half_edges"]
    h[0]["next"], h[2]["next"] = h[2]["next"], h[0]["next"]


def move_isolated(dump):
    where = next(f for f in dump["faces"] if 7 in f["isolated"])
    where["isolated"].remove(7)
    dump["faces"][0]["isolated"].append(7)


def reverse_twin(dump):
    dump["half_edges"][0]["twin"] = 2


def wrong_face(dump):
    h = dump["half_edges"][0]
    h["face"] = (h["face"] + 1) % len(dump["faces"])


def hole_elsewhere(dump):
    inner = next(f for f in dump["faces"] if f["outer"] is not None and f["inner"])
    dump["faces"][0]["inner"].append(inner["inner"].pop())


def bad_point(dump):
    dump["vertices"][4] = [2, 3]


@pytest.mark.parametrize(
    "corruption, invariant, difference",
    [
        (swap_next, "next-prev", "broken-invariant"),
        (reverse_twin, "twin", "broken-invariant"),
        (wrong_face, "face-on-cycle", "broken-invariant"),
        (move_isolated, "hole-placement", "broken-invariant"),
        (hole_elsewhere, "face-records", "broken-invariant"),
        (bad_point, None, "wrong-point"),
    ],
)
def test_each_corruption_is_reported(corruption, invariant, difference):
    dump = corrupted(corruption)
    violations = dcel.validate(dump)
    if invariant is not None:
        assert invariant in [v.invariant for v in violations], violations
        assert all(v.message and "\n" not in v.message for v in violations)
    report = dcel.check(NESTED, dump)
    assert difference in kinds(report), report.text


def test_validate_refuses_what_is_not_a_dump():
    with pytest.raises(dcel.InvalidInput) as caught:
        dcel.validate({"vertices": [[0, 0]], "half_edges": [{"origin": 0}], "faces": []})
    assert "half_edges[0]" in str(caught.value)
    with pytest.raises(ValueError, match="unknown kind"):
        dcel.check(TRIANGLE, RIGHT, kind="rings-maybe")
    with pytest.raises(dcel.InvalidInput, match="cross"):
        dcel.check(([(0, 0), (2, 2), (0, 2), (2, 0)], [(0, 1), (2, 3)]), [])


def test_the_report_is_a_sequence_with_the_cli_text():
    report = dcel.check(TRIANGLE, [[0, 1, 2], [0, 1, 2]], kind="faces")
    assert len(report) == 1 and list(report) == [report[0]] and report[:1] == [report[0]]
    assert report[0] == dcel.Difference("reversed-cycle", report[0].message, [0, 1, 2])
    assert report.text == "1 difference\nreversed-cycle: " + report[0].message + "\n"
    assert report.unlisted == 0 and "1 difference" in repr(report)
    huge = dcel.check(TRIANGLE, [[0, 1, 2], [1, 0, 2]] + [[0, 1, 2]] * 150)
    assert len(huge) == 100 and huge.unlisted > 0 and "more not listed" in huge.text


JUNK = st.recursive(
    st.none() | st.booleans() | st.integers(-(2**70), 2**70) | st.floats() | st.text(max_size=3),
    lambda inner: st.lists(inner, max_size=4) | st.dictionaries(st.sampled_from(
        ["faces", "vertices", "half_edges", "origin", "twin", "next", "prev", "face", "outer", "inner", "isolated"]),
        inner, max_size=4),
    max_leaves=16,
)


@settings(max_examples=400)
@given(JUNK, st.sampled_from([None, "faces", "dump"]))
def test_junk_answers_are_differences_not_crashes(answer, kind):
    """check() of anything gives a Report; a malformed answer is an unreadable-answer difference."""
    report = dcel.check(NESTED, answer, kind=kind)
    assert report.agrees or len(report) > 0
    for d in report:
        assert d.message and "\n" not in d.message


@settings(max_examples=300)
@given(st.data())
def test_random_corruptions_of_a_dump_are_never_accepted(data):
    """Change one id of a valid dump to another value: validate() reports it, or it is still the reference DCEL
    (e.g. another half-edge of the same cycle as a face's outer), in which case check() agrees too."""
    dump = dcel.build(*NESTED).to_dump()
    h = data.draw(st.integers(0, len(dump["half_edges"]) - 1))
    field = data.draw(st.sampled_from(["origin", "twin", "next", "prev", "face"]))
    value = data.draw(st.integers(0, 20))
    original = dump["half_edges"][h][field]
    dump["half_edges"][h][field] = value
    violations = dcel.validate(dump)
    report = dcel.check(NESTED, dump)
    if value == original:
        assert violations == [] and report.agrees
    else:
        assert violations and not report.agrees, (h, field, value)


# The answer kinds of the checker (docs/checking.md): NESTED's bounded faces
# by hand. Face 1 is the square with the triangle as its hole (and the
# isolated vertex 7 inside, which polygons cannot see); face 2 the triangle.
SQUARE_SHELL, TRIANGLE_HOLE, TRIANGLE_SHELL = [0, 1, 2, 3], [4, 6, 5], [4, 5, 6]


def test_polygons_and_rings_by_hand():
    polygons = [[SQUARE_SHELL, TRIANGLE_HOLE], [TRIANGLE_SHELL]]
    for answer, kind in ((polygons, "polygons"), ({"polygons": polygons}, None),
                         ([SQUARE_SHELL, TRIANGLE_SHELL], "rings"), ({"rings": [SQUARE_SHELL, TRIANGLE_SHELL]}, None)):
        report = dcel.check(NESTED, answer, kind=kind)
        assert report.agrees and report.kind in ("polygons", "rings"), report.text
    points = [[list(map(float, NESTED[0][v])) for v in ring] for ring in (SQUARE_SHELL, TRIANGLE_HOLE)]
    assert dcel.check(NESTED, [points, [[list(map(float, NESTED[0][v])) for v in TRIANGLE_SHELL]]],
                      kind="polygons").agrees
    forgot_the_hole = dcel.check(NESTED, [[SQUARE_SHELL], [TRIANGLE_SHELL]], kind="polygons")
    assert kinds(forgot_the_hole) == ["wrong-hole"], forgot_the_hole.text
    reversed_rings = [[list(reversed(SQUARE_SHELL)), list(reversed(TRIANGLE_HOLE))], [list(reversed(TRIANGLE_SHELL))]]
    clockwise = dcel.check(NESTED, reversed_rings, kind="polygons")
    assert set(kinds(clockwise)) == {"wrong-orientation"} and any("face-on right" in n for n in clockwise.notes)
    assert dcel.check(NESTED, reversed_rings, kind="polygons", face_on_right=True).agrees
    assert dcel.check(NESTED, reversed_rings, kind="polygons", unoriented=True).agrees


def test_conventions_and_notes():
    cycles = dcel.faces(*NESTED)
    detected = dcel.check(NESTED, cycles)
    assert detected.agrees and detected.kind == "faces" and detected.notes  # a bare list: the note says how it was read
    assert not dcel.check(NESTED, {"faces": cycles}).notes
    one_based = [[v + 1 for v in c] for c in cycles]
    assert not dcel.check(NESTED, {"faces": one_based}).agrees
    assert dcel.check(NESTED, {"faces": one_based}, one_based=True).agrees
    backwards = [list(reversed(c)) for c in cycles]
    assert dcel.check(NESTED, {"faces": backwards}, face_on_right=True).agrees


def test_a_shapely_polygonize_answer():
    shapely = pytest.importorskip("shapely")
    from shapely.geometry import GeometryCollection, LineString
    from shapely.ops import polygonize

    vertices, edges = NESTED
    pieces = GeometryCollection(list(polygonize([LineString([vertices[u], vertices[v]]) for u, v in edges])))
    report = dcel.check(NESTED, pieces)  # GeoJSON through __geo_interface__; GEOS writes shells clockwise
    assert report.kind == "polygons" and not report.agrees, report.text
    assert dcel.check(NESTED, pieces, unoriented=True).agrees or dcel.check(NESTED, pieces, face_on_right=True).agrees
