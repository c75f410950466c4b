#!/usr/bin/env python3
"""The seed solver (the project's starting point, "an array-based DCEL builder"),
adapted to the `dcel diff` protocol and KEPT WITH ITS BUGS, so that
`dcel diff` has a real-world implementation to catch:

  * its next rule takes the twin of the right half-edge: next(h) is
    twin(ring[i - 1]) instead of ring[i - 1], so next(h) arrives at the
    target of h instead of leaving it. A lone edge gives two 1-cycles, a
    triangle three 2-cycles.
  * it orders directions by math.atan2 of float differences, which cannot
    separate directions that differ by about one ulp of angle.

Usage: seed_solver.py < graph.json, or seed_solver.py --stream (one graph
per line in, one answer per line out).
"""
import json
import sys
from math import atan2


# ---- the seed's solve(), as published (comments shortened) ----------------
def solve(xs):
    vertices, edges = xs
    n = len(vertices)
    # Build half-edges: two per undirected edge, indexed 2k and 2k+1.
    he_origin = []
    he_twin = []
    for u, v in edges:
        he_origin.append(u)
        he_twin.append(len(he_origin))  # twin will be placed next
        he_origin.append(v)
        he_twin.append(len(he_origin) - 2)
    # For each vertex, gather outgoing half-edges sorted by angle CCW.
    out = [[] for _ in range(n)]
    for h, u in enumerate(he_origin):
        v = he_origin[he_twin[h]]
        dx = vertices[v][0] - vertices[u][0]
        dy = vertices[v][1] - vertices[u][1]
        out[u].append((atan2(dy, dx), h))
    for lst in out:
        lst.sort()
    # next[h] = twin(prev CCW outgoing half-edge at destination of h).
    m = len(he_origin)
    he_next = [0] * m
    for h in range(m):
        t = he_twin[h]
        v = he_origin[t]
        ring = out[v]
        idx = next(i for i, (_, hh) in enumerate(ring) if hh == t)
        prev_idx = (idx - 1) % len(ring)
        he_next[h] = he_twin[ring[prev_idx][1]]  # the bug: should be ring[prev_idx][1]
    # Walk face cycles.
    seen = [False] * m
    faces = []
    for start in range(m):
        if seen[start]:
            continue
        cycle = []
        h = start
        while not seen[h]:
            seen[h] = True
            cycle.append(he_origin[h])
            h = he_next[h]
        faces.append(cycle)
    return faces
# ---- end of the seed ---------------------------------------------------------


def answer(text):
    """The protocol around solve(): graph JSON in, {"faces": ...} out."""
    doc = json.loads(text)
    if isinstance(doc, list):
        doc = {"vertices": doc[0], "edges": doc[1]}
    vertices = [(float(x), float(y)) for x, y in doc["vertices"]]
    edges = [(int(u), int(v)) for u, v in doc["edges"]]
    return json.dumps({"faces": solve((vertices, edges))}, separators=(",", ":"))


def main():
    if "--stream" in sys.argv[1:]:
        for line in sys.stdin:
            if line.strip():
                sys.stdout.write(answer(line) + "\n")
                sys.stdout.flush()
    else:
        sys.stdout.write(answer(sys.stdin.read()) + "\n")


if __name__ == "__main__":
    main()
