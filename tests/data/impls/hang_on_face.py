#!/usr/bin/env python3
# Test impl: correct, but never answers on a graph with a bounded face
# (E - V + C > 0: here, simply, more edges than a forest can have).
import time
import _correct


def components(n, edges):
    parent = list(range(n))

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x
    for u, v in edges:
        parent[find(u)] = find(v)
    return len({find(x) for x in range(n)})


def answer(text):
    points, edges = _correct.graph(text)
    if len(edges) - len(points) + components(len(points), edges) > 0:
        while True:
            time.sleep(60)
    return _correct.correct(text)


_correct.serve(answer)
