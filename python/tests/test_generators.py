"""The generators through the binding (against `dcel gen`, and by what they
promise: valid, deterministic, smaller when shrinking, exact transforms,
refused defects) and the Hypothesis strategy planar_graphs()."""
import json

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import dcel
from dcel.hypothesis import planar_graphs
from conftest import canonical_cycles, run_cli


def test_generate_is_dcel_gen():
    for family in dcel.families():
        for seed in (0, 7, 2**64 - 1):
            g = dcel.generate(family, seed, 20)
            cli = json.loads(run_cli("gen", "--family", family, "--seed", str(seed), "--vertices", "20"))
            assert [list(p) for p in g.vertices] == cli["vertices"] and [list(e) for e in g.edges] == cli["edges"]
            assert dcel.generate(family, seed, 20) == g  # deterministic
            assert len(g.vertices) == 20
            dcel.build(g)  # valid


def test_generate_refuses_bad_arguments():
    with pytest.raises(dcel.InvalidInput, match="unknown family \"mesh\"; the families are random-segments"):
        dcel.generate("mesh", 1)
    with pytest.raises(dcel.InvalidInput, match="not an unsigned 64-bit integer"):
        dcel.generate("tree", -1)
    with pytest.raises(dcel.InvalidInput, match="not an unsigned 64-bit integer"):
        dcel.generate("tree", 2**64)
    with pytest.raises(dcel.InvalidInput, match="more than 10000"):
        dcel.generate("tree", 1, 10001)


def size(g):
    return (len(g.edges), len(g.vertices))


def test_shrink_candidates_are_valid_and_smaller():
    for family in dcel.families():
        g = dcel.generate(family, 3, 12)
        candidates = dcel.shrink_candidates(g)
        assert candidates and candidates[0] == dcel.Graph([], [])
        for c in candidates:
            dcel.build(c)
            smaller = size(c) < size(g) or (size(c) == size(g) and c.vertices != g.vertices)
            assert smaller, (g, c)


def test_shrink_finds_the_smallest_graph_with_a_vertex_of_degree_three():
    def has_degree_three(g):
        degree = {}
        for u, v in g.edges:
            degree[u] = degree.get(u, 0) + 1
            degree[v] = degree.get(v, 0) + 1
        return max(degree.values(), default=0) >= 3

    g = dcel.generate("triangulation", 5, 30)
    assert has_degree_three(g)
    small = dcel.shrink(g, has_degree_three)
    assert size(small) == (3, 4) and has_degree_three(small)  # a claw: one centre, three arms
    assert all(float(c).is_integer() and abs(c) <= 2 for p in small.vertices for c in p)


def test_transforms_are_exact():
    g = dcel.generate("nested-polygons", 2, 20)
    cycles = canonical_cycles(dcel.faces(g))
    assert canonical_cycles(dcel.faces(dcel.transform(g, "rotate90"))) == cycles
    mirrored = canonical_cycles(dcel.faces(dcel.transform(g, "mirror")))
    assert mirrored == canonical_cycles([list(reversed(c)) for c in cycles])
    assert canonical_cycles(dcel.faces(dcel.transform(g, "scale-pow2", -30))) == cycles
    assert dcel.transform(g, "scale-pow2", 1100) is None  # would overflow
    assert dcel.transform(dcel.Graph([(0.5, 0)], []), "translate", 2**53) is None  # would round
    with pytest.raises(dcel.InvalidInput, match="unknown kind"):
        dcel.transform(g, "shear")


def test_planted_defects_are_refused():
    g = dcel.generate("triangulation", 1, 20)
    for defect, kinds in (("crossing", {"crossing"}), ("touch", {"vertex-on-edge"}),
                          ("overlap", {"overlap", "vertex-on-edge"})):
        bad = dcel.plant(g, defect, 3)
        assert bad is not None
        with pytest.raises(dcel.InvalidInput) as caught:
            dcel.build(bad)
        assert caught.value.kind in kinds and caught.value.edges, (defect, str(caught.value))
    assert dcel.plant(dcel.Graph([], []), "crossing", 0) is None


@settings(max_examples=300)
@given(planar_graphs(max_vertices=25))
def test_planar_graphs_are_valid_and_small(graph):
    d = dcel.build(graph)
    assert len(graph.vertices) <= 25
    assert isinstance(graph.vertices, list) and all(isinstance(p, tuple) for p in graph.vertices)
    assert d.validate() == []


@settings(max_examples=200)
@given(planar_graphs(coordinates="integers"))
def test_integer_coordinates_fit_64_bit_cross_products(graph):
    for x, y in graph.vertices:
        assert float(x).is_integer() and float(y).is_integer() and abs(x) <= 2**30 and abs(y) <= 2**30
    dcel.build(graph)


@settings(max_examples=50)
@given(st.data())
def test_families_restrict_the_generator(data):
    family = data.draw(st.sampled_from(dcel.families()))
    graph = data.draw(planar_graphs(families=[family], max_vertices=12))
    dcel.build(graph)
    if family == "star" and len(graph.edges) >= 3:
        degree = {}
        for u, v in graph.edges:
            degree[u] = degree.get(u, 0) + 1
            degree[v] = degree.get(v, 0) + 1
        assert max(degree.values()) >= 2


def test_the_strategy_refuses_bad_arguments():
    for kwargs in ({"families": ["mesh"]}, {"families": []}, {"coordinates": "floats"},
                   {"max_vertices": -1}, {"min_vertices": 5, "max_vertices": 4}):
        with pytest.raises(ValueError):
            planar_graphs(**kwargs)


def test_near_degenerate_graphs_come_up():
    seen = []

    @settings(max_examples=100)
    @given(planar_graphs())
    def collect(graph):
        seen.append(graph)

    collect()
    awkward = [g for g in seen if any(not float(c).is_integer() or abs(c) > 2**40 for p in g.vertices for c in p)]
    assert len(awkward) >= 10, len(awkward)
