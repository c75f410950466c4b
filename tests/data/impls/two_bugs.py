#!/usr/bin/env python3
# Test impl with two independent bugs, for --keep-going: it exits with status
# 3 on any vertex of degree 4 or more, and it leaves out the last boundary
# cycle whenever the graph has two or more edges that share no vertex.
import json
import sys
import _correct
import dcel_faces


def answer(text):
    points, edges = _correct.graph(text)
    if max(_correct.degrees(points, edges) + [0]) >= 4:
        sys.exit(3)
    cycles = dcel_faces.faces(points, edges)
    disjoint = any(not ({a, b} & {c, d}) for i, (a, b) in enumerate(edges) for (c, d) in edges[i + 1:])
    if disjoint:
        cycles = cycles[:-1]
    return json.dumps({"faces": cycles})


_correct.serve(answer)
