#!/usr/bin/env python3
# Test impl: right, but every boundary walk stops after 1000 half-edges (a
# "safety" cap), so a cycle longer than that comes out cut short. Only a large
# graph shows it: a star or a tree of more than 500 vertices.
import json
import _correct
import dcel_faces


def answer(text):
    points, edges = _correct.graph(text)
    return json.dumps({"faces": [c[:1000] for c in dcel_faces.faces(points, edges)]})


_correct.serve(answer)
