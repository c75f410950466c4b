#!/usr/bin/env python3
# Test impl: correct, but exits with status 3 and a message on a graph with an isolated vertex.
import sys
import _correct


def answer(text):
    points, edges = _correct.graph(text)
    if 0 in _correct.degrees(points, edges):
        sys.stderr.write("exit3_on_isolated: isolated vertices are not supported\n")
        sys.exit(3)
    return _correct.correct(text)


_correct.serve(answer)
