#!/usr/bin/env python3
# Test impl, right under a convention: a face enumerator that writes each
# isolated vertex as the one-vertex cycle [v] (`dcel diff --isolated-as-cycles`
# agrees; without it, a note names the option).
import json
import _correct
import dcel_faces


def answer(text):
    points, edges = _correct.graph(text)
    cycles = dcel_faces.faces(points, edges)
    cycles += [[v] for v, d in enumerate(_correct.degrees(points, edges)) if d == 0]
    return json.dumps({"faces": cycles})


_correct.serve(answer)
