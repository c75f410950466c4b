#!/usr/bin/env python3
# Test impl: orders the directions around a vertex by half-plane, then by
# cotangent dx/dy (largest first), exactly (Fractions), with a horizontal
# direction given cotangent +inf eastwards and -inf westwards. The half-plane
# comes from the sign bit of dy, which is right for every dy but a negative
# zero: an edge from (x, 0) east to (x', -0.0) has dy = -0.0 and lands first
# in the lower half-plane instead of first in the upper. Python reads the
# reference's "-0" as the integer 0, which has no sign bit, so only a graph
# that writes -0.0 shows it.
import json
import math
from fractions import Fraction
from functools import cmp_to_key
import _correct


def read(text):
    doc = json.loads(text)
    if isinstance(doc, list):
        doc = {"vertices": doc[0], "edges": doc[1]}
    return doc["vertices"], [(int(u), int(v)) for u, v in doc["edges"]]


def sort_key(points, v, w):
    (x0, y0), (x1, y1) = points[v], points[w]
    dy_float = y1 - y0  # keeps the sign of a zero: -0.0 - 0 is -0.0
    dx, dy = Fraction(x1) - Fraction(x0), Fraction(y1) - Fraction(y0)
    upper = math.copysign(1.0, dy_float) > 0
    if dy == 0:
        cot = (1 if dx > 0 else -1, 0)  # +inf or -inf
    else:
        cot = (0, dx / dy)
    return (0 if upper else 1, (-cot[0], -cot[1]))


def faces(points, edges):
    origin = [w for u, v in edges for w in (u, v)]
    rings = [[] for _ in points]
    for h, u in enumerate(origin):
        rings[u].append(h)
    for v, ring in enumerate(rings):
        ring.sort(key=lambda h: sort_key(points, v, origin[h ^ 1]))
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
    points, edges = read(text)
    return json.dumps({"faces": faces(points, edges)})


_correct.serve(answer)
