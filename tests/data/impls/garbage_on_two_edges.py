#!/usr/bin/env python3
# Test impl: correct, but prints binary garbage for a graph with two edges or more.
import _correct


def answer(text):
    points, edges = _correct.graph(text)
    if len(edges) >= 2:
        return "\x00\x01garbage \xff{\"faces\": [[0, 1"
    return _correct.correct(text)


_correct.serve(answer)
