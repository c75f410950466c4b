"""Hostile Python objects: whatever a caller hands the module, the answer is
a result or a one-line InvalidInput, TypeError or ValueError naming the
place, never a crash, a hang, a RecursionError or pybind11's multi-line
"incompatible function arguments" TypeError (docs/python.md, "Hostile
objects").

The dangerous properties (a __float__ or __index__ that changes the list
being read, threads) run in a child interpreter (in_child), so that a crash
fails the test instead of killing pytest: the child runs the Hypothesis
search and exits 0, or prints the falsifying example, or dies of a signal
(faulthandler then shows where), or hangs past a timeout.
"""
import json
import math
import os
import subprocess
import sys
import textwrap
import threading
import warnings

import numpy as np
import pytest
from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st

import dcel
from dcel import _check

HERE = os.path.dirname(os.path.abspath(__file__))

# Every test here sets its own settings (the child interpreter does not load
# conftest's profile): no example database, no deadline (a shared machine).
QUICK = dict(database=None, deadline=None, suppress_health_check=list(HealthCheck))

TRIANGLE = dcel.build([(0, 0), (4, 0), (0, 3)], [(0, 1), (1, 2), (2, 0)])
SQUARE = ([(0, 0), (4, 0), (4, 4), (0, 4)], [(0, 1), (1, 2), (2, 3), (3, 0), (0, 2)])
ALLOWED = (dcel.InvalidInput, TypeError, ValueError)


def in_child(name, timeout=120):
    """Run this module's function `name` in a fresh interpreter; fail on a nonzero exit, a signal or a hang."""
    code = f"import sys; sys.path.insert(0, {HERE!r}); import test_hostile; test_hostile.{name}()"
    try:
        done = subprocess.run([sys.executable, "-X", "faulthandler", "-c", code], capture_output=True, text=True,
                              timeout=timeout, env=os.environ.copy())
    except subprocess.TimeoutExpired as e:
        pytest.fail(f"{name} hung (no end after {timeout} s); its output:\n{e.stdout}\n{e.stderr}")
    died = f"died of signal {-done.returncode}" if done.returncode < 0 else f"exit {done.returncode}"
    assert done.returncode == 0, f"{name}: {died}\n{done.stdout[-6000:]}\n{done.stderr[-6000:]}"


def outcome(call):
    """call()'s result, or the allowed exception it raised, which must say what it says on one line.
    A complex number is refused, not cast by numpy with a warning (the imaginary part dropped)."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error", np.ComplexWarning)
            result = call()
    except ALLOWED as e:
        text = str(e)
        assert text and "\n" not in text, f"{type(e).__name__} over several lines: {text!r}"
        assert "incompatible function arguments" not in text and "Invoked with" not in text, text
        return e
    if isinstance(result, dcel.Dcel):
        assert result.validate() == []
    if isinstance(result, _check.Report):
        for d in result:
            assert d.message and "\n" not in d.message, d
    return result


# ---- Lists changed while they are read (in a child interpreter).

ACTIONS = ("clear", "shrink", "extend", "replace", "reverse", "insert", "nothing")


def mutate(target, action):
    if action == "clear":
        target.clear()
    elif action == "shrink":
        del target[len(target) // 2:]
    elif action == "extend":  # reallocates the list's array
        target.extend([[9.5, 9.5]] * 64)
    elif action == "replace":  # frees every item that only the list held
        target[:] = [[float(i), -1.0] for i in range(len(target))]
    elif action == "reverse":
        target.reverse()
    elif action == "insert":
        target.insert(0, object())


class HostileNumber:
    """A number whose __float__ and __index__ first do what _act() does."""

    def __float__(self):
        self._act()
        return float(self.value)

    def __index__(self):
        self._act()
        return int(self.value)


class Mutator(HostileNumber):
    """A number whose __float__, __index__, tolist() and __repr__ first change
    the given lists (typically the ones being read), then return its value or
    raise; only while armed (so that Hypothesis can show it)."""

    armed = False

    def __init__(self, targets, action, value, raises):
        self.targets, self.action, self.value, self.raises = targets, action, value, raises

    def _act(self):
        if not Mutator.armed:
            return
        for target in self.targets:
            mutate(target, self.action)
        if self.raises:
            raise ZeroDivisionError("raised by a hostile number")

    def tolist(self):
        self._act()
        return self.value

    def __repr__(self):
        self._act()
        return "Mutator()"


class Seq:
    """A sequence that is neither a list nor a tuple (read by len() and indexing)."""

    def __init__(self, items):
        self.items = items

    def __len__(self):
        return len(self.items)

    def __getitem__(self, i):
        return self.items[i]


@st.composite
def mutating_graphs(draw):
    """(vertices, edges) of lists, with a few coordinates and indexes replaced by Mutators
    whose targets are among the lists being read (and others)."""
    n = draw(st.integers(1, 12))
    points = draw(st.lists(st.tuples(st.integers(-4, 4), st.integers(-4, 4)), min_size=n, max_size=n, unique=True))
    vertices = [[float(x), float(y)] for x, y in points]
    edges = [[u, v] for u, v in draw(st.lists(st.tuples(st.integers(0, n - 1), st.integers(0, n - 1)), max_size=12))]
    lists = [vertices, edges] + vertices + edges
    for _ in range(draw(st.integers(1, 3))):
        in_vertices = not edges or draw(st.booleans())
        pairs = vertices if in_vertices else edges
        pair = pairs[draw(st.integers(0, len(pairs) - 1))]
        c = draw(st.integers(0, 1))
        targets = [lists[i] for i in draw(st.lists(st.integers(0, len(lists) - 1), min_size=1, max_size=3))]
        pair[c] = Mutator(targets, draw(st.sampled_from(ACTIONS)), pair[c], draw(st.integers(0, 4)) == 0)
    return vertices, edges


def _first(vs):
    return vs[0] if vs else (0, 0)


MUTATED_CALLS = {
    "build": lambda vs, es: dcel.build(vs, es),
    "faces": lambda vs, es: dcel.faces(vs, es),
    "build(mapping)": lambda vs, es: dcel.build({"vertices": vs, "edges": es}),
    "build(pair)": lambda vs, es: dcel.build((vs, es)),
    "build(sequences)": lambda vs, es: dcel.build(Seq(vs), Seq(es)),
    "build(mixed)": lambda vs, es: dcel.build([np.array([-7.0, -7.0])] + vs, es),  # not all pairs are lists
    "locate_many": lambda vs, es: TRIANGLE.locate_many(vs),
    "locate": lambda vs, es: TRIANGLE.locate(_first(vs)),
    "stab": lambda vs, es: TRIANGLE.stab(_first(vs), (-1, -1)),
    "add_vertex": lambda vs, es: TRIANGLE.copy().add_vertex(_first(vs)),
    "split_edge": lambda vs, es: TRIANGLE.copy().split_edge(0, _first(vs)),
    "svg(highlight)": lambda vs, es: TRIANGLE.svg(highlight=es),
    "transform": lambda vs, es: dcel.transform((vs, es), "mirror"),
    "plant": lambda vs, es: dcel.plant((vs, es), "crossing"),
    "shrink_candidates": lambda vs, es: dcel.shrink_candidates((vs, es)),
    "check(answer)": lambda vs, es: dcel.check(TRIANGLE, es),
    "check(graph)": lambda vs, es: dcel.check((vs, es), []),
    "check(dump)": lambda vs, es: dcel.check(TRIANGLE, {"vertices": vs, "origin": sum(es, []), "twin": [],
                                                         "next": [], "prev": [], "face": [], "faces": []}),
    "validate": lambda vs, es: dcel.validate({"vertices": vs, "half_edges": [], "faces": []}),
}


@settings(max_examples=1000, **QUICK)
@given(mutating_graphs(), st.sampled_from(sorted(MUTATED_CALLS)))
def child_lists_changed_while_read(graph, call):
    vertices, edges = graph
    Mutator.armed = True
    try:
        outcome(lambda: MUTATED_CALLS[call](vertices, edges))
    finally:
        Mutator.armed = False


class Editor(HostileNumber):
    """A number whose __float__ and __index__ edit the given Dcel (the one being called) first."""

    armed = False

    def __init__(self, d, edits, value):
        self.d, self.edits, self.value = d, edits, value

    def _act(self):
        if not Editor.armed:
            return
        for edit in self.edits:
            try:
                if edit == "remove_edge" and self.d.num_edges > 0:
                    self.d.remove_edge(self.d.num_edges - 1)
                elif edit == "add_vertex":
                    self.d.add_vertex((100.0 + self.d.num_vertices, -50.0))
                elif edit == "remove_vertex" and self.d.num_vertices > 0:
                    self.d.remove_isolated_vertex(self.d.num_vertices - 1)
                elif edit == "view":  # a view holds the state: the next edit copies it
                    self.view = self.d.origin
                elif edit == "drop_view":
                    self.view = None
            except ValueError:
                pass


EDITOR_EDITS = ("remove_edge", "add_vertex", "remove_vertex", "view", "drop_view")
EDITED_CALLS = {
    "cycle": lambda d, i, p: d.cycle(i),
    "around": lambda d, i, p: d.around(i),
    "face_area": lambda d, i, p: d.face_area(i),
    "neighbours": lambda d, i, p: d.neighbours(i),
    "split_edge": lambda d, i, p: d.split_edge(i, p),
    "add_edge": lambda d, i, p: d.add_edge(i, i),
    "add_edge_to_point": lambda d, i, p: d.add_edge_to_point(i, p),
    "remove_edge": lambda d, i, p: d.remove_edge(i),
    "remove_isolated_vertex": lambda d, i, p: d.remove_isolated_vertex(i),
    "merge_collinear_edges": lambda d, i, p: d.merge_collinear_edges(i),
    "locate": lambda d, i, p: d.locate(p),
    "locate_many": lambda d, i, p: d.locate_many([p, p]),
    "stab": lambda d, i, p: d.stab(p, (0.5, 0.5)),
    "svg": lambda d, i, p: d.svg(highlight=[[i, i]]),
}


@settings(max_examples=500, **QUICK)
@given(st.sampled_from(sorted(EDITED_CALLS)), st.integers(0, 12),
       st.lists(st.sampled_from(EDITOR_EDITS), min_size=1, max_size=4),
       st.lists(st.sampled_from(EDITOR_EDITS), min_size=1, max_size=4), st.integers(0, 3))
def child_arguments_edit_the_dcel(call, index, index_edits, point_edits, y):
    d = dcel.build(*SQUARE)
    d.split_edge(0, (2, 0))  # a vertex to merge back
    i = Editor(d, index_edits, index)
    p = (Editor(d, point_edits, 2), Editor(d, (), y * 0.5))
    Editor.armed = True
    try:
        outcome(lambda: EDITED_CALLS[call](d, i, p))
    finally:
        Editor.armed = False
    assert d.validate() == []


def test_arguments_edit_the_dcel():
    """An id's __index__ or a coordinate's __float__ that edits the very Dcel being called (before: an id
    checked against the DCEL before a point's __float__ removed that edge reached the library)."""
    in_child("child_arguments_edit_the_dcel")


def test_lists_changed_while_read():
    """A __float__ or __index__ (or tolist, or __repr__) that clears, shrinks, extends or refills the lists
    being read: never a crash (before: SIGSEGV in build, faces, locate_many, locate, and in numpy's own
    reading of a list)."""
    in_child("child_lists_changed_while_read")


# ---- Junk of every kind, at every public entry (in a child interpreter).

ERRORS = (ZeroDivisionError, KeyError, IndexError, RuntimeError, RecursionError, TypeError, ValueError,
          OverflowError, StopIteration, AttributeError, MemoryError)


class Raises:
    """Every protocol raises."""

    def __init__(self, error):
        self.error = error

    def _raise(self, *args, **kwargs):
        raise self.error("hostile")

    __float__ = __index__ = __int__ = __len__ = __iter__ = __getitem__ = __contains__ = _raise
    __repr__ = __str__ = __bool__ = __eq__ = tolist = keys = items = _raise
    __hash__ = object.__hash__


class BadClass:
    """isinstance() asks __class__, which raises."""

    @property
    def __class__(self):
        raise RuntimeError("hostile __class__")


class Lying:
    """len() says claimed; indexing past the real items raises IndexError."""

    def __init__(self, items, claimed):
        self.items, self.claimed = items, claimed

    def __len__(self):
        return self.claimed

    def __getitem__(self, i):
        if 0 <= i < len(self.items):
            return self.items[i]
        raise IndexError(i)


class HostileDict(dict):
    """A dict whose methods raise or lie."""

    def __init__(self, items, error):
        super().__init__(items)
        self.error = error

    def __getitem__(self, key):
        raise self.error("hostile __getitem__")

    def keys(self):
        raise self.error("hostile keys")

    def items(self):
        return [("vertices", self.error), (object(), 1)]

    def __contains__(self, key):
        return True


class StrEq(str):
    """A str whose comparisons raise."""

    def __eq__(self, other):
        raise RuntimeError("hostile __eq__")

    __hash__ = str.__hash__


def nest(depth, make):
    value = []
    for _ in range(depth):
        value = make(value)
    return value


SURROGATE = st.integers(0xD800, 0xDFFF).map(chr)
ARRAYS = [
    np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])[:, ::-1],  # not contiguous
    np.asfortranarray([[0, 1], [1, 2]]),
    np.arange(12.0).reshape(2, 3, 2),
    np.zeros((0, 3)),
    np.array(3.5),
    np.array([[True, False]]),
    np.array([[1 + 2j, 3]]),
    np.array([["a", "b"]]),
    np.array([[0, 1]], dtype=">i8"),
    np.array([[0.5, 1]], dtype=np.float16),
    np.array(["2020-01-01", "2021-01-01"], dtype="datetime64[D]").reshape(1, 2),
    np.zeros(2, dtype=[("x", "f8"), ("y", "f8")]),
    np.array([[0, 2**40]], dtype=np.uint64),
    np.array([[np.nan, np.inf]]),
]


# The junk is drawn as a description (plain tuples, which Hypothesis can show
# and shrink) and made by materialize() in the test: Hypothesis itself calls
# repr() and == on what it draws, which the hostile objects refuse.
LEAF = st.one_of(
    st.tuples(st.just("value"), st.none() | st.booleans() | st.integers(-(2**300), 2**300) | st.floats()
              | st.sampled_from([2**32 - 1, 2**32, 2**63, -(2**63) - 1, 2**64, -1]) | st.text(max_size=4)
              | st.binary(max_size=4)),
    st.tuples(st.just("surrogate"), st.text(max_size=3), SURROGATE),
    st.tuples(st.just("power of ten"), st.sampled_from([400, 5000])),  # 10**5000: repr() refuses it
    st.tuples(st.just("bytearray"), st.binary(max_size=4)),
    st.tuples(st.just("raises"), st.sampled_from(ERRORS)),
    st.tuples(st.just("bad __class__")),
    st.tuples(st.just("array"), st.integers(0, len(ARRAYS) - 1)),
    st.tuples(st.just("nested"), st.integers(257, 3000), st.sampled_from(["list", "faces"])),
    st.tuples(st.just("iterator")),
    st.tuples(st.just("str with hostile __eq__")),
)
KEYS = st.sampled_from(["vertices", "edges", "faces", "type", "coordinates", "half_edges", "origin", "polygons",
                        "rings"])


def _containers(inner):
    return st.one_of(
        st.tuples(st.just("list"), st.lists(inner, max_size=4)),
        st.tuples(st.just("tuple"), st.lists(inner, min_size=2, max_size=2)),
        st.tuples(st.just("dict"), st.lists(st.tuples(KEYS, inner), max_size=3)),
        st.tuples(st.just("hostile dict"), st.lists(st.tuples(st.sampled_from(["vertices", "edges"]), inner),
                                                    max_size=2), st.sampled_from(ERRORS)),
        st.tuples(st.just("lying len"), st.lists(inner, max_size=3), st.sampled_from([0, 2, 5, 10**6, -1, 2**70])),
        st.tuples(st.just("sequence"), st.lists(inner, max_size=3)),
        st.tuples(st.just("object array"), st.lists(inner, min_size=1, max_size=6), st.booleans()),
    )


JUNK = st.recursive(LEAF, _containers, max_leaves=8)


def materialize(description):
    """The object a JUNK description describes."""
    kind, *args = description
    if kind == "value":
        return args[0]
    if kind == "surrogate":
        return args[0] + args[1]
    if kind == "power of ten":
        return 10 ** args[0]
    if kind == "bytearray":
        return bytearray(args[0])
    if kind == "raises":
        return Raises(args[0])
    if kind == "bad __class__":
        return BadClass()
    if kind == "array":
        return ARRAYS[args[0]]
    if kind == "nested":
        return nest(args[0], (lambda v: [v]) if args[1] == "list" else (lambda v: {"faces": v}))
    if kind == "iterator":
        return iter([(0, 0), (1, 0)])
    if kind == "str with hostile __eq__":
        return StrEq("faces")
    if kind == "list":
        return [materialize(d) for d in args[0]]
    if kind == "tuple":
        return tuple(materialize(d) for d in args[0])
    if kind == "dict":
        return {k: materialize(d) for k, d in args[0]}
    if kind == "hostile dict":
        return HostileDict({k: materialize(d) for k, d in args[0]}, args[1])
    if kind == "lying len":
        return Lying([materialize(d) for d in args[0]], args[1])
    if kind == "sequence":
        return Seq([materialize(d) for d in args[0]])
    if kind == "object array":
        items = [materialize(d) for d in args[0]]
        a = np.empty(len(items), dtype=object)
        for i, x in enumerate(items):
            a[i] = x
        return a.reshape(-1, 2) if args[1] and len(items) % 2 == 0 else a
    raise AssertionError(kind)


def _edited(method, *args, **kwargs):
    return getattr(TRIANGLE.copy(), method)(*args, **kwargs)


ENTRIES = {
    "build(x)": lambda x, y: dcel.build(x),
    "build(x, y)": lambda x, y: dcel.build(x, y),
    "build(check_crossings=x)": lambda x, y: dcel.build(*SQUARE, check_crossings=x),
    "faces(x, y)": lambda x, y: dcel.faces(x, y),
    "locate_many(x)": lambda x, y: TRIANGLE.locate_many(x),
    "locate(x)": lambda x, y: TRIANGLE.locate(x),
    "stab(x, y)": lambda x, y: TRIANGLE.stab(x, y),
    "stab(line=x)": lambda x, y: TRIANGLE.stab((0, 0), (1, 1), line=x),
    "cycle(x)": lambda x, y: TRIANGLE.cycle(x),
    "cycle_vertices(x)": lambda x, y: TRIANGLE.cycle_vertices(x),
    "around(x)": lambda x, y: TRIANGLE.around(x),
    "face_area(x)": lambda x, y: TRIANGLE.face_area(x),
    "cycle_area(x)": lambda x, y: TRIANGLE.cycle_area(x),
    "neighbours(x)": lambda x, y: TRIANGLE.neighbours(x),
    "faces_around(x)": lambda x, y: TRIANGLE.faces_around(x),
    "split_edge(x, y)": lambda x, y: _edited("split_edge", x, y),
    "add_edge(x, y)": lambda x, y: _edited("add_edge", x, y),
    "add_edge_to_point(x, y)": lambda x, y: _edited("add_edge_to_point", x, y),
    "add_vertex(x)": lambda x, y: _edited("add_vertex", x),
    "remove_edge(x)": lambda x, y: _edited("remove_edge", x),
    "remove_isolated_vertex(x)": lambda x, y: _edited("remove_isolated_vertex", x),
    "merge_collinear_edges(x)": lambda x, y: _edited("merge_collinear_edges", x),
    "to_json(compact=x)": lambda x, y: TRIANGLE.to_json(compact=x),
    "svg(title=x, highlight=y)": lambda x, y: TRIANGLE.svg(title=x, highlight=y),
    "read_graph(x)": lambda x, y: dcel.read_graph(x),
    "check(d, x)": lambda x, y: dcel.check(TRIANGLE, x),
    "check(d, x, faces)": lambda x, y: dcel.check(TRIANGLE, x, "faces"),
    "check(d, x, dump)": lambda x, y: dcel.check(TRIANGLE, x, "dump"),
    "check(d, x, polygons)": lambda x, y: dcel.check(TRIANGLE, x, "polygons"),
    "check(d, x, rings)": lambda x, y: dcel.check(TRIANGLE, x, "rings"),
    "check(x, y)": lambda x, y: dcel.check(x, y),
    "check(kind=x)": lambda x, y: dcel.check(TRIANGLE, [], kind=x),
    "check(face_on_right=x)": lambda x, y: dcel.check(TRIANGLE, [], face_on_right=x),
    "validate(x)": lambda x, y: dcel.validate(x),
    "answer_text(x)": lambda x, y: dcel.answer_text(x),
    "generate(x, y)": lambda x, y: dcel.generate(x, y),
    "generate(tree, x, y)": lambda x, y: dcel.generate("tree", x, y),
    "transform(x, mirror)": lambda x, y: dcel.transform(x, "mirror"),
    "transform(g, x, y)": lambda x, y: dcel.transform(SQUARE, x, y),
    "plant(x, crossing)": lambda x, y: dcel.plant(x, "crossing"),
    "plant(g, x, y)": lambda x, y: dcel.plant(SQUARE, x, y),
    "shrink_candidates(x)": lambda x, y: dcel.shrink_candidates(x),
    "shrink(x)": lambda x, y: dcel.shrink(x, lambda g: False),
    "shrink(g, x, y)": lambda x, y: dcel.shrink(SQUARE, x, y),
}


@settings(max_examples=3000, **QUICK)
@given(st.sampled_from(sorted(ENTRIES)), JUNK, JUNK)
def child_junk_at_every_entry(entry, x, y):
    x, y = materialize(x), materialize(y)
    outcome(lambda: ENTRIES[entry](x, y))


def test_junk_at_every_entry():
    """Huge ints, NaN, raising or lying protocols, bytes, surrogates, hostile dicts, object and odd numpy
    arrays, deep nesting, at every public function and method (before: multi-line pybind11 TypeErrors for
    ids, counts and strings; KeyError, RuntimeError, ZeroDivisionError and RecursionError passed through)."""
    in_child("child_junk_at_every_entry")


@settings(max_examples=200, **QUICK)
@given(JUNK, JUNK)
def test_assert_same_faces_fails_only_by_assertion(graph, answer):
    from dcel.hypothesis import assert_same_faces

    graph, answer = materialize(graph), materialize(answer)
    try:
        assert_same_faces(TRIANGLE if graph is None else graph, answer)
    except AssertionError:
        pass  # what it is for: its message is many lines by design
    except ALLOWED as e:
        assert "\n" not in str(e)


@settings(max_examples=100, **QUICK)
@given(JUNK, JUNK, JUNK)
def test_planar_graphs_refuses_junk_arguments_cleanly(families, max_vertices, coordinates):
    from dcel.hypothesis import planar_graphs

    families, max_vertices, coordinates = map(materialize, (families, max_vertices, coordinates))
    outcome(lambda: planar_graphs(families=families, max_vertices=max_vertices, coordinates=coordinates))


INVALID_GRAPHS = [
    ([(0, 0)], [(0, 5)]),  # an index past the points
    ([(0, 0), (1, 1)], [(0, 1000000)]),
    ([(0, 0), (0, 0), (1, 1)], [(0, 2), (1, 2)]),  # a duplicate point
    ([(0, 0), (2, 2), (0, 2), (2, 0)], [(0, 1), (2, 3)]),  # a crossing
    ([(0, 0), (1, 1)], [(0, 0)]),  # a self-loop
    ([(0, 0), (math.nan, 1)], []),
]


def child_generators_refuse_invalid_graphs():
    for graph in INVALID_GRAPHS:
        for call in (lambda: dcel.shrink_candidates(graph), lambda: dcel.plant(graph, "crossing"),
                     lambda: dcel.shrink(graph, lambda g: False), lambda: dcel.shrink(graph, lambda g: True)):
            e = outcome(call)
            assert isinstance(e, dcel.InvalidInput), (graph, e)


def test_generators_refuse_invalid_graphs():
    """plant, shrink_candidates and shrink take their graph as valid: an invalid one is refused as build()
    refuses it (before: read out of bounds; SIGSEGV in shrink_candidates and plant on an index past the
    points, found by test_junk_at_every_entry)."""
    in_child("child_generators_refuse_invalid_graphs")


# ---- Deep nesting (in process: nothing here can crash, only recurse).

CONTAINERS = {
    "list": lambda v: [v],
    "tuple": lambda v: (v,),
    "dict": lambda v: {"a": v},
}


@settings(max_examples=30, **QUICK)
@given(st.integers(257, 100_000), st.sampled_from(sorted(CONTAINERS)), st.sampled_from([None, *dcel.KINDS]))
def test_any_depth_is_an_unreadable_answer(depth, container, kind):
    """check() of an answer nested deeper than the JSON reader reads (256 levels) is one unreadable-answer
    difference, validate() refuses it in one line, answer_text() writes it all (before: RecursionError)."""
    answer = nest(depth, CONTAINERS[container])
    report = dcel.check(TRIANGLE, answer, kind)
    assert [d.kind for d in report] == ["unreadable-answer"] and "\n" not in report[0].message
    with pytest.raises(dcel.InvalidInput):
        dcel.validate(answer)
    text = dcel.answer_text(answer)
    assert text.count("[" if container != "dict" else "{") == depth + (container != "dict")


# json.dumps's text of nest(n, CONTAINERS[...]), which json.dumps itself cannot write.
DEEP_TEXT = {
    "list": lambda n: "[" * (n + 1) + "]" * (n + 1),
    "dict": lambda n: '{"a": ' * n + "[]" + "}" * n,
}


@pytest.mark.parametrize("kind", [None, *dcel.KINDS])
@pytest.mark.parametrize("container", sorted(DEEP_TEXT))
def test_the_deep_answer_s_message_is_the_cli_s(container, kind, tmp_path):
    """The message is the one `dcel check` gives for the same document in a file."""
    from conftest import run_cli

    if (container, kind) == ("list", "dump"):
        pytest.skip("a list is no dump: check() says so before any JSON is written")
    depth = 100_000
    answer = nest(depth, CONTAINERS[container])
    text = DEEP_TEXT[container](depth)
    if kind is not None and container == "list":  # a bare list goes under its kind's key; a mapping as it is
        text = json.dumps({kind: None})[:-5] + text + "}"
    graph, path = tmp_path / "graph.json", tmp_path / "answer.json"
    graph.write_text(dcel.Graph(*TRIANGLE.graph()).to_json())
    path.write_text(text)
    report = dcel.check(TRIANGLE, answer, kind)
    expected = report.text.replace("unreadable-answer: answer: ", f"unreadable-answer: ANSWER {path}: ", 1)
    args = ["check", str(graph), str(path)] + (["--answer", kind] if kind else [])
    assert run_cli(*args, expect=(1,)) == expected


DOCUMENTS = st.recursive(
    st.none() | st.booleans() | st.integers(-(2**70), 2**70) | st.floats() | st.text(max_size=5)
    | st.sampled_from([np.int64(3), np.float32(0.5), np.array([[1, 2]]), np.bool_(True)]),
    lambda inner: st.lists(inner, max_size=4) | st.tuples(inner)
    | st.dictionaries(st.text(max_size=3) | st.integers() | st.floats() | st.booleans() | st.none(), inner,
                      max_size=3),
    max_leaves=20,
)


@settings(max_examples=300, **QUICK)
@given(DOCUMENTS)
def test_the_iterative_writer_writes_what_json_dumps_writes(document):
    """_json_cut, which writes documents too deep for json.dumps, writes the same text as json.dumps."""
    assert _check._json_cut(document) == json.dumps(document, default=_check._plain, allow_nan=True)


@settings(max_examples=20, **QUICK)
@given(st.integers(257, 600), DOCUMENTS)
def test_a_cut_text_is_the_start_of_the_whole_one(depth, leaf):
    """Past 256 levels _json_cut stops at the first bracket too deep, after what json.dumps writes first."""
    document = nest(depth, lambda v: [leaf, v])
    cut = _check._json_cut(document)
    whole = json.dumps(document, default=_check._plain, allow_nan=True)
    assert whole.startswith(cut) and cut.endswith(("[", "{")) and open_brackets(cut) == 257
    assert _check._json_cut(document, None) == whole


def open_brackets(text):
    """How many brackets are open at the end of a JSON text (brackets in strings do not count)."""
    depth, in_string, escaped = 0, False, False
    for c in text:
        if in_string:
            in_string = escaped or c != '"'
            escaped = not escaped and c == "\\"
        elif c == '"':
            in_string = True
        elif c in "[{":
            depth += 1
        elif c in "]}":
            depth -= 1
    return depth


# ---- Lone surrogates (in process).

@st.composite
def with_surrogate(draw, alphabet=st.characters(blacklist_categories=("Cs",))):
    """(text with one lone surrogate, its line, its column)."""
    before = draw(st.text(alphabet, max_size=12))
    after = draw(st.text(alphabet, max_size=5))
    line = before.count("\n") + 1
    column = len(before) - (before.rfind("\n") + 1) + 1
    return before + draw(SURROGATE) + after, line, column


@settings(max_examples=150, **QUICK)
@given(with_surrogate())
def test_a_lone_surrogate_is_named_with_its_place(text_at):
    """A str no UTF-8 can encode: one-line InvalidInput naming line and column, or an unreadable-answer
    difference (before: pybind11's multi-line TypeError naming the internal _check_text)."""
    text, line, column = text_at
    where = f"line {line}, column {column}: lone surrogate"
    for call in (lambda: dcel.read_graph(text), lambda: dcel.validate(text)):
        e = outcome(call)
        assert isinstance(e, dcel.InvalidInput) and where in str(e), e
    report = dcel.check(TRIANGLE, text)
    assert [d.kind for d in report] == ["unreadable-answer"] and where in report[0].message
    for call in (lambda: dcel.generate(text, 1), lambda: dcel.transform(SQUARE, text),
                 lambda: dcel.plant(SQUARE, text), lambda: TRIANGLE.svg(title=text)):
        e = outcome(call)
        assert isinstance(e, dcel.InvalidInput) and "lone surrogate" in str(e), e


@settings(max_examples=100, **QUICK)
@given(with_surrogate(), st.sampled_from(["type", "key", "value", "names"]), st.booleans())
def test_a_lone_surrogate_inside_an_answer(text_at, where, as_text):
    """Inside an answer (a GeoJSON type, a key, a value, a names dict): in a Python answer it is written as
    the \\ud800 escape, which the JSON reader refuses; in an answer given as JSON text (a str) it is a lone
    surrogate the text cannot be encoded with. Either way the report says where (before: the text gave
    pybind11's multi-line TypeError naming _check_text)."""
    text = text_at[0]
    answer = {
        "type": {"type": text, "coordinates": []},
        "key": {text: [[0, 1, 2]]},
        "value": [[0, 1, text]],
        "names": {"faces": [[0, 1, 2], [1, 0, 2]], "names": {"0": text}},
    }[where]
    if as_text:
        answer = json.dumps(answer, ensure_ascii=False)  # the surrogate itself, not its escape
        before = answer[:next(i for i, c in enumerate(answer) if 0xD800 <= ord(c) <= 0xDFFF)]
        place = f"line {before.count(chr(10)) + 1}, column {len(before) - before.rfind(chr(10))}: lone surrogate"
    else:
        place = "unpaired surrogate"
    report = dcel.check(TRIANGLE, answer)
    assert not report.agrees and all("\n" not in d.message for d in report)
    if as_text or where != "names":  # a member the reader skips is still read, as far as its reading says
        assert report[0].kind == "unreadable-answer" and place in report[0].message, report[0]
    with pytest.raises(ValueError, match="unknown kind") as caught:
        dcel.check(TRIANGLE, [], kind=text)
    assert "\n" not in str(caught.value)


# ---- Threads.

FIRST_CALLS = {
    "points": "d.points",
    "origin": "d.origin",
    "twin": "d.twin",
    "faces": "d.faces",
    "graph": "d.graph()",
    "locate": "d.locate((1, 1))",
    "locate_many": "d.locate_many(__import__('numpy').array([[1.0, 1.0]]))",
    "build(arrays)": "dcel.build(__import__('numpy').zeros((1, 2)), __import__('numpy').zeros((0, 2)))",
    "to_dump": "d.to_dump()",
    "check": "dcel.check(d, d.boundary_cycles())",
    "validate": "dcel.validate(d.to_dump())",
    "generate": "dcel.generate('tree', 1)",
    "error": "dcel.build([(0, 0)], [(0, 5)])",
}


@settings(max_examples=6, phases=(Phase.generate,), **QUICK)
@given(st.lists(st.sampled_from(sorted(FIRST_CALLS)), min_size=2, max_size=8))
def test_first_calls_from_many_threads_at_once(calls):
    """Threads making their first calls at once in a fresh interpreter all finish (before: a deadlock,
    pybind11's lazy numpy initialisation waited for with the GIL held; 20 of 20 runs hung)."""
    code = textwrap.dedent(f"""
        import threading, dcel
        d = dcel.build([(0, 0), (4, 0), (0, 3)], [(0, 1), (1, 2), (2, 0)])
        barrier = threading.Barrier({len(calls)})
        def first(call):
            barrier.wait()
            try:
                eval(call)
            except ValueError:
                pass
        threads = [threading.Thread(target=first, args=(c,)) for c in {[FIRST_CALLS[c] for c in calls]!r}]
        for t in threads: t.start()
        for t in threads: t.join()
        print("done")
    """)
    try:
        done = subprocess.run([sys.executable, "-X", "faulthandler", "-c", code], capture_output=True, text=True,
                              timeout=30, env=os.environ.copy())
    except subprocess.TimeoutExpired:
        pytest.fail(f"first calls {calls} from {len(calls)} threads at once: deadlocked")
    assert done.returncode == 0 and done.stdout == "done\n", done.stderr


EDITS = {
    "add_vertex": lambda d, i: d.add_vertex((1e6 + i, -1e6 - i)),
    "split_edge": lambda d, i: d.split_edge(0, tuple(0.5 * (d.points[d.origin[0]] + d.points[d.origin[1]]))),
    "remove_edge": lambda d, i: d.remove_edge(d.num_edges - 1) if d.num_edges > 3 else None,
    "copy": lambda d, i: d.copy(),
}
READS = {  # the calls that release the GIL while they use the Dcel
    "locate_many": lambda d, points: d.locate_many(points),
    "check": lambda d, points: dcel.check(d, [[0, 1, 2]]),
}


@settings(max_examples=8, phases=(Phase.generate,), **QUICK)
@given(st.lists(st.sampled_from(sorted(EDITS)), min_size=1, max_size=3), st.sampled_from(sorted(READS)),
       st.integers(0, 2**32))
def child_edits_while_calls_run_unlocked(edits, read, seed):
    d = dcel.build(dcel.generate("triangulation", seed, 400))
    rng = np.random.default_rng(seed)
    points = rng.uniform(-10, 1010, size=(20000, 2))
    stop = threading.Event()

    def edit():
        i = 0
        while not stop.is_set():
            for name in edits:
                try:
                    EDITS[name](d, i)
                    d.locate((1.0, 2.0))  # a new point locator after each edit
                except ValueError:
                    pass
                i += 1

    editor = threading.Thread(target=edit)
    editor.start()
    try:
        for _ in range(3):
            outcome(lambda: READS[read](d, points))
    finally:
        stop.set()
        editor.join()
    assert d.validate() == []


def test_edits_while_calls_run_unlocked():
    """An edit in one thread while another's call runs with the GIL released on the same Dcel (before:
    SIGSEGV, the point locator freed under locate_many; check() read a DCEL being edited)."""
    in_child("child_edits_while_calls_run_unlocked")


def test_huge_and_non_finite_numbers_are_named():
    """The examples of docs/python.md's "Hostile objects", exactly."""
    for call, words in [
        (lambda: dcel.build([(0, 0), (1, 1)], [(0, 2**200)]), "edges[0][1]: vertex index an int of 201 bits is too large"),
        (lambda: dcel.build([(2**2000, 0)], []), "vertices[0][0]: expected a number, found an int of 2001 bits"),
        (lambda: TRIANGLE.cycle(2**200), "cycle: half-edge an int of 201 bits does not exist"),
        (lambda: TRIANGLE.locate_many([(0, 0), (math.nan, 1)]), "locate_many: points[1]: coordinates must be finite"),
        (lambda: dcel.build([(0, 0), (Raises(ZeroDivisionError), 1)], []),
         "vertices[1][0]: expected a number, found <Raises instance at "),
        (lambda: dcel.build([(0, 0), (Raises(ZeroDivisionError), 1)], []), "> (ZeroDivisionError: hostile)"),
    ]:
        e = outcome(call)
        assert isinstance(e, dcel.InvalidInput) and words in str(e), (words, e)
