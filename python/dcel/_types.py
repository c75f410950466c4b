"""The value types and exceptions of the dcel module.

Plain Python (NamedTuples and two exception classes), so that they print,
compare and pickle like any tuple; the C++ extension creates them by name.
Ids are ints; a missing id (the outer cycle of the unbounded face, a merge
that absorbed nothing) is None.
"""
from __future__ import annotations

import re
from typing import List, NamedTuple, Optional, Sequence, Tuple

# Every id in the numpy arrays is a uint32; this value means "no such element"
# (out[v] of an isolated vertex). Elsewhere a missing id is None.
NULL = 0xFFFFFFFF


class Graph(NamedTuple):
    """A planar straight-line graph: points and index pairs.

    ``vertices`` is a sequence of (x, y) and ``edges`` a sequence of (u, v)
    (lists, tuples or numpy arrays). Edge k of the input owns half-edges 2k
    (u -> v) and 2k + 1 (v -> u).
    """

    vertices: Sequence[Tuple[float, float]]
    edges: Sequence[Tuple[int, int]]

    def to_json(self) -> str:
        """The graph as `dcel faces` reads it, on one line."""
        import json

        points = [[_plain_float(x), _plain_float(y)] for x, y in self.vertices]
        pairs = [[int(u), int(v)] for u, v in self.edges]
        return json.dumps({"vertices": points, "edges": pairs})


def _plain_float(v: float) -> float | int:
    """An integral double as an int (readable JSON), -0.0 and the rest as they are."""
    v = float(v)
    if v.is_integer() and abs(v) < 2.0**53 and not (v == 0 and str(v).startswith("-")):
        return int(v)
    return v


class Face(NamedTuple):
    """One face record: its outer cycle (None for the unbounded face 0), one
    half-edge of each hole's cycle, and its isolated vertices."""

    id: int
    outer: Optional[int]
    holes: List[int]
    isolated: List[int]


class Area(NamedTuple):
    """An area whose sign is exact; value is the exact area rounded once."""

    value: float
    sign: int  # -1, 0 or 1


class Location(NamedTuple):
    """Where a point lies: kind is "face", "edge" or "vertex", id that element's id."""

    kind: str
    id: int


class StabPiece(NamedTuple):
    """One piece of what a segment or line meets: a "face" stretch, an "edge"
    crossed (along=True when the stretch runs along it) or a "vertex" passed."""

    kind: str
    id: int
    along: bool = False


class IdChange(NamedTuple):
    """What one edit did to the ids of one kind of element (see docs/editing.md)."""

    added: Optional[int] = None
    added_from: Optional[int] = None
    removed: Optional[int] = None
    merged_into: Optional[int] = None
    moved: Optional[int] = None

    def __repr__(self) -> str:
        given = ", ".join(f"{name}={value}" for name, value in zip(self._fields, self) if value is not None)
        return f"IdChange({given})"

    def renamed(self, before: int) -> Optional[int]:
        """The id after the edit of what had id ``before`` (None when it went away)."""
        if self.removed is not None and before == self.removed:
            return self.merged_into
        if self.moved is not None and before == self.moved:
            return self.removed
        return before


class Change(NamedTuple):
    """What one edit did to the ids: vertices, edges and faces."""

    vertices: IdChange
    edges: IdChange
    faces: IdChange


class Violation(NamedTuple):
    """A broken DCEL invariant, as validate() reports it."""

    invariant: str  # "references", "twin", "next-prev", ..., "hole-placement"
    message: str
    vertices: List[int]
    half_edges: List[int]
    faces: List[int]


class Difference(NamedTuple):
    """One difference between an answer and the reference (`dcel check`'s kinds)."""

    kind: str  # "wrong-next", "missing-cycle", ...
    message: str
    vertices: List[int]


class InvalidInput(ValueError):
    """The input is not a planar straight-line graph (or an edit names an id
    that does not exist, or a coordinate that is not finite).

    ``kind`` is one of "syntax", "shape", "bad-index", "bad-coordinate",
    "too-large", "duplicate-point", "self-loop", "duplicate-edge", "crossing",
    "vertex-on-edge", "overlap"; ``vertices`` and ``edges`` are the offending
    ids, as the message names them.
    """

    def __init__(self, message: str, kind: str = "shape", vertices: Sequence[int] = (), edges: Sequence[int] = ()):
        super().__init__(message)
        self.kind = kind
        self.vertices = list(vertices)
        self.edges = list(edges)


_NAMED_ID = re.compile(r"\b([vehf])(\d+)\b")


class TopologyError(ValueError):
    """An edit that would break the planar subdivision (a crossing, a point not
    on the edge, ...). The DCEL is unchanged. ``vertices``, ``edges``,
    ``half_edges`` and ``faces`` are the ids involved: the edit's own
    arguments first, then those the message names (v3, e7, h2, f1).
    """

    def __init__(self, message: str, vertices: Sequence[int] = (), edges: Sequence[int] = ()):
        super().__init__(message)
        named: dict = {"v": list(vertices), "e": list(edges), "h": [], "f": []}
        for prefix, number in _NAMED_ID.findall(message):
            if int(number) not in named[prefix]:
                named[prefix].append(int(number))
        self.vertices: List[int] = named["v"]
        self.edges: List[int] = named["e"]
        self.half_edges: List[int] = named["h"]
        self.faces: List[int] = named["f"]
