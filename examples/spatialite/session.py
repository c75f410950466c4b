#!/usr/bin/env python3
"""SpatiaLite's ISO SQL/MM topology behind the `dcel diff --sessions`
protocol: a topology library's own edits and queries, checked step by step.

    session.py              one session JSON on stdin, one answer on stdout
    session.py --stream     one session per line in, one answer per line out
    session.py --new-edges  split and merge with ST_NewEdgesSplit and
                            ST_NewEdgeHeal (new edge ids) instead of
                            ST_ModEdgeSplit and ST_ModEdgeHeal

Each session gets its own topology (Debian's libsqlite3-mod-spatialite,
loaded into Python's sqlite3), tolerance 0, dropped after. The start graph is
built as examples/spatialite/topology.py builds a graph: ST_AddIsoNode per
vertex, ST_AddEdgeNewFaces per edge. Each step is one or two of the
library's own calls:

    split_edge               ST_ModEdgeSplit(edge, point)  (the new node)
    add_vertex               ST_AddIsoNode(NULL, point)    (the library finds its face)
    add_edge                 ST_AddEdgeNewFaces(node, node, segment)
    add_edge_to_point        ST_AddIsoNode, then ST_AddEdgeNewFaces; when the
                             edge is refused, ST_RemIsoNode takes the node away
    remove_edge              ST_RemEdgeNewFace(edge)
    remove_isolated_vertex   ST_RemIsoNode(node)
    merge_collinear_edges    ST_ModEdgeHeal(edge, edge), after an exact test that
                             the node lies strictly between its two neighbours:
                             the library heals any two edges into one polyline
                             (its edges are linestrings), which is not this
                             operation on a straight-line graph
    locate                   GetNodeByPoint, else GetEdgeByPoint, else
                             GetFaceByPoint, each with tolerance 0
    face_boundary            the face GetFaceByPoint names (after the node and
                             edge look-ups, as locate), its rings read from the
                             edge table
    neighbours               the faces across the edges of those rings
    stab                     {"skip": ...}: the library has no such query

A refusal by the library (an exception from SQLite) is answered
{"error": message}, and the session goes on. The adapter refuses by itself
only what it cannot put to the library: a protocol vertex id with no node, a
pair of vertices with no edge between them, a vertex with fewer than two
edges to merge, or two edges that are not collinear. A start graph the
library refuses is answered {"refused": message}, as topology.py does.

The state is read from the library's tables, not from what the steps were
meant to do: the boundary cycles are the orbits of next over the half-edges
(+e runs from start_node to end_node with left_face on its left and is
followed by next_left_edge; -e runs back with right_face on its left, followed
by next_right_edge; a signed edge id); each cycle belongs to the face on the
left of its first half-edge. A bounded face's outer cycle is its cycle of
positive signed area, decided exactly (the coordinates as integers, in units
of 2^-1074); its other cycles are its holes, and all of the unbounded face 0's
are. The isolated vertices are the nodes without edges, each in the face its
containing_face names. The points are the nodes' geometries read from WKB
(exactly: the text forms round). Faces are named by the first half-edge of
their outer cycle (any cycle when they have none), face 0 by null.

    build/bin/dcel diff --sessions --impl '/usr/bin/python3 examples/spatialite/session.py' --stream
"""
import json
import math
import sqlite3
import struct
import sys

EDITS = ("split_edge", "add_vertex", "add_edge", "add_edge_to_point", "remove_edge",
         "remove_isolated_vertex", "merge_collinear_edges")
QUERIES = ("locate", "face_boundary", "neighbours", "stab")
POINT = "MakePoint(?, ?, 0)"
SEGMENT = f"MakeLine({POINT}, {POINT})"
UNIT = 1 << 1074  # every double is an integer multiple of 2^-1074


class Refused(Exception):
    """A step refused, by the library or by the adapter: {"error": message}."""


def exact(x):
    """The double x as an integer, in units of 2^-1074."""
    n, d = x.as_integer_ratio()
    return n * (UNIT // d)


def orient(a, b, c):
    """The sign of (b - a) x (c - a), points as exact integer pairs."""
    cross = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (cross > 0) - (cross < 0)


def read_point(xy):
    if not isinstance(xy, list) or len(xy) != 2:
        raise Refused("a point is [x, y], not %r" % (xy,))
    out = []
    for x in xy:
        if isinstance(x, bool) or not isinstance(x, (int, float)):
            raise Refused("a coordinate is not a number: %r" % (x,))
        try:
            f = float(x)
        except OverflowError:
            raise Refused("the coordinate %r is beyond the range of a double" % (x,))
        if not math.isfinite(f):
            raise Refused("the coordinate %r is not finite" % (x,))
        out.append(f)
    return tuple(out)


def wkb_point(blob):
    """(x, y) of a WKB Point (2D, Z, M or ZM; either byte order)."""
    order = "<" if blob[0] == 1 else ">"
    (kind,) = struct.unpack_from(order + "I", blob, 1)
    if kind % 1000 != 1:
        raise ValueError(f"WKB geometry type {kind} is not a point")
    return struct.unpack_from(order + "dd", blob, 5)


def library_error(e):
    return str(e) or "refused with no message"


class Tables:
    """What the library's tables say, read once after each edit."""

    def __init__(self, db, name, vertex_of):
        self.vertex_of = vertex_of  # node id -> protocol id
        self.origin, self.next, self.face = {}, {}, {}  # of each signed edge id
        self.ends = {}  # edge id -> (start node, end node)
        for e, start, end, nl, nr, lf, rf in db.execute(
                f'SELECT edge_id, start_node, end_node, next_left_edge, next_right_edge, left_face, right_face '
                f'FROM "{name}_edge"'):
            self.ends[e] = (start, end)
            self.origin[e], self.next[e], self.face[e] = start, nl, lf
            self.origin[-e], self.next[-e], self.face[-e] = end, nr, rf
        self.points = {}  # node id -> exact integer point
        self.floats = {}  # node id -> (x, y) as read
        self.containing = {}  # node id -> containing_face
        for n, face, blob in db.execute(f'SELECT node_id, containing_face, AsBinary(geom) FROM "{name}_node"'):
            self.floats[n] = wkb_point(blob)
            self.points[n] = (exact(self.floats[n][0]), exact(self.floats[n][1]))
            self.containing[n] = face

        # The orbits of next (a walk that meets a missing edge or runs into
        # another orbit stops there: the tables are then inconsistent, and the
        # cycle printed is what they hold).
        self.cycles = []  # lists of signed edge ids
        self.cycle_of = {}
        for start in sorted(self.origin, key=lambda h: (abs(h), h < 0)):
            if start in self.cycle_of:
                continue
            cycle, h = [], start
            while h in self.origin and h not in self.cycle_of:
                self.cycle_of[h] = len(self.cycles)
                cycle.append(h)
                h = self.next[h]
            self.cycles.append(cycle)

        # Each face's cycles: the outer one (positive area) and the holes. A
        # cycle whose half-edges name different faces is listed in each (the
        # tables are inconsistent; one face for it would hide that).
        self.outer, self.holes = {}, {}
        for c, cycle in enumerate(self.cycles):
            for f in dict.fromkeys(self.face[h] for h in cycle):
                if f is not None and f != 0 and f not in self.outer and self.twice_area(cycle) > 0:
                    self.outer[f] = c
                else:
                    self.holes.setdefault(f, []).append(c)
        self.isolated = {}  # face -> protocol ids of its nodes without edges
        with_edges = set(self.origin.values())
        for n, face in self.containing.items():
            if n not in with_edges and n in vertex_of:
                self.isolated.setdefault(face, []).append(vertex_of[n])

    def twice_area(self, cycle):
        pts = [self.points.get(self.origin[h], (0, 0)) for h in cycle]
        return sum(pts[i][0] * pts[(i + 1) % len(pts)][1] - pts[(i + 1) % len(pts)][0] * pts[i][1]
                   for i in range(len(pts)))

    def text(self, c):
        """Cycle c as protocol vertex ids (-1 for a node the session does not know)."""
        return [self.vertex_of.get(self.origin[h], -1) for h in self.cycles[c]]

    def cycles_of(self, face):
        return ([self.outer[face]] if face in self.outer else []) + self.holes.get(face, [])

    def name(self, face):
        """The protocol's name of a face: a half-edge [u, v] with it on the left, or null."""
        if face == 0:
            return None
        for c in self.cycles_of(face):
            for h in self.cycles[c]:
                if self.face[h] == face:
                    start, end = self.ends[abs(h)]
                    u, v = (start, end) if h > 0 else (end, start)
                    return [self.vertex_of.get(u, -1), self.vertex_of.get(v, -1)]
        raise Refused(f"face {face} of the library has no edges to name it by")

    def across(self, face):
        """The faces on the other side of the edges that have `face` on one side."""
        out = []
        for h, f in self.face.items():
            if f == face and self.face[-h] != face and self.face[-h] not in out:
                out.append(self.face[-h])
        return out

    def record(self, face):
        return {"outer": self.text(self.outer[face]) if face in self.outer else None,
                "holes": [self.text(c) for c in self.holes.get(face, [])],
                "isolated": sorted(self.isolated.get(face, []))}

    def state(self, node_of):
        faces = set(self.outer) | set(self.holes) | set(self.isolated) | {0}
        records = [self.record(f) for f in sorted(faces, key=lambda f: (f is None, f or 0))]
        vertices = [None if n is None else list(self.floats[n]) for n in node_of]
        return {"faces": records, "vertices": vertices}


class Session:
    """One session's topology: protocol vertex ids mapped to the library's nodes."""

    def __init__(self, db, name, new_edges):
        self.db, self.name, self.new_edges = db, name, new_edges
        self.node_of = []     # protocol id -> node id, or None once removed
        self.vertex_of = {}   # node id -> protocol id
        self.points = []      # protocol id -> (x, y) as given
        self._tables = None

    def call(self, sql, *args):
        """One call of the library; its refusal raises Refused."""
        try:
            return self.db.execute(sql, args).fetchone()[0]
        except sqlite3.Error as e:
            raise Refused(library_error(e))

    def tables(self):
        if self._tables is None:
            self._tables = Tables(self.db, self.name, self.vertex_of)
        return self._tables

    # ---- names

    def start(self, vertices, edges):
        """The start graph. Each vertex's node is added just before its first
        edge, and the vertices without edges last: then no cycle closes around
        an isolated node while the start is built (a face split moves only one
        of them into the new face: docs/checking.md, "Wrapping a library");
        the edits still meet that."""
        self.points = [read_point(xy) for xy in vertices]
        self.node_of = [None] * len(self.points)
        for u, v in ((int(u), int(v)) for u, v in edges):
            for w in (u, v):
                if self.node_of[w] is None:
                    self.place(w)
            try:
                self.add_edge(u, v)
            except Refused as e:
                raise Refused("the start graph's edge [%d, %d]: %s" % (u, v, e))
        for w in range(len(self.points)):
            if self.node_of[w] is None:
                self.place(w)

    def place(self, w):
        """A node for protocol vertex w, at its point."""
        node = self.call(f"SELECT ST_AddIsoNode(?, NULL, {POINT})", self.name, *self.points[w])
        self.node_of[w] = node
        self.vertex_of[node] = w

    def new_vertex(self, node, p):
        self.node_of.append(node)
        self.vertex_of[node] = len(self.node_of) - 1
        self.points.append(p)
        return len(self.node_of) - 1

    def node(self, v):
        if isinstance(v, float) and v.is_integer():
            v = int(v)
        if isinstance(v, bool) or not isinstance(v, int) or v < 0 or v >= len(self.node_of):
            raise Refused("vertex %r does not exist" % (v,))
        if self.node_of[v] is None:
            raise Refused("vertex %d was removed earlier in the session" % v)
        return self.node_of[v]

    def edge(self, pair):
        if not isinstance(pair, list) or len(pair) != 2:
            raise Refused("an edge is [u, v], not %r" % (pair,))
        a, b = self.node(pair[0]), self.node(pair[1])
        row = self.db.execute(
            f'SELECT edge_id FROM "{self.name}_edge" WHERE (start_node = ? AND end_node = ?) '
            f'OR (start_node = ? AND end_node = ?) ORDER BY edge_id', (a, b, b, a)).fetchone()
        if row is None:
            raise Refused("the library has no edge between vertices %r and %r" % tuple(pair))
        return row[0]

    def segment(self, a, b):
        return (a[0], a[1], b[0], b[1])

    # ---- edits

    def add_edge(self, u, v):
        a, b = self.node(u), self.node(v)
        self.call(f"SELECT ST_AddEdgeNewFaces(?, ?, ?, {SEGMENT})", self.name, a, b,
                  *self.segment(self.points[u], self.points[v]))

    def add_node(self, p):
        node = self.call(f"SELECT ST_AddIsoNode(?, NULL, {POINT})", self.name, *p)
        return self.new_vertex(node, p)

    def edit(self, op, args):
        if op == "split_edge":
            e = self.edge(args["edge"])
            p = read_point(args["at"])
            split = "ST_NewEdgesSplit" if self.new_edges else "ST_ModEdgeSplit"
            node = self.call(f"SELECT {split}(?, ?, {POINT})", self.name, e, *p)
            self.new_vertex(node, p)
        elif op == "add_vertex":
            self.add_node(read_point(args["at"]))
        elif op == "add_edge":
            self.add_edge(args["from"], args["to"])
        elif op == "add_edge_to_point":
            u = args["from"]
            self.node(u)
            w = self.add_node(read_point(args["to"]))
            try:
                self.add_edge(u, w)
            except Refused:
                self.call("SELECT ST_RemIsoNode(?, ?)", self.name, self.node_of[w])
                del self.vertex_of[self.node_of[w]]
                self.node_of.pop()
                self.points.pop()
                raise
        elif op == "remove_edge":
            self.call("SELECT ST_RemEdgeNewFace(?, ?)", self.name, self.edge(args["edge"]))
        elif op == "remove_isolated_vertex":
            v = args["vertex"]
            self.call("SELECT ST_RemIsoNode(?, ?)", self.name, self.node(v))
            self.forget(v)
        elif op == "merge_collinear_edges":
            self.merge(args["vertex"])
        else:
            raise Refused("unknown operation %r" % op)

    def merge(self, v):
        n = self.node(v)
        rows = self.db.execute(
            f'SELECT edge_id, start_node, end_node FROM "{self.name}_edge" WHERE start_node = ? OR end_node = ? '
            f'ORDER BY edge_id', (n, n)).fetchall()
        if len(rows) < 2:
            raise Refused("vertex %d has %d edges; merging needs two" % (v, len(rows)))
        (e1, s1, t1), (e2, s2, t2) = rows[:2]
        a, b = (t1 if s1 == n else s1), (t2 if s2 == n else s2)
        pa, pb, pv = (self.exact_point(self.vertex_of.get(x, -1)) for x in (a, b, n))
        if pa is None or pb is None or orient(pa, pb, pv) != 0 or not min(pa, pb) < pv < max(pa, pb):
            raise Refused("vertex %d is not exactly between its two neighbours" % v)
        heal = "ST_NewEdgeHeal" if self.new_edges else "ST_ModEdgeHeal"
        self.call(f"SELECT {heal}(?, ?, ?)", self.name, e1, e2)
        self.forget(v)

    def exact_point(self, v):
        if v < 0:
            return None
        return (exact(float(self.points[v][0])), exact(float(self.points[v][1])))

    def forget(self, v):
        del self.vertex_of[self.node_of[v]]
        self.node_of[v] = None

    # ---- queries

    def locate(self, p):
        """("vertex", v), ("edge", [u, v]) or ("face", face id), by the library's look-ups."""
        node = self.call(f"SELECT GetNodeByPoint(?, {POINT}, 0)", self.name, *p)
        if node:
            return ("vertex", self.vertex_of.get(node, -1))
        e = self.call(f"SELECT GetEdgeByPoint(?, {POINT}, 0)", self.name, *p)
        if e:
            start, end = self.tables().ends[e]
            return ("edge", [self.vertex_of.get(start, -1), self.vertex_of.get(end, -1)])
        return ("face", self.call(f"SELECT GetFaceByPoint(?, {POINT}, 0)", self.name, *p))

    def query(self, op, args):
        if op == "stab":
            return {"skip": "SpatiaLite's topology has no query for the faces a segment crosses"}
        where, what = self.locate(read_point(args["at"]))
        if where != "face":
            return {where: what}
        t = self.tables()
        if op == "locate":
            return {"face": t.name(what)}
        if op == "face_boundary":
            rec = t.record(what)
            return {"face": t.name(what), "outer": rec["outer"], "holes": rec["holes"]}
        return {"faces": [t.name(g) for g in t.across(what)]}

    # ---- one step

    def step(self, step, each_step):
        if not isinstance(step, dict) or len(step) != 1:
            return {"error": "a step is {\"operation\": {operands}}"}
        (op, args), = step.items()
        if not isinstance(args, dict):
            return {"error": "%s: the operands are an object" % op}
        if "point" in args and "at" not in args:
            args = dict(args, at=args["point"])
        try:
            if op in QUERIES:
                return self.query(op, args)
            try:
                self.edit(op, args)
            finally:
                self._tables = None  # a refusal may have changed the tables too
            answer = {"ok": True}
        except (Refused, KeyError, TypeError) as e:
            answer = {"error": "%s: %s" % (op, e)}
        if each_step and op in EDITS:
            answer["state"] = self.tables().state(self.node_of)
        return answer


def connect():
    db = sqlite3.connect(":memory:", isolation_level=None)  # autocommit: each call stands alone
    db.enable_load_extension(True)
    db.load_extension("mod_spatialite")
    db.execute("SELECT InitSpatialMetadata(1)")
    return db


def answer(db, text, number, new_edges):
    doc = json.loads(text)
    name = f"s{number}"
    db.execute("SELECT CreateTopology(?, 0, 0, 0)", (name,))
    s = Session(db, name, new_edges)
    try:
        try:
            s.start(doc["vertices"], doc["edges"])
        except Refused as e:
            return json.dumps({"refused": "the start graph: %s" % e})
        each = doc.get("each_step") is True
        steps = [s.step(step, each) for step in doc.get("steps", [])]
        return json.dumps({"steps": steps, "state": s.tables().state(s.node_of)}, separators=(",", ":"))
    finally:
        try:
            db.execute("SELECT DropTopology(?)", (name,))
        except sqlite3.Error:
            pass  # a topology half made is dropped with the connection


def main():
    new_edges = "--new-edges" in sys.argv[1:]
    db = connect()
    if "--stream" in sys.argv[1:]:
        for number, line in enumerate(sys.stdin):
            if line.strip():
                sys.stdout.write(answer(db, line, number, new_edges) + "\n")
                sys.stdout.flush()  # the other side waits for this line
    else:
        sys.stdout.write(answer(db, sys.stdin.read(), 0, new_edges) + "\n")


if __name__ == "__main__":
    main()
