"""Shared by the test impls here: the correct answer (examples/python) and the
protocol loop, so that each impl states only its one misbehaviour."""
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "examples", "python"))
import dcel_faces  # noqa: E402


def graph(text):
    return dcel_faces.read_graph(text)


def degrees(points, edges):
    d = [0] * len(points)
    for u, v in edges:
        d[u] += 1
        d[v] += 1
    return d


def serve(answer_text):
    """answer_text(graph_json) -> the text to print (without the newline)."""
    if "--stream" in sys.argv[1:]:
        for line in sys.stdin:
            if line.strip():
                sys.stdout.write(answer_text(line) + "\n")
                sys.stdout.flush()
    else:
        sys.stdout.write(answer_text(sys.stdin.read()) + "\n")


def correct(text):
    points, edges = graph(text)
    return json.dumps({"faces": dcel_faces.faces(points, edges)})
