"""check() and validate(): Python answers in, structured differences out.

An answer is turned into the JSON document `dcel check` reads
(docs/formats.md) and read by the library's own reader, so that a Python
answer and the same answer in a file are judged alike, down to the message
for a malformed one.
"""
from __future__ import annotations

import json
import math
from collections.abc import Mapping
from typing import Any, Iterator, List, Optional, Sequence, Union, overload

from . import _dcel
from ._types import NULL, Difference, Violation

# The answer kinds check() knows (docs/checking.md, "Answer kinds"); with no
# kind, the library detects it from the answer's shape.
KINDS = ("faces", "dump", "polygons", "rings")


class Report(Sequence[Difference]):
    """The differences between an answer and the reference, most telling first.

    A sequence of Difference(kind, message, vertices); ``agrees`` is True when
    there is none. ``unlisted`` counts differences beyond the cap of 100 per
    kind; ``kind`` is the answer kind it was read as; ``notes`` say what was
    assumed (a detected kind, rings read as closed) and which convention
    would make a disagreeing answer agree; ``text`` is what `dcel check`
    prints, notes included.
    """

    def __init__(self, differences: List[Difference], unlisted: int, text: str, kind: str,
                 notes: Optional[List[str]] = None):
        self._differences = differences
        self.unlisted = unlisted
        self.text = text
        self.kind = kind
        self.notes = list(notes or [])

    @property
    def agrees(self) -> bool:
        return not self._differences and self.unlisted == 0

    @overload
    def __getitem__(self, i: int) -> Difference: ...
    @overload
    def __getitem__(self, i: slice) -> List[Difference]: ...
    def __getitem__(self, i):  # type: ignore[no-untyped-def]
        return self._differences[i]

    def __len__(self) -> int:
        return len(self._differences)

    def __iter__(self) -> Iterator[Difference]:
        return iter(self._differences)

    def __repr__(self) -> str:
        if self.agrees:
            return "<dcel.Report: agrees>"
        count = len(self) + self.unlisted
        return f"<dcel.Report: {count} difference{'s' if count != 1 else ''}, first: {self._differences[0]!r}>"


def _plain(value: Any) -> Any:
    """numpy arrays and scalars as lists and numbers; NaN stays NaN (and is refused)."""
    tolist = getattr(value, "tolist", None)
    if tolist is not None:
        return tolist()
    raise TypeError(f"{type(value).__name__} is not a number or a list")


def _null(v: Any) -> Any:
    """None, -1 and NULL all mean "no id"."""
    if v is None:
        return None
    try:
        i = int(v)
    except (TypeError, ValueError, OverflowError):
        return v  # left for the reader to refuse, with its place
    return None if i in (-1, NULL) and i == v else v


def _ids(values: Any) -> Any:
    values = _plain(values) if hasattr(values, "tolist") else values
    return [_null(v) for v in values]


def _columnar_dump(answer: Mapping[str, Any]) -> dict:
    """{"vertices", "origin", "twin", "next", "prev", "face", "faces"[, "out"]}
    (one array per field, as numpy code keeps a DCEL) to the record form."""
    columns = [_ids(answer[k]) for k in ("origin", "twin", "next", "prev", "face")]
    lengths = {len(c) for c in columns}
    if len(lengths) != 1:
        raise ValueError("origin, twin, next, prev and face must have one entry per half-edge each")
    half_edges = [dict(zip(("origin", "twin", "next", "prev", "face"), row)) for row in zip(*columns)]
    dump = {"vertices": answer["vertices"], "half_edges": half_edges, "faces": answer["faces"]}
    if answer.get("out") is not None:
        dump["vertex_out"] = _ids(answer["out"])
    return dump


def _face_records(faces: Any) -> list:
    out = []
    for f in faces:
        if isinstance(f, Mapping):
            f = dict(f)
            if "holes" in f and "inner" not in f:
                f["inner"] = f.pop("holes")
            f["outer"] = _null(f.get("outer"))
            out.append(f)
        elif hasattr(f, "outer") and hasattr(f, "holes"):  # a dcel.Face, or an object like it
            out.append({"outer": _null(f.outer), "inner": list(f.holes), "isolated": list(getattr(f, "isolated", []))})
        else:
            out.append(f)  # refused by the reader, with its place
    return out


def _dump_document(answer: Any) -> dict:
    if isinstance(answer, _dcel.Dcel):
        return answer.to_dump()
    if not isinstance(answer, Mapping):
        raise ValueError("a dump is a mapping: {\"vertices\", \"half_edges\", \"faces\"} or {\"vertices\", "
                         "\"origin\", \"twin\", \"next\", \"prev\", \"face\", \"faces\"}")
    dump = _columnar_dump(answer) if "origin" in answer and "half_edges" not in answer else dict(answer)
    if "faces" in dump:
        dump["faces"] = _face_records(dump["faces"])
    if "half_edges" in dump:
        dump["half_edges"] = [
            {k: _null(v) for k, v in dict(h).items()} if isinstance(h, Mapping) else h for h in dump["half_edges"]
        ]
    if dump.get("vertex_out") is not None:
        dump["vertex_out"] = _ids(dump["vertex_out"])
    return dump


def _is_dump(answer: Any) -> bool:
    return isinstance(answer, _dcel.Dcel) or (
        isinstance(answer, Mapping) and ("half_edges" in answer or "origin" in answer)
    )


def _document(answer: Any, kind: Optional[str]) -> Any:
    """The JSON value `dcel check` would read: a dump as a whole DCEL; a
    mapping (or GeoJSON, or an object with __geo_interface__ such as a
    shapely geometry) as it is; a bare list under the kind's key when the
    kind is given, else as it is (its shape tells the kind)."""
    if kind == "dump" or (kind is None and _is_dump(answer)):
        return _dump_document(answer)
    geo = getattr(answer, "__geo_interface__", None)
    if geo is not None:
        return geo
    if isinstance(answer, Mapping):
        return dict(answer)
    if kind is not None:
        return {kind: answer}
    return answer


def answer_text(answer: Any, kind: Optional[str] = None) -> str:
    """The JSON document `dcel check` would read for this answer."""
    if isinstance(answer, (str, bytes)):
        return answer.decode() if isinstance(answer, bytes) else answer
    return json.dumps(_document(answer, kind), default=_plain, allow_nan=True)


def _reference(graph: Any) -> "_dcel.Dcel":
    return graph if isinstance(graph, _dcel.Dcel) else _dcel.build(graph)


def check(graph: Any, answer: Any, kind: Optional[str] = None, *, face_on_right: bool = False,
          one_based: bool = False, unoriented: bool = False) -> Report:
    """Compare another implementation's answer for ``graph`` with the reference.

    graph: a Graph, a pair (vertices, edges), a mapping with "vertices" and
    "edges", or a Dcel (taken as the reference). answer, by kind
    (docs/checking.md, "Answer kinds", says what each is compared with):

    - "faces": every boundary cycle as vertex ids in next order, a list of
      lists (or {"faces": [...]}); cycle order and rotation do not matter,
      direction does.
    - "dump": a whole DCEL, {"vertices", "half_edges": [{"origin", "twin",
      "next", "prev", "face"}, ...], "faces": [{"outer", "inner",
      "isolated"}, ...]} (the `dcel build` format), or the same as columns
      {"vertices", "origin", "twin", "next", "prev", "face", "faces"[,
      "out"]}; a missing id is None, -1 or NULL. Validated, then compared up
      to the numbering of half-edges and faces.
    - "polygons": the bounded faces, each [shell, hole, ...] of rings (vertex
      ids or coordinates), or {"polygons": [...]}, GeoJSON, or a shapely
      geometry (anything with __geo_interface__).
    - "rings": one ring per bounded face, holes filled, or {"rings": [...]}.
    - None (the default): detected from the shape, as `dcel check` does (a
      note says so); a mapping with "half_edges" or "origin" is a dump. A
      str is taken as the JSON text of the answer.

    face_on_right, one_based, unoriented: the conventions of `dcel check
    --face-on right --one-based --unoriented`.

    Returns a Report (a sequence of Difference, empty when the answer agrees).
    A malformed answer is one "unreadable-answer" difference, as in
    `dcel check`. Raises InvalidInput when graph itself is not valid.
    """
    if kind is not None and kind not in KINDS:
        raise ValueError(f"check: unknown kind {kind!r}; the kinds are {', '.join(KINDS)}")
    reference = _reference(graph)
    try:
        text = answer_text(answer, kind)
    except (TypeError, ValueError, KeyError, OverflowError) as e:
        message = f"answer: cannot be written as a {kind or 'JSON'} document: {type(e).__name__}: {e}"
        difference = Difference("unreadable-answer", message, [])
        return Report([difference], 0, f"1 difference\nunreadable-answer: {message}\n", kind or "faces")
    differences, unlisted, report, read_as, notes = _dcel._check_text(
        reference, text, kind or "auto", face_on_right, one_based, unoriented)
    return Report(differences, unlisted, report, read_as, notes)


def validate(dump: Any) -> List[Violation]:
    """Every broken DCEL invariant of a dump (the first violation of each of
    the checkers: references, twin, next-prev, next-origin, face-on-cycle,
    vertex-out, face-records, isolated-vertices, embedding, rotation,
    orientation, hole-placement). [] when it is a valid DCEL of its own
    points. dump: as check()'s "dump" answers, or a Dcel. Raises InvalidInput
    when it cannot be read as a dump at all."""
    if isinstance(dump, _dcel.Dcel):
        return dump.validate()
    return _dcel._validate_text(answer_text(dump, "dump"))
