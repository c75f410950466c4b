#!/usr/bin/env python3
"""Every boundary cycle of a planar straight-line graph, exactly.

A straightforward implementation of the `dcel diff` answer protocol
(docs/checking.md), written to be read:

    dcel_faces.py            one graph JSON on stdin, one answer on stdout
    dcel_faces.py --stream   one graph per line in, one answer per line out

The answer is {"faces": [[v0, v1, ...], ...]}: every next-cycle of half-edges,
as the origins of its half-edges. next(u->v) is the half-edge leaving v
immediately clockwise from v->u (so at a vertex of degree 1 it is v->u).

Exact: coordinates are doubles, and a double is a rational number, so
Fraction(x) holds it without rounding. Directions around a vertex are ordered
by half-plane, then by the sign of a cross product: no atan2, no epsilon.

DCEL_EXAMPLE_BUG=NAME plants a bug, to see `dcel diff` catch it (several,
comma-separated, plant several):
    atan2      directions are ordered by math.atan2 of float differences,
               which cannot separate nearly parallel directions (the demo)
    ccw        next(u->v) takes the neighbour just counterclockwise of v->u:
               every cycle through a vertex of degree 3 or more is reversed
    isolated   an isolated vertex is answered as a cycle of its own, [v]
"""
import json
import math
import os
import sys
from fractions import Fraction
from functools import cmp_to_key

BUG = set(os.environ.get("DCEL_EXAMPLE_BUG", "").split(","))


def read_graph(text):
    """(points, edges) from {"vertices": [[x, y], ...], "edges": [[u, v], ...]}."""
    doc = json.loads(text)
    if isinstance(doc, list):  # the positional form [[points], [edges]]
        doc = {"vertices": doc[0], "edges": doc[1]}
    points = [(Fraction(x), Fraction(y)) for x, y in doc["vertices"]]
    edges = [(int(u), int(v)) for u, v in doc["edges"]]
    return points, edges


def half_plane(d):
    """0 for directions of angle in [0, pi), 1 for [pi, 2 pi)."""
    dx, dy = d
    return 0 if dy > 0 or (dy == 0 and dx > 0) else 1


def counterclockwise(a, b):
    """Orders directions a and b by angle from the +x axis: -1, 0 or 1."""
    ha, hb = half_plane(a), half_plane(b)
    if ha != hb:
        return -1 if ha < hb else 1
    cross = a[0] * b[1] - a[1] * b[0]  # exact: Fractions
    return -1 if cross > 0 else (1 if cross < 0 else 0)


def faces(points, edges):
    # Half-edge 2k is u->v of edge k, 2k+1 is v->u: twin(h) = h ^ 1.
    origin = [w for u, v in edges for w in (u, v)]
    rings = [[] for _ in points]  # the half-edges leaving each vertex
    for h, u in enumerate(origin):
        rings[u].append(h)

    def direction(h):
        (x0, y0), (x1, y1) = points[origin[h]], points[origin[h ^ 1]]
        return (x1 - x0, y1 - y0)

    if "atan2" in BUG:
        def key(h):
            dx, dy = direction(h)
            return math.atan2(float(dy), float(dx))  # planted: rounds the angle
        for ring in rings:
            ring.sort(key=key)
    else:
        by_angle = cmp_to_key(lambda g, h: counterclockwise(direction(g), direction(h)))
        for ring in rings:
            ring.sort(key=by_angle)

    position = {}
    for ring in rings:
        for i, h in enumerate(ring):
            position[h] = i
    nxt = []
    for h in range(len(origin)):
        twin = h ^ 1  # leaves v = target of h
        ring = rings[origin[twin]]
        if "ccw" in BUG:
            nxt.append(ring[(position[twin] + 1) % len(ring)])  # planted: counterclockwise
            continue
        nxt.append(ring[position[twin] - 1])  # the one just clockwise of the twin

    cycles = []
    seen = [False] * len(origin)
    for start in range(len(origin)):
        if seen[start]:
            continue
        cycle, h = [], start
        while not seen[h]:
            seen[h] = True
            cycle.append(origin[h])
            h = nxt[h]
        cycles.append(cycle)
    if "isolated" in BUG:
        cycles += [[v] for v, ring in enumerate(rings) if not ring]  # planted
    return cycles


def answer(text):
    points, edges = read_graph(text)
    return json.dumps({"faces": faces(points, edges)}, separators=(",", ":"))


def main():
    if "--stream" in sys.argv[1:]:
        for line in sys.stdin:
            if line.strip():
                sys.stdout.write(answer(line) + "\n")
                sys.stdout.flush()  # the other side waits for this line
    else:
        sys.stdout.write(answer(sys.stdin.read()) + "\n")


if __name__ == "__main__":
    main()
