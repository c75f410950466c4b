#!/usr/bin/env python3
# Test impl with two bugs, each met in several coordinate classes: it walks
# backwards every cycle that passes through a vertex of degree 3 or more
# (wrong answer, whatever the coordinates), and it exits with status 3 and "vertex N is isolated" on
# stderr for any isolated vertex. Grouped by what each is once shrunk, this is
# exactly two distinct failures, each listing the classes it was seen in.
import json
import sys
import _correct
import dcel_faces


def answer(text):
    points, edges = _correct.graph(text)
    degrees = _correct.degrees(points, edges)
    for v, d in enumerate(degrees):
        if d == 0:
            sys.stderr.write(f"Traceback (most recent call last):\n  File \"impl.py\", line 9, in answer\n"
                             f"ValueError: vertex {v} is isolated\n")
            sys.exit(3)
    cycles = dcel_faces.faces(points, edges)
    cycles = [[c[0]] + c[1:][::-1] if any(degrees[v] >= 3 for v in c) else c for c in cycles]
    return json.dumps({"faces": cycles})


_correct.serve(answer)
