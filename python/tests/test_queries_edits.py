"""locate, stab and the edits through the binding, each against something
computed another way: winding numbers walked on the DCEL's own arrays in
exact rationals (locate), a hand derivation (stab), and a rebuild of the
edited graph compared as a whole dump (the edits)."""
import random
from fractions import Fraction

import pytest

import dcel

SQUARE = ([(0, 0), (4, 0), (4, 4), (0, 4)], [(0, 1), (1, 2), (2, 3), (3, 0), (0, 2)])


def winding(d, h, p):
    """Winding number of the cycle through half-edge h around p (p on none of its edges), exact."""
    pts = d.points
    total = 0
    for x in d.cycle(h):
        (ax, ay), (bx, by) = (map(Fraction, pts[d.origin[x]])), (map(Fraction, pts[d.target[x]]))
        cross = (bx - ax) * (p[1] - ay) - (by - ay) * (p[0] - ax)
        if ay <= p[1] < by and cross > 0:
            total += 1
        elif by <= p[1] < ay and cross < 0:
            total -= 1
    return total


def inside(d, face, p):
    """Is p in the interior of face, judged from its cycles alone?"""
    f = d.faces[face]
    if f.outer is not None and winding(d, f.outer, p) != 1:
        return False
    return all(winding(d, h, p) == 0 for h in f.holes)


def on_edge(d, e, p):
    (ax, ay), (bx, by) = map(Fraction, d.points[d.origin[2 * e]]), map(Fraction, d.points[d.target[2 * e]])
    a, b = (Fraction(ax), Fraction(ay)), (Fraction(bx), Fraction(by))
    cross = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
    return cross == 0 and min(a, b) < p < max(a, b)


def test_locate_agrees_with_winding_numbers():
    rng = random.Random(5)
    for family in ("nested-polygons", "grid-with-holes", "components", "triangulation"):
        for seed in range(3):
            g = dcel.generate(family, seed, 30)
            d = dcel.build(g)
            xs = [p[0] for p in g.vertices] or [0]
            ys = [p[1] for p in g.vertices] or [0]
            probes = [(rng.uniform(min(xs) - 1, max(xs) + 1), rng.uniform(min(ys) - 1, max(ys) + 1)) for _ in range(60)]
            probes += [tuple(p) for p in g.vertices[:5]]
            probes += [((a[0] + b[0]) / 2, (a[1] + b[1]) / 2) for a, b in
                       ((g.vertices[u], g.vertices[v]) for u, v in g.edges[:5])]
            located = d.locate_many(probes)
            for p, where in zip(probes, located):
                assert d.locate(p) == where
                q = (Fraction(p[0]), Fraction(p[1]))
                if where.kind == "vertex":
                    assert tuple(d.points[where.id]) == tuple(p)
                elif where.kind == "edge":
                    assert on_edge(d, where.id, q)
                else:
                    holders = [f for f in range(d.num_faces) if inside(d, f, q)]
                    assert holders == [where.id], (family, seed, p, holders, where)


def test_stab_of_the_square_by_hand():
    d = dcel.build(*SQUARE)
    # y = 1 from x = -1: outside, across e3 (x = 0), the upper triangle (y > x),
    # across the diagonal e4 at (1, 1), the lower triangle, across e1 (x = 4), outside.
    pieces = d.stab((-1, 1), (5, 1))
    assert [(p.kind, p.id) for p in pieces] == [("face", 0), ("edge", 3), ("face", 2), ("edge", 4), ("face", 1),
                                                ("edge", 1), ("face", 0)]
    along = d.stab((0, 0), (4, 4))
    assert [(p.kind, p.id, p.along) for p in along] == [("vertex", 0, False), ("edge", 4, True), ("vertex", 2, False)]
    assert d.stab((1, 3), (1, 3)) == [dcel.StabPiece("face", 2)]
    assert [p.kind for p in d.stab((2, -1), (2, 0), line=True)] == ["face", "edge", "face", "edge", "face", "edge", "face"]
    with pytest.raises(dcel.InvalidInput, match="two different points"):
        d.stab((1, 1), (1, 1), line=True)


def assert_matches_a_rebuild(d):
    assert d.validate() == []
    report = dcel.check(d.graph(), d.to_dump(), kind="dump")
    assert report.agrees, report.text


def test_edits_match_a_rebuild_of_the_edited_graph():
    rng = random.Random(11)
    for family in ("triangulation", "nested-polygons", "tree", "components"):
        d = dcel.build(dcel.generate(family, 4, 25))
        for _ in range(40):
            step = rng.choice(["split", "add", "remove", "vertex", "point"])
            try:
                if step == "split" and d.num_edges:
                    e = rng.randrange(d.num_edges)
                    (ax, ay), (bx, by) = d.points[d.origin[2 * e]], d.points[d.target[2 * e]]
                    d.split_edge(e, ((ax + bx) / 2, (ay + by) / 2))
                elif step == "add" and d.num_vertices > 1:
                    d.add_edge(rng.randrange(d.num_vertices), rng.randrange(d.num_vertices))
                elif step == "remove" and d.num_edges:
                    d.remove_edge(rng.randrange(d.num_edges))
                elif step == "vertex":
                    d.add_vertex((rng.randint(-5, 500) + 0.5, rng.randint(-5, 500) + 0.25))
                elif step == "point" and d.num_vertices:
                    d.add_edge_to_point(rng.randrange(d.num_vertices), (rng.randint(0, 400) + 0.5, rng.randint(0, 400)))
            except (dcel.TopologyError, dcel.InvalidInput) as refused:
                assert "\n" not in str(refused)
                continue
            assert_matches_a_rebuild(d)


def test_a_change_says_which_ids_moved():
    d = dcel.build(*SQUARE)
    d.split_edge(0, (2, 0))  # edge 5 is new: 4 -> 1
    change = d.remove_edge(4)  # the diagonal: faces 1 and 2 merge into 1; edge 5 moves into 4
    assert change.faces == dcel.IdChange(removed=2, merged_into=1)
    assert change.edges == dcel.IdChange(removed=4, moved=5)
    assert change.edges.renamed(5) == 4 and change.edges.renamed(4) is None and change.faces.renamed(2) == 1
    assert sorted(d.origin[8:10].tolist()) == [1, 4]  # the old edge 5, now edge 4
    assert d.num_faces == 2 and d.face_area(1) == dcel.Area(16.0, 1)
    v = d.add_vertex((1, 3)).vertices.added
    assert d.faces[1].isolated == [v] and d.locate((1, 3)) == dcel.Location("vertex", v)
    assert d.remove_isolated_vertex(v).vertices == dcel.IdChange(removed=v)
    assert d.merge_collinear_edges(4).edges.removed is not None
    assert_matches_a_rebuild(d)


def test_refused_edits_name_the_ids_and_change_nothing():
    d = dcel.build(*SQUARE)
    before = d.to_json()
    with pytest.raises(dcel.TopologyError) as caught:
        d.add_edge(1, 3)  # crosses the diagonal e4
    assert 4 in caught.value.edges and {1, 3} <= set(caught.value.vertices), str(caught.value)
    with pytest.raises(dcel.TopologyError) as caught:
        d.split_edge(0, (1, 1))  # not on e0
    assert caught.value.edges == [0]
    with pytest.raises(dcel.TopologyError):
        d.merge_collinear_edges(0)  # three edges
    with pytest.raises(dcel.TopologyError):
        d.remove_isolated_vertex(0)
    assert d.to_json() == before
