#!/usr/bin/env python3
# Test impl (--stream): right for the first graph, but it keeps each vertex's
# angular order of its edges in a cache keyed by (vertex id, degree) across
# graphs, so a later graph whose vertex has the same id and degree gets the
# old order. Run alone every graph is right; only a graph after another one
# in the same process shows it.
import json
from functools import cmp_to_key
import _correct
import dcel_faces

CACHE = {}


def faces(points, edges):
    origin = [w for u, v in edges for w in (u, v)]
    rings = [[] for _ in points]
    for h, u in enumerate(origin):
        rings[u].append(h)

    def direction(h):
        (x0, y0), (x1, y1) = points[origin[h]], points[origin[h ^ 1]]
        return (x1 - x0, y1 - y0)

    by_angle = cmp_to_key(lambda g, h: dcel_faces.counterclockwise(direction(g), direction(h)))
    for v, ring in enumerate(rings):
        # The sorted order as positions in the ring as built: stale across graphs.
        order = CACHE.setdefault((v, len(ring)), [ring.index(h) for h in sorted(ring, key=by_angle)])
        rings[v] = [ring[i] for i in order]
    position = {h: i for ring in rings for i, h in enumerate(ring)}
    nxt = [rings[origin[h ^ 1]][position[h ^ 1] - 1] for h in range(len(origin))]
    cycles, seen = [], [False] * len(origin)
    for start in range(len(origin)):
        if seen[start]:
            continue
        cycle, h = [], start
        while not seen[h]:
            seen[h] = True
            cycle.append(origin[h])
            h = nxt[h]
        cycles.append(cycle)
    return cycles


def answer(text):
    points, edges = _correct.graph(text)
    return json.dumps({"faces": faces(points, edges)})


_correct.serve(answer)
