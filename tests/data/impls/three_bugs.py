#!/usr/bin/env python3
# Test impl with three bugs, for the tests that compare reports run in
# different ways (--jobs, --shard): it walks backwards every cycle through a
# vertex of degree 3 or more (a wrong answer); it exits with status 3 on an
# isolated vertex; and it prints an unparsable answer when a coordinate is
# negative. Deterministic: the same graph always gets the same answer.
import json
import sys
import _correct
import dcel_faces


def answer(text):
    points, edges = _correct.graph(text)
    degrees = _correct.degrees(points, edges)
    if 0 in degrees:
        sys.stderr.write("ValueError: a vertex is isolated\n")
        sys.exit(3)
    if any(c < 0 for p in points for c in p):
        return "{\"faces\": [oops"
    cycles = dcel_faces.faces(points, edges)
    cycles = [[c[0]] + c[1:][::-1] if any(degrees[v] >= 3 for v in c) else c for c in cycles]
    return json.dumps({"faces": cycles})


_correct.serve(answer)
