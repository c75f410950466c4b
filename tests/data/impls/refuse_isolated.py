#!/usr/bin/env python3
# Test impl: refuses any graph with an isolated vertex, naming it: {"refused":
# "vertex 7 at (3, 4) is isolated"}. A refusal of a valid graph is a failure,
# grouped by its message with the numbers masked; in --stream the process
# goes on (no restart).
import json
import _correct


def answer(text):
    points, edges = _correct.graph(text)
    for v, d in enumerate(_correct.degrees(points, edges)):
        if d == 0:
            x, y = points[v]
            return json.dumps({"refused": f"vertex {v} at ({x}, {y}) is isolated"})
    return _correct.correct(text)


_correct.serve(answer)
