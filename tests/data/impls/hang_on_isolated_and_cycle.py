#!/usr/bin/env python3
# Test impl: right, but it never answers when the graph has both a bounded
# face and an isolated vertex (its face-assignment loop never ends then).
import time
import _correct


def answer(text):
    points, edges = _correct.graph(text)
    degree = _correct.degrees(points, edges)
    parent = list(range(len(points)))

    def find(x):
        while parent[x] != x:
            x = parent[x]
        return x
    cycle = False
    for u, v in edges:
        ru, rv = find(u), find(v)
        cycle = cycle or ru == rv
        parent[ru] = rv
    if cycle and 0 in degree:
        while True:
            time.sleep(60)
    return _correct.correct(text)


_correct.serve(answer)
