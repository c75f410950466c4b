#!/usr/bin/env python3
"""Edit sessions of a planar straight-line graph, answered by brute force.

An implementation of the `dcel diff --sessions` protocol (docs/checking.md,
"Sessions: checking edits and queries"), written as an oracle to be read, not
as a DCEL: it keeps only the vertices (protocol id -> exact point) and the set
of edges. An edit checks its precondition exactly and changes those two; the
faces, their records and every query are then computed from scratch:

    dcel_session.py            one session JSON on stdin, one answer on stdout
    dcel_session.py --stream   one session per line in, one answer per line out

The subdivision, from scratch (class Picture):
  - next(u->v) is the half-edge leaving v just clockwise of v->u (directions
    ordered by half-plane, then by the sign of a cross product, as in
    dcel_faces.py: no atan2, no epsilon); the boundary cycles are its orbits;
  - a cycle of positive signed area is the outer boundary of a bounded face
    (the face on its left); every other cycle (area <= 0) is the outside
    boundary of a connected component, a hole of the face around it;
  - that face, for a hole and for an isolated vertex, is the smallest bounded
    face whose outer cycle winds around a vertex of it (the cycles of its own
    component left out), else the unbounded face. Bounded faces' outer cycles
    are nested or disjoint, so the smallest is the innermost.

The queries: locate is the vertex at the point, else the edge with the point
strictly inside, else the face; face_boundary and neighbours answer as locate
at a vertex or an edge, else with the face's record, or the faces across the
edges of its cycles (itself left out). stab cuts the segment at every vertex
on it and every edge crossing it; each open stretch between two cuts that
does not run along an edge gives the face of its midpoint; consecutive
repeats are merged. from == to: the face the point is in, or nothing.

Exact: a double is a rational number, so Fraction(x) holds it; every decision
is a comparison of Fractions or the sign of a cross product. (Two shortcuts,
both exact: bounding boxes are compared as doubles, which the vertices'
coordinates are; a vertex's rotation and a cycle's area are remembered from
step to step, since a vertex id's point never changes. A session of 2000
vertices and 200 steps then takes a few seconds.)

Names (the protocol's): vertex ids never change and are never reused (the
start graph's are 0..V-1, each vertex a step creates takes the next id); a
bounded face is named by the first half-edge of its outer cycle, [u, v] with
the face on its left; the unbounded face by null.

The refusals are the reference's (src/dcel/edit.hpp, edit/edit_checks.cpp):
an unknown or removed vertex id, an edge that does not exist, a coordinate
that is not finite; split_edge at a point not strictly inside the edge;
add_vertex or add_edge_to_point at a vertex or inside an edge; add_edge with
u == v or between joined vertices; a new segment that crosses an edge,
overlaps one, touches one (an end inside it, or it through an end) or passes
through a vertex; remove_isolated_vertex of a vertex with edges;
merge_collinear_edges of a vertex without exactly two edges, or not strictly
between its two neighbours.

For the planted-bug variants in tests/data/impls/session_*.py, SessionRunner
has a few hooks (refusal, after_edit, adjust_records, cycle_text, locate);
each variant subclasses it and overrides one.
"""
import json
import math
import os
import sys
from fractions import Fraction
from functools import cmp_to_key

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dcel_faces import counterclockwise  # noqa: E402  (orders two directions by angle)


# ---------------------------------------------------------------- geometry

def orient(a, b, c):
    """The sign of (b - a) x (c - a): 1 when c is left of a->b, -1 right, 0 on the line."""
    cross = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (cross > 0) - (cross < 0)


def on_segment(a, b, p):
    """p on the closed segment ab."""
    return (min(a[0], b[0]) <= p[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= p[1] <= max(a[1], b[1])
            and orient(a, b, p) == 0)


def strictly_inside(a, b, p):
    """p on the segment ab, and not an end of it."""
    return p != a and p != b and on_segment(a, b, p)


def meets_elsewhere(p, q, a, b):
    """Do the closed segments pq and ab share a point that is not an end of both?
    (A crossing, an overlap, or an end of one inside the other.)"""
    o1, o2 = orient(p, q, a), orient(p, q, b)
    if o1 == 0 and o2 == 0:
        # Collinear: along the line, points are ordered as (x, y) tuples are.
        lo = max(min(p, q), min(a, b))
        hi = min(max(p, q), max(a, b))
        return lo < hi  # lo == hi: they touch at an end of both; lo > hi: apart
    o3, o4 = orient(a, b, p), orient(a, b, q)
    if o1 * o2 < 0 and o3 * o4 < 0:
        return True
    return (strictly_inside(p, q, a) or strictly_inside(p, q, b)
            or strictly_inside(a, b, p) or strictly_inside(a, b, q))


def boxes_apart(p, q, a, b):
    """Are the bounding boxes of segments pq and ab apart? (On the points as
    floats: the vertices' coordinates are doubles, so this is exact.)"""
    return (max(p[0], q[0]) < min(a[0], b[0]) or max(a[0], b[0]) < min(p[0], q[0])
            or max(p[1], q[1]) < min(a[1], b[1]) or max(a[1], b[1]) < min(p[1], q[1]))


def winding(points, p):
    """The winding number of the closed walk through `points` around p (not on it):
    Sunday's rule, half-open in y, exact."""
    w = 0
    n = len(points)
    for i in range(n):
        a, b = points[i], points[(i + 1) % n]
        if a[1] <= p[1]:
            if b[1] > p[1] and orient(a, b, p) > 0:
                w += 1
        elif b[1] <= p[1] and orient(a, b, p) < 0:
            w -= 1
    return w


def twice_area(points):
    """Twice the signed area of the closed walk (counterclockwise positive)."""
    n = len(points)
    return sum(points[i][0] * points[(i + 1) % n][1] - points[(i + 1) % n][0] * points[i][1] for i in range(n))


# ---------------------------------------------------------------- the subdivision, from scratch

class Picture:
    """The DCEL of the current graph, computed from the points and edges alone.

    cycles[c]      the vertex ids of boundary cycle c, in next order (face on the left)
    cycle_of[h]    the cycle of half-edge h = (u, v)
    area2[c]       twice its signed area
    positive       the cycles of positive area: the bounded faces, each named by its cycle index
    hole_face[c]   for a cycle of area <= 0: the face it is a hole of (a cycle index, or None: unbounded)
    iso_face[v]    for an isolated vertex: the face it lies in
    A face is known by the index of its outer cycle; the unbounded face by None.
    """

    def __init__(self, pts, floats, adj, memo=None):
        self.pts = pts
        self.floats = floats  # the same points as doubles, for quick exact box tests
        # memo: results of pure functions of fixed points, kept across the
        # pictures of one session (a vertex id's point never changes): the
        # rotation of a vertex with a given set of neighbours, a cycle's area.
        memo = {} if memo is None else memo
        self.edges = [(u, v) for u, nbs in enumerate(adj) if nbs for v in nbs if u < v]
        self.at_point = {p: v for v, p in enumerate(pts) if p is not None}

        # The rotation at each vertex: its neighbours counterclockwise.
        self.ring = {}
        self.position = {}
        for v, nbs in enumerate(adj):
            if not nbs:
                continue
            key = ("ring", v, frozenset(nbs))
            if key not in memo:
                o = pts[v]
                direction = {w: (pts[w][0] - o[0], pts[w][1] - o[1]) for w in nbs}
                memo[key] = sorted(nbs, key=cmp_to_key(lambda a, b: counterclockwise(direction[a], direction[b])))
            ring = self.ring[v] = memo[key]
            for i, w in enumerate(ring):
                self.position[(v, w)] = i

        # The boundary cycles: the orbits of next.
        self.cycles = []
        self.cycle_of = {}
        for v in sorted(self.ring):
            for w in self.ring[v]:
                if (v, w) in self.cycle_of:
                    continue
                c = len(self.cycles)
                cycle, h = [], (v, w)
                while h not in self.cycle_of:
                    self.cycle_of[h] = c
                    cycle.append(h[0])
                    h = self.next(h)
                self.cycles.append(cycle)
        self.area2 = []
        for cycle in self.cycles:
            key = ("area", tuple(cycle))
            if key not in memo:
                memo[key] = twice_area([pts[v] for v in cycle])
            self.area2.append(memo[key])
        self.positive = [c for c, a in enumerate(self.area2) if a > 0]
        self.bbox = {}  # of each positive cycle, as doubles
        for c in self.positive:
            xs = [floats[v][0] for v in self.cycles[c]]
            ys = [floats[v][1] for v in self.cycles[c]]
            self.bbox[c] = (min(xs), max(xs), min(ys), max(ys))

        # Connected components (isolated vertices are components of their own).
        parent = list(range(len(pts)))

        def find(x):
            while parent[x] != x:
                parent[x] = parent[parent[x]]
                x = parent[x]
            return x
        for u, v in self.edges:
            parent[find(u)] = find(v)
        self.component = [find(v) if p is not None else None for v, p in enumerate(pts)]

        # Where each hole and each isolated vertex lies.
        self.hole_face = {}
        for c, a in enumerate(self.area2):
            if a <= 0:
                v = self.cycles[c][0]
                self.hole_face[c] = self.face_at(pts[v], skip_component=self.component[v])
        self.isolated = [v for v, p in enumerate(pts) if p is not None and not adj[v]]
        self.iso_face = {v: self.face_at(pts[v], skip_component=self.component[v]) for v in self.isolated}
        # Each component's outside boundary (its one cycle of area <= 0).
        self.exterior = {self.component[self.cycles[c][0]]: c for c in self.hole_face}

    def next(self, h):
        """next(u->v): the half-edge leaving v just clockwise of v->u."""
        u, v = h
        ring = self.ring[v]
        return (v, ring[self.position[(v, u)] - 1])

    def face_at(self, p, skip_component=None):
        """The face whose interior holds p (p on no cycle, except cycles of
        skip_component, which are left out): the innermost bounded face whose
        outer cycle winds around p, else None (unbounded)."""
        best, best_area = None, None
        # p rounded to doubles: rounding is monotonic, so a point outside a
        # box by this test is outside it exactly (the box's corners are doubles).
        fx, fy = float(p[0]), float(p[1])
        for c in self.positive:
            x0, x1, y0, y1 = self.bbox[c]
            if fx < x0 or fx > x1 or fy < y0 or fy > y1:
                continue
            if best is not None and self.area2[c] >= best_area:
                continue
            if skip_component is not None and self.component[self.cycles[c][0]] == skip_component:
                continue
            if winding([self.pts[v] for v in self.cycles[c]], p) != 0:
                best, best_area = c, self.area2[c]
        return best

    def face_of_cycle(self, c):
        return c if self.area2[c] > 0 else self.hole_face[c]

    def face_of_half_edge(self, h):
        return self.face_of_cycle(self.cycle_of[h])

    def name(self, face):
        """The protocol's name of a face: its outer cycle's first half-edge, or None."""
        return None if face is None else self.cycles[face][:2]

    def locate(self, p):
        """("vertex", v), ("edge", u, v) or ("face", face)."""
        if p in self.at_point:
            return ("vertex", self.at_point[p])
        f = (float(p[0]), float(p[1]))
        for u, v in self.edges:
            if not boxes_apart(f, f, self.floats[u], self.floats[v]) and strictly_inside(self.pts[u], self.pts[v], p):
                return ("edge", u, v)
        return ("face", self.face_at(p))

    def records(self):
        """Every face's record: {face: {"outer": cycle or None, "holes": [cycle, ...], "isolated": [v, ...]}},
        the unbounded face first."""
        recs = {None: {"outer": None, "holes": [], "isolated": []}}
        for c in self.positive:
            recs[c] = {"outer": c, "holes": [], "isolated": []}
        for c, f in self.hole_face.items():
            recs[f]["holes"].append(c)
        for v, f in self.iso_face.items():
            recs[f]["isolated"].append(v)
        return recs


# ---------------------------------------------------------------- the session

class Refused(Exception):
    """A step the reference refuses: {"error": message}, and nothing changes."""


def read_number(x):
    """A coordinate as the double the reference reads, or Refused."""
    if isinstance(x, bool) or not isinstance(x, (int, float)):
        raise Refused("a coordinate is not a number: %r" % (x,))
    try:
        f = float(x)
    except OverflowError:
        raise Refused("the coordinate %r is beyond the range of a double" % (x,))
    if not math.isfinite(f):
        raise Refused("the coordinate %r is not finite" % (x,))
    return f


def read_point(xy):
    """([x, y] as doubles, the same point as Fractions)."""
    if not isinstance(xy, list) or len(xy) != 2:
        raise Refused("a point is [x, y], not %r" % (xy,))
    f = [read_number(x) for x in xy]
    return f, (Fraction(f[0]), Fraction(f[1]))


def read_id(x):
    if isinstance(x, float) and x.is_integer():
        x = int(x)
    if isinstance(x, bool) or not isinstance(x, int) or x < 0:
        raise Refused("%r is no vertex id" % (x,))
    return x


EDITS = ("split_edge", "add_vertex", "add_edge", "add_edge_to_point", "remove_edge",
         "remove_isolated_vertex", "merge_collinear_edges")
QUERIES = ("locate", "face_boundary", "neighbours", "stab")


class SessionRunner:
    """One session: the vertices and edges, edited step by step."""

    def __init__(self, vertices, edges):
        self.floats = []  # protocol id -> [x, y] as doubles (printed), or None once removed
        self.pts = []     # protocol id -> (x, y) as Fractions, or None
        self.adj = []     # protocol id -> the set of its neighbours, or None
        self.at_point = {}  # (x, y) -> the live vertex there
        self.memo = {}      # for Picture
        for xy in vertices:
            try:
                f, p = read_point(xy)
            except Refused as e:
                raise ValueError("the start graph: %s" % e)
            self.new_vertex(f, p)
        for e in edges:
            u, v = (int(w) for w in e)
            if u == v or not (0 <= u < len(self.pts) and 0 <= v < len(self.pts)) or v in self.adj[u]:
                raise ValueError("the start graph: bad edge %r" % (e,))
            self.adj[u].add(v)
            self.adj[v].add(u)
        self._picture = None
        self._records = None

    # ---- state

    def new_vertex(self, f, p):
        self.floats.append(list(f))
        self.pts.append(p)
        self.adj.append(set())
        self.at_point[p] = len(self.pts) - 1
        return len(self.pts) - 1

    def drop_vertex(self, v):
        del self.at_point[self.pts[v]]
        self.pts[v] = self.floats[v] = self.adj[v] = None

    def edges(self):
        return [(u, v) for u, nbs in enumerate(self.adj) if nbs for v in nbs if u < v]

    def changed(self):
        self._picture = None
        self._records = None

    def picture(self):
        if self._picture is None:
            self._picture = Picture(self.pts, self.floats, self.adj, self.memo)
        return self._picture

    def records(self):
        if self._records is None:
            pic = self.picture()
            self._records = pic.records()
            self.adjust_records(pic, self._records)
        return self._records

    def state(self):
        pic = self.picture()
        faces = []
        for rec in self.records().values():
            faces.append({"outer": None if rec["outer"] is None else self.cycle_text(pic, rec["outer"]),
                          "holes": [self.cycle_text(pic, c) for c in rec["holes"]],
                          "isolated": sorted(rec["isolated"])})
        return {"faces": faces, "vertices": list(self.floats)}  # a copy: later steps change the list

    # ---- hooks for the planted-bug variants (tests/data/impls/session_*.py)

    def refusal(self, op, args):
        """An extra reason to refuse an edit (a message), or None."""
        return None

    def after_edit(self, op, args, created):
        """Called after each accepted edit (created: the new vertex id, or None)."""

    def adjust_records(self, pic, recs):
        """May change the face records before they are used."""

    def cycle_text(self, pic, c):
        """Cycle c as it is printed: its vertex ids in next order."""
        return list(pic.cycles[c])

    def locate(self, p):
        """Where locate, face_boundary and neighbours find the point."""
        return self.picture().locate(p)

    # ---- checks

    def vertex(self, x):
        v = read_id(x)
        if v >= len(self.pts):
            raise Refused("vertex %d does not exist" % v)
        if self.pts[v] is None:
            raise Refused("vertex %d was removed earlier in the session" % v)
        return v

    def edge(self, pair):
        if not isinstance(pair, list) or len(pair) != 2:
            raise Refused("an edge is [u, v], not %r" % (pair,))
        u, v = self.vertex(pair[0]), self.vertex(pair[1])
        if v not in self.adj[u]:
            raise Refused("there is no edge [%d, %d]" % (u, v))
        return u, v

    def require_free(self, p, f):
        """p (f as doubles) is at no vertex and inside no edge."""
        if p in self.at_point:
            raise Refused("the point is vertex %d already" % self.at_point[p])
        for a, b in self.edges():
            if not boxes_apart(f, f, self.floats[a], self.floats[b]) and strictly_inside(self.pts[a], self.pts[b], p):
                raise Refused("the point lies inside edge [%d, %d]" % (a, b))

    def require_clear(self, u, q, fq, v=None):
        """The segment from u's point to q (fq as doubles; vertex v's point, or
        a new point) meets the graph at u (and v) only."""
        p, fp = self.pts[u], self.floats[u]
        for a, b in self.edges():
            if (not boxes_apart(fp, fq, self.floats[a], self.floats[b])
                    and meets_elsewhere(p, q, self.pts[a], self.pts[b])):
                raise Refused("the segment crosses, overlaps or touches edge [%d, %d]" % (a, b))
        for w, pw in enumerate(self.pts):
            if (pw is not None and w != u and w != v and not boxes_apart(fp, fq, self.floats[w], self.floats[w])
                    and strictly_inside(p, q, pw)):
                raise Refused("the segment passes through vertex %d" % w)

    # ---- edits

    def edit(self, op, args):
        """Checks, then makes one edit; returns the new vertex id or None. Raises Refused."""
        if op == "split_edge":
            u, v = self.edge(args["edge"])
            f, p = read_point(args["at"])
            if not strictly_inside(self.pts[u], self.pts[v], p):
                raise Refused("the point is not exactly on edge [%d, %d] strictly between its ends" % (u, v))
            self.check_extra(op, args)
            w = self.new_vertex(f, p)
            self.disconnect(u, v)
            self.connect(u, w)
            self.connect(w, v)
            return w
        if op == "add_vertex":
            f, p = read_point(args["at"])
            self.require_free(p, f)
            self.check_extra(op, args)
            return self.new_vertex(f, p)
        if op == "add_edge":
            u, v = self.vertex(args["from"]), self.vertex(args["to"])
            if u == v:
                raise Refused("an edge needs two different vertices, but both ends are %d" % u)
            if v in self.adj[u]:
                raise Refused("%d and %d are already joined" % (u, v))
            self.require_clear(u, self.pts[v], self.floats[v], v)
            self.check_extra(op, args)
            self.connect(u, v)
            return None
        if op == "add_edge_to_point":
            u = self.vertex(args["from"])
            f, p = read_point(args["to"])
            self.require_free(p, f)
            self.require_clear(u, p, f)
            self.check_extra(op, args)
            w = self.new_vertex(f, p)
            self.connect(u, w)
            return w
        if op == "remove_edge":
            u, v = self.edge(args["edge"])
            self.check_extra(op, args)
            self.disconnect(u, v)
            return None
        if op == "remove_isolated_vertex":
            v = self.vertex(args["vertex"])
            if self.adj[v]:
                raise Refused("vertex %d has %d edges; remove them first" % (v, len(self.adj[v])))
            self.check_extra(op, args)
            self.drop_vertex(v)
            return None
        if op == "merge_collinear_edges":
            v = self.vertex(args["vertex"])
            if len(self.adj[v]) != 2:
                raise Refused("vertex %d has %d edges; merging needs exactly two" % (v, len(self.adj[v])))
            a, b = sorted(self.adj[v])
            if not strictly_inside(self.pts[a], self.pts[b], self.pts[v]):
                raise Refused("vertex %d is not exactly between %d and %d" % (v, a, b))
            self.check_extra(op, args)
            self.disconnect(v, a)
            self.disconnect(v, b)
            self.connect(a, b)
            self.drop_vertex(v)
            return None
        raise Refused("unknown operation %r" % op)

    def check_extra(self, op, args):
        why = self.refusal(op, args)
        if why:
            raise Refused(why)

    def connect(self, u, v):
        self.adj[u].add(v)
        self.adj[v].add(u)

    def disconnect(self, u, v):
        self.adj[u].discard(v)
        self.adj[v].discard(u)

    # ---- queries

    def located(self, where):
        pic = self.picture()
        if where[0] == "vertex":
            return {"vertex": where[1]}
        if where[0] == "edge":
            return {"edge": [where[1], where[2]]}
        return {"face": pic.name(where[1])}

    def query(self, op, args):
        pic = self.picture()
        if op == "stab":
            fa, a = read_point(args["from"])
            fb, b = read_point(args["to"])
            return {"faces": [pic.name(f) for f in self.stab(a, b, fa, fb)]}
        _, p = read_point(args["at"])
        where = self.locate(p)
        if op == "locate" or where[0] != "face":
            return self.located(where)
        face = where[1]
        rec = self.records()[face]
        if op == "face_boundary":
            return {"face": pic.name(face),
                    "outer": None if rec["outer"] is None else self.cycle_text(pic, rec["outer"]),
                    "holes": [self.cycle_text(pic, c) for c in rec["holes"]]}
        # neighbours: the faces across the edges of the face's cycles, itself left out.
        seen = []
        for c in ([rec["outer"]] if rec["outer"] is not None else []) + rec["holes"]:
            cycle = pic.cycles[c]
            for i, u in enumerate(cycle):
                g = pic.face_of_half_edge((cycle[(i + 1) % len(cycle)], u))
                if g != face and g not in seen:
                    seen.append(g)
        return {"faces": [pic.name(g) for g in seen]}

    def stab(self, a, b, fa, fb):
        """The faces of the open stretches of segment ab (fa, fb: its ends as
        doubles), in order, repeats merged; a stretch along an edge gives none.
        a == b: the face a lies in, if any."""
        pic = self.picture()
        if a == b:
            where = pic.locate(a)
            return [where[1]] if where[0] == "face" else []
        d = (b[0] - a[0], b[1] - a[1])
        dd = d[0] * d[0] + d[1] * d[1]

        def cross(p, q):
            return p[0] * q[1] - p[1] * q[0]

        def param(p):  # of a point on the line
            return ((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / dd
        # What the segment meets: the vertices on it, the edges it crosses or
        # runs along (only those whose boxes meet its box can; exact, on doubles).
        side = {}

        def side_of(v):
            if v not in side:
                side[v] = orient(a, b, self.pts[v])
            return side[v]
        ts = {Fraction(0), Fraction(1)}
        along = []  # the parameter intervals of the edges on the line
        for v in pic.at_point.values():
            if not boxes_apart(fa, fb, self.floats[v], self.floats[v]) and side_of(v) == 0:
                ts.add(param(self.pts[v]))
        for u, v in pic.edges:
            if boxes_apart(fa, fb, self.floats[u], self.floats[v]):
                continue
            pu, pv = self.pts[u], self.pts[v]
            su, sv = side_of(u), side_of(v)
            if su * sv < 0:  # the line crosses the edge inside it
                e = (pv[0] - pu[0], pv[1] - pu[1])
                ts.add(cross((pu[0] - a[0], pu[1] - a[1]), e) / cross(d, e))
            elif su == 0 and sv == 0:
                along.append(sorted((param(pu), param(pv))))
        ts = sorted(t for t in ts if 0 <= t <= 1)
        faces = []
        for t0, t1 in zip(ts, ts[1:]):
            t = (t0 + t1) / 2
            if any(lo < t < hi for lo, hi in along):
                continue  # running along an edge: no face
            f = pic.face_at((a[0] + t * d[0], a[1] + t * d[1]))
            if not faces or faces[-1] != f:
                faces.append(f)
        return faces

    # ---- one step

    def step(self, step, each_step):
        if not isinstance(step, dict) or len(step) != 1:
            return {"error": "a step is {\"operation\": {operands}}"}
        (op, args), = step.items()
        if not isinstance(args, dict):
            return {"error": "%s: the operands are an object" % op}
        if "point" in args and "at" not in args:  # the reader's alias
            args = dict(args, at=args["point"])
        try:
            if op in QUERIES:
                return self.query(op, args)
            if op not in EDITS:
                raise Refused("unknown operation %r" % op)
            created = self.edit(op, args)
            self.changed()
            self.after_edit(op, args, created)
            answer = {"ok": True}
        except (Refused, KeyError, TypeError) as e:
            answer = {"error": "%s: %s" % (op, e)}
        if each_step and op in EDITS:
            answer["state"] = self.state()
        return answer


def answer(text, runner=SessionRunner):
    doc = json.loads(text)
    s = runner(doc["vertices"], doc["edges"])
    each = doc.get("each_step") is True
    steps = [s.step(step, each) for step in doc.get("steps", [])]
    return json.dumps({"steps": steps, "state": s.state()}, separators=(",", ":"))


def main(runner=SessionRunner):
    if "--stream" in sys.argv[1:]:
        for line in sys.stdin:
            if line.strip():
                sys.stdout.write(answer(line, runner) + "\n")
                sys.stdout.flush()  # the other side waits for this line
    else:
        sys.stdout.write(answer(sys.stdin.read(), runner) + "\n")


if __name__ == "__main__":
    main()
