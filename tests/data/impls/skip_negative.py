#!/usr/bin/env python3
# Test impl: right on what it promises, and {"skip": reason} for graphs with a
# negative coordinate, outside its domain (a skip is counted by reason, never
# a failure and never a pass).
import json
import _correct


def answer(text):
    points, edges = _correct.graph(text)
    if any(x < 0 or y < 0 for x, y in points):
        return json.dumps({"skip": "negative coordinates are outside this library's domain"})
    return _correct.correct(text)


_correct.serve(answer)
