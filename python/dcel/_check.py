"""check() and validate(): Python answers in, structured differences out.

An answer is turned into the JSON document `dcel check` reads
(docs/formats.md) and read by the library's own reader, so that a Python
answer and the same answer in a file are judged alike, down to the message
for a malformed one.
"""
from __future__ import annotations

import json
import math
import reprlib
from collections.abc import Mapping
from itertools import chain
from typing import Any, Iterator, List, Optional, Sequence, Union, overload

from . import _dcel
from ._types import NULL, Difference, InvalidInput, Violation

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


# The lists of an answer are read from a snapshot (tuple(...)): _null() runs
# the answer's own __int__ and __eq__, which may change the list being read,
# and a list iterated as it grows at the front never ends.

def _ids(values: Any) -> Any:
    values = _plain(values) if hasattr(values, "tolist") else values
    return [_null(v) for v in tuple(values)]


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
    for f in tuple(faces):
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
    if _is_dcel(answer):
        return answer.to_dump()
    if not isinstance(answer, Mapping):
        raise ValueError("a dump is a mapping: {\"vertices\", \"half_edges\", \"faces\"} or {\"vertices\", "
                         "\"origin\", \"twin\", \"next\", \"prev\", \"face\", \"faces\"}")
    dump = _columnar_dump(answer) if "origin" in answer and "half_edges" not in answer else dict(answer)
    if "faces" in dump:
        dump["faces"] = _face_records(dump["faces"])
    if "half_edges" in dump:
        dump["half_edges"] = [
            {k: _null(v) for k, v in dict(h).items()} if isinstance(h, Mapping) else h
            for h in tuple(dump["half_edges"])
        ]
    if dump.get("vertex_out") is not None:
        dump["vertex_out"] = _ids(dump["vertex_out"])
    return dump


def _is_dump(answer: Any) -> bool:
    return _is_dcel(answer) or (
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


# ---- Writing an answer as JSON text, whatever it holds.
#
# json.dumps recurses (RecursionError past about 1000 levels of nesting)
# and reads a list as it changes; the library's JSON reader reads at most
# _dcel._JSON_MAX_DEPTH (256) levels and refuses the bracket beyond with a
# message naming its line and column. _json_cut writes the text json.dumps
# writes, without recursion, from snapshots; for check() it stops just after
# that bracket: the reader stops there too, so check() reports what `dcel
# check` reports for the whole document in a file, and spends no time or
# memory on the rest.

_MAX_DEPTH = _dcel._JSON_MAX_DEPTH
_DEFAULT_CHAIN = 32  # _plain() of _plain() of ...: more is an object that never becomes JSON
_END = object()


def _is(o: Any, types: Any) -> bool:
    """isinstance() by the type itself, as the json module checks (isinstance() also asks __class__, which an
    object may fake or make raise)."""
    return issubclass(type(o), types)


def _float_json(v: float) -> str:
    """json.dumps's spelling of a float (of a subclass too: its own methods are not called)."""
    if math.isnan(v):
        return "NaN"
    if math.isinf(v):
        return "Infinity" if math.copysign(1.0, v) > 0 else "-Infinity"
    return float.__repr__(v)


def _scalar_json(o: Any) -> Optional[str]:
    """json.dumps's text for None, a bool, str, int or float; None for anything else."""
    if o is None:
        return "null"
    if o is True:
        return "true"
    if o is False:
        return "false"
    if _is(o, str):
        return json.encoder.encode_basestring_ascii(o)
    if _is(o, int):
        return int.__repr__(o)
    if _is(o, float):
        return _float_json(o)
    return None


def _key_json(key: Any) -> str:
    """A dict key as json.dumps writes it (a str; numbers, bools and None as their JSON text, quoted)."""
    if _is(key, str):
        return json.encoder.encode_basestring_ascii(key)
    if _is(key, float):
        return '"' + _float_json(key) + '"'
    if key is True or key is False or key is None:
        return '"' + str(_scalar_json(key)) + '"'
    if _is(key, int):
        return '"' + int.__repr__(key) + '"'
    raise TypeError(f"keys must be str, int, float, bool or None, not {type(key).__name__}")


_PLAIN_TYPES = frozenset((int, float, str, bool, type(None)))
_STR_TYPE = frozenset((str,))
_LIST_TYPE = {list}
_DICT_TYPE = {dict}
_CONTAINER_TYPES = frozenset((list, dict))
_PLAIN_LEVELS = 3  # a dump is a plain tree of 3 levels; faces, polygons and rings of 1 to 3


def _plain_tree(o: Any, levels: int) -> bool:
    """o is a list or dict (str keys) of exactly these types, nested at most
    levels + 1 deep, down to numbers, strs, bools and None of exactly those
    types: json.dumps writes it running no code of its items, as _json_cut
    would, several times faster. Most answers are such trees. Checked a
    level at a time, each by itertools in C."""
    layer = [o]
    for _ in range(levels + 1):
        kinds = set(map(type, layer))
        if not kinds <= _CONTAINER_TYPES:
            return False
        lists = layer if kinds == _LIST_TYPE else [x for x in layer if type(x) is list]
        dicts = layer if kinds == _DICT_TYPE else [x for x in layer if type(x) is dict]
        if dicts and not _STR_TYPE.issuperset(map(type, chain.from_iterable(dicts))):
            return False
        children = list(chain(chain.from_iterable(lists), chain.from_iterable(map(dict.values, dicts))))
        kinds = set(map(type, children))
        if kinds <= _PLAIN_TYPES:
            return True
        if not kinds <= _PLAIN_TYPES | _CONTAINER_TYPES:
            return False
        layer = [x for x in children if type(x) is list or type(x) is dict]
    return False


def _json_cut(document: Any, max_depth: Optional[int] = _MAX_DEPTH) -> str:
    """json.dumps(document, default=_plain, allow_nan=True), written without
    recursion, and cut just after the first bracket nested deeper than
    max_depth (None: not cut). Lists, tuples and dicts are read as json.dumps
    reads them (a dict's items(), a subclass's __iter__), each once, into a
    tuple, so that code they run cannot change what is being written (the
    json module reads a list as it changes: a tolist() that inserts into the
    list being written makes json.dumps run forever)."""
    out: List[str] = []
    stack: List[list] = []  # [items iterator, is a dict, id, first item?] of each open container
    open_ids: set = set()

    def write(o: Any) -> bool:
        """Write o, or open it (a container) on the stack; False at the bracket too deep to read."""
        for _ in range(_DEFAULT_CHAIN):
            text = _scalar_json(o)
            if text is not None:
                out.append(text)
                return True
            if _is(o, (list, tuple, dict)):
                if id(o) in open_ids:
                    raise ValueError("Circular reference detected")
                is_dict = _is(o, dict)
                if len(stack) == max_depth:
                    out.append("{" if is_dict else "[")
                    return False
                if (max_depth is None or len(stack) + _PLAIN_LEVELS < max_depth) and _plain_tree(o, _PLAIN_LEVELS):
                    out.append(json.dumps(o))  # nothing runs between the check and the writing
                    return True
                out.append("{" if is_dict else "[")
                items = tuple(dict.items(o) if type(o) is dict else o.items()) if is_dict else tuple(o)
                open_ids.add(id(o))
                stack.append([iter(items), is_dict, id(o), True])
                return True
            o = _plain(o)
        raise TypeError(f"{type(o).__name__}.tolist() keeps giving objects that are not numbers or lists")

    if not write(document):
        return "".join(out)
    while stack:
        frame = stack[-1]
        item = next(frame[0], _END)
        if item is _END:
            out.append("}" if frame[1] else "]")
            open_ids.discard(frame[2])
            stack.pop()
            continue
        if not frame[3]:
            out.append(", ")
        frame[3] = False
        if frame[1]:
            key, item = item
            out.append(_key_json(key) + ": ")
        if not write(item):
            break
    return "".join(out)



def _text(answer: Any, kind: Optional[str], max_depth: Optional[int] = _MAX_DEPTH) -> Union[str, bytes]:
    """The answer's JSON text, cut as _json_cut says; a str or bytes answer is that text already (bytes are
    read as UTF-8)."""
    if isinstance(answer, (str, bytes)):
        return answer
    return _json_cut(_document(answer, kind), max_depth)


def answer_text(answer: Any, kind: Optional[str] = None) -> str:
    """The JSON document `dcel check` would read for this answer.

    ValueError when it cannot be written (numbers or lists of a kind JSON
    has not, or code of the answer's own that raises)."""
    try:
        text = _text(answer, kind, max_depth=None)
        return text.decode() if isinstance(text, bytes) else text
    except Exception as e:  # whatever the answer's own code raises
        raise ValueError(f"answer: cannot be written as a {kind or 'JSON'} document: {_error_text(e)}") from e


# ---- Messages about Python values and errors: one printable line.

_REPR = reprlib.Repr()
_REPR.maxlevel = 3
_REPR.maxstring = 40
_REPR.maxother = 40


def _one_line(text: str, limit: int = 200) -> str:
    """text with what str.isprintable() refuses (newlines, lone surrogates) escaped, cut at limit characters."""
    out = "".join(c if c.isprintable() else repr(c)[1:-1] for c in text[:limit])
    return out + ("..." if len(text) > limit else "")


def _shown(value: Any) -> str:
    """A short repr of any value, on one line (a type name when its repr fails)."""
    try:
        return _one_line(_REPR.repr(value), 60)
    except Exception:
        return f"<{type(value).__name__} object>"


def _error_text(e: BaseException) -> str:
    """ "ZeroDivisionError: boom", on one line, whatever the exception's __str__ does."""
    name = type(e).__name__
    try:
        message = str(e)
    except Exception:
        message = ""
    return _one_line(f"{name}: {message}" if message else name)


def _is_dcel(value: Any) -> bool:
    try:
        return isinstance(value, _dcel.Dcel)
    except Exception:  # a __class__ that raises: not a Dcel
        return False


def _reference(graph: Any) -> "_dcel.Dcel":
    return graph if _is_dcel(graph) else _dcel.build(graph)


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
      str is taken as the JSON text of the answer, bytes as its UTF-8.

    face_on_right, one_based, unoriented: the conventions of `dcel check
    --face-on right --one-based --unoriented`.

    Returns a Report (a sequence of Difference, empty when the answer agrees).
    A malformed answer is one "unreadable-answer" difference, as in
    `dcel check`: so is one nested too deep, one whose own code raises
    (a __float__, tolist(), items()), a lone surrogate in a str. Raises
    InvalidInput when graph itself is not valid.
    """
    kind = _kind(kind)
    reference = _reference(graph)
    try:
        text = _text(answer, kind)
    except Exception as e:  # whatever the answer's own code raises: the answer is unreadable
        message = f"answer: cannot be written as a {kind or 'JSON'} document: {_error_text(e)}"
        difference = Difference("unreadable-answer", message, [])
        return Report([difference], 0, f"1 difference\nunreadable-answer: {message}\n", kind or "faces")
    differences, unlisted, report, read_as, notes = _dcel._check_text(
        reference, text, kind or "auto", face_on_right, one_based, unoriented)
    return Report(differences, unlisted, report, read_as, notes)


def _kind(kind: Any) -> Optional[str]:
    """The kind, one of KINDS (compared as a plain str: a subclass's __eq__ is not asked), or None."""
    if kind is None:
        return None
    for known in KINDS:
        if issubclass(type(kind), str) and str.__eq__(kind, known):  # not isinstance(), which asks __class__
            return known
    raise ValueError(f"check: unknown kind {_shown(kind)}; the kinds are {', '.join(KINDS)}")


def validate(dump: Any) -> List[Violation]:
    """Every broken DCEL invariant of a dump (the first violation of each of
    the checkers: references, twin, next-prev, next-origin, face-on-cycle,
    vertex-out, face-records, isolated-vertices, embedding, rotation,
    orientation, hole-placement). [] when it is a valid DCEL of its own
    points. dump: as check()'s "dump" answers, or a Dcel. Raises InvalidInput
    when it cannot be read as a dump at all."""
    if _is_dcel(dump):
        return dump.validate()
    try:
        text = _text(dump, "dump")
    except Exception as e:  # whatever the dump's own code raises
        raise InvalidInput(f"dump: cannot be written as a JSON document: {_error_text(e)}") from e
    return _dcel._validate_text(text)
