"""dcel: the exact reference DCEL (half-edge structure) of planar straight-line graphs.

    >>> import dcel
    >>> d = dcel.build([(0, 0), (4, 0), (0, 3)], [(0, 1), (1, 2), (2, 0)])
    >>> d.boundary_cycles()
    [[0, 1, 2], [1, 0, 2]]
    >>> dcel.check(d, [[0, 1, 2], [0, 1, 2]])[0].kind
    'reversed-cycle'

build() gives a Dcel whose arrays (origin, next, prev, face, ...) are
read-only numpy views; check() compares another implementation's answer
with it; dcel.hypothesis has strategies for planar graphs. Exact: no
decision is taken in floating point. See docs/python.md.
"""
from ._types import (
    NULL,
    Area,
    Change,
    Difference,
    Face,
    Graph,
    IdChange,
    InvalidInput,
    Location,
    StabPiece,
    TopologyError,
    Violation,
)
from ._dcel import (  # noqa: I001  (the extension needs ._types imported first)
    Dcel,
    build,
    faces,
    families,
    generate,
    plant,
    read_graph,
    shrink,
    shrink_candidates,
    transform,
)
from ._check import KINDS, Report, answer_text, check, validate

__version__ = "0.1.0"

__all__ = [
    "NULL",
    "KINDS",
    "Area",
    "Change",
    "Dcel",
    "Difference",
    "Face",
    "Graph",
    "IdChange",
    "InvalidInput",
    "Location",
    "Report",
    "StabPiece",
    "TopologyError",
    "Violation",
    "answer_text",
    "build",
    "check",
    "faces",
    "families",
    "generate",
    "plant",
    "read_graph",
    "shrink",
    "shrink_candidates",
    "transform",
    "validate",
]

# Shown as dcel.Face, dcel.InvalidInput, ... in reprs and tracebacks (and
# pickled under those names, which resolve here).
for _cls in (Area, Change, Difference, Face, Graph, IdChange, InvalidInput, Location, StabPiece, TopologyError,
             Violation, Report):
    _cls.__module__ = __name__
del _cls
