"""A whole DCEL of a planar straight-line graph in plain Python, exactly.

The kind of implementation people write for a course or a GIS script, made
exact: coordinates become Fractions (a double is a rational number, so
nothing is rounded) and every decision is a comparison or the sign of a cross
product. docs/python.md checks it against the reference with pytest and
Hypothesis (test_pure_dcel.py).

    d = PureDcel([(0, 0), (4, 0), (0, 3)], [(0, 1), (1, 2), (2, 0)])
    d.cycles()    # [[0, 1, 2], [1, 0, 2]]: every boundary cycle, as vertex ids
    d.to_dump()   # the whole DCEL in the `dcel build` format

Conventions (the reference's): half-edge 2k runs u -> v along edge k, 2k + 1
back; next(u->v) leaves v immediately clockwise from v->u; face 0 is the
unbounded face; a bounded face has one counterclockwise outer cycle, and its
holes are the clockwise outer boundaries of the components directly inside.

bug= (or the environment variable DCEL_EXAMPLE_BUG) plants one bug:
    "atan2"     directions ordered by math.atan2 of float differences, which
                cannot separate nearly parallel directions
    "ccw"       next(u->v) takes the neighbour just counterclockwise of v->u
    "isolated"  out(v) is taken as the first half-edge leaving v, which an
                isolated vertex does not have: IndexError
    "tiny"      coordinates below 1e-200 in magnitude read as 0, as a
                "snap tiny values" tolerance would
    "recursive" a boundary cycle walked by a recursion per half-edge, which
                passes Python's recursion limit on a cycle of about a
                thousand half-edges: RecursionError
"""
import math
import os
from fractions import Fraction
from functools import cmp_to_key

NONE = None


def _half_plane(dx, dy):
    """0 for directions of angle in [0, pi), 1 for [pi, 2 pi)."""
    return 0 if dy > 0 or (dy == 0 and dx > 0) else 1


def _by_angle(a, b):
    """Orders directions a and b counterclockwise from the +x axis: -1, 0 or 1."""
    ha, hb = _half_plane(*a), _half_plane(*b)
    if ha != hb:
        return -1 if ha < hb else 1
    cross = a[0] * b[1] - a[1] * b[0]
    return -1 if cross > 0 else (1 if cross < 0 else 0)


def _orient(a, b, c):
    """The sign of the cross product (b - a) x (c - a): 1 left turn, -1 right, 0 collinear."""
    cross = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (cross > 0) - (cross < 0)


class PureDcel:
    def __init__(self, vertices, edges, bug=None):
        self.bug = os.environ.get("DCEL_EXAMPLE_BUG", "") if bug is None else bug
        if self.bug == "tiny":
            vertices = [[c if abs(c) >= 1e-200 else 0.0 for c in map(float, p)] for p in vertices]
        self.points = [(Fraction(x), Fraction(y)) for x, y in vertices]
        self.origin = [w for u, v in edges for w in (int(u), int(v))]
        self.twin = [h ^ 1 for h in range(len(self.origin))]
        self._link_next()
        self._make_faces()

    def _direction(self, h):
        (x0, y0), (x1, y1) = self.points[self.origin[h]], self.points[self.origin[h ^ 1]]
        return (x1 - x0, y1 - y0)

    def _link_next(self):
        # The half-edges leaving each vertex, counterclockwise.
        rings = [[] for _ in self.points]
        for h, v in enumerate(self.origin):
            rings[v].append(h)
        for ring in rings:
            if self.bug == "atan2":
                ring.sort(key=lambda h: math.atan2(float(self._direction(h)[1]), float(self._direction(h)[0])))
            else:
                ring.sort(key=cmp_to_key(lambda g, h: _by_angle(self._direction(g), self._direction(h))))
        position = {h: i for ring in rings for i, h in enumerate(ring)}
        self.next = [0] * len(self.origin)
        for h in range(len(self.origin)):
            ring = rings[self.origin[h ^ 1]]  # around the target of h
            step = 1 if self.bug == "ccw" else -1  # -1: just clockwise of the twin
            self.next[h] = ring[(position[h ^ 1] + step) % len(ring)]
        self.prev = [0] * len(self.origin)
        for h, n in enumerate(self.next):
            self.prev[n] = h
        if self.bug == "isolated":
            self.out = [rings[v][0] for v in range(len(self.points))]
        else:
            self.out = [ring[0] if ring else NONE for ring in rings]

    def _cycle(self, h):
        if self.bug == "recursive":
            def walk(x):
                return [x] if self.next[x] == h else [x] + walk(self.next[x])
            return walk(h)
        cycle = [h]
        while self.next[cycle[-1]] != h:
            cycle.append(self.next[cycle[-1]])
        return cycle

    def _area2(self, cycle):
        """Twice the signed area (shoelace), exact."""
        total = Fraction(0)
        for h in cycle:
            (x0, y0), (x1, y1) = self.points[self.origin[h]], self.points[self.origin[h ^ 1]]
            total += x0 * y1 - x1 * y0
        return total

    def _winds_around(self, cycle, p):
        """Does the closed walk along cycle wind around p (p on none of its edges)?"""
        winding = 0
        for h in cycle:
            a, b = self.points[self.origin[h]], self.points[self.origin[h ^ 1]]
            if a[1] <= p[1] < b[1] and _orient(a, b, p) > 0:
                winding += 1
            elif b[1] <= p[1] < a[1] and _orient(a, b, p) < 0:
                winding -= 1
        return winding != 0

    def _make_faces(self):
        # Every next-cycle; a positive one is the outer cycle of a bounded face,
        # the others (one per connected component) are its outside, a hole.
        self.face = [NONE] * len(self.origin)
        cycles, outers, holes = [], [], []
        for h in range(len(self.origin)):
            if self.face[h] is NONE:
                cycle = self._cycle(h)
                for x in cycle:
                    self.face[x] = len(cycles)  # a cycle number for now
                area = self._area2(cycle)
                (outers if area > 0 else holes).append((area, len(cycles)))
                cycles.append(cycle)
        # Faces: 0 unbounded, then one per positive cycle.
        self.faces = [{"outer": NONE, "inner": [], "isolated": []}]
        face_of_cycle = {}
        for _, c in outers:
            face_of_cycle[c] = len(self.faces)
            self.faces.append({"outer": cycles[c][0], "inner": [], "isolated": []})
        # A component lies in the smallest positive cycle of another component
        # that winds around one of its vertices (nested cycles: the smallest is
        # the face directly around it), or in the unbounded face.
        component = self._components()
        outers.sort()

        def enclosing_face(v):
            for _, c in outers:
                if component[self.origin[cycles[c][0]]] != component[v] and self._winds_around(cycles[c], self.points[v]):
                    return face_of_cycle[c]
            return 0

        for _, c in holes:
            f = enclosing_face(self.origin[cycles[c][0]])
            face_of_cycle[c] = f
            self.faces[f]["inner"].append(cycles[c][0])
        for v, h in enumerate(self.out):
            if h is NONE:
                self.faces[enclosing_face(v)]["isolated"].append(v)
        self.face = [face_of_cycle[c] for c in self.face]

    def _components(self):
        component = list(range(len(self.points)))

        def find(v):
            while component[v] != v:
                component[v] = component[component[v]]
                v = component[v]
            return v

        for h in range(0, len(self.origin), 2):
            component[find(self.origin[h])] = find(self.origin[h + 1])
        return [find(v) for v in range(len(self.points))]

    def cycles(self):
        """Every boundary cycle as its vertices in next order (the `dcel faces` answer)."""
        seen, out = set(), []
        for h in range(len(self.origin)):
            if h not in seen:
                cycle = self._cycle(h)
                seen.update(cycle)
                out.append([self.origin[x] for x in cycle])
        return out

    def to_dump(self):
        """The whole DCEL as a dict in the `dcel build` format (docs/formats.md)."""
        return {
            "vertices": [[float(x), float(y)] for x, y in self.points],
            "vertex_out": self.out,
            "half_edges": [
                {"origin": self.origin[h], "twin": self.twin[h], "next": self.next[h], "prev": self.prev[h],
                 "face": self.face[h]}
                for h in range(len(self.origin))
            ],
            "faces": self.faces,
        }
