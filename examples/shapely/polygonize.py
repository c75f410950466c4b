#!/usr/bin/env python3
"""shapely's polygonize (GEOS) behind the `dcel diff` protocol: the template
for wrapping a library whose answer is polygons.

    polygonize.py            one graph JSON on stdin, one answer on stdout
    polygonize.py --stream   one graph per line in, one answer per line out

An adapter has three parts, and only the middle one is about the library:
  1. read the graph: {"vertices": [[x, y], ...], "edges": [[u, v], ...]} or
     the positional form [[[x, y], ...], [[u, v], ...]];
  2. call the library the way its users do: here one LineString per edge,
     then shapely.ops.polygonize, which returns the bounded faces as
     polygons with holes (dangling edges and bridges belong to none);
  3. print the result as it comes, here GeoJSON (shapely.geometry.mapping),
     which `dcel diff --answer polygons` reads. Coordinates are printed as
     the library returns them; dcel matches them to the graph's vertices
     exactly.

GEOS does not promise an orientation for polygonize's rings (it returns
shells clockwise), so check it with --unoriented:

    build/bin/dcel diff --impl 'examples/shapely/polygonize.py' --stream --unoriented
"""
import json
import sys

from shapely.geometry import LineString, mapping
from shapely.ops import polygonize


def read_graph(text):
    doc = json.loads(text)
    if isinstance(doc, list):  # the positional form
        doc = {"vertices": doc[0], "edges": doc[1]}
    points = [(float(x), float(y)) for x, y in doc["vertices"]]
    return points, [(int(u), int(v)) for u, v in doc["edges"]]


def answer(text):
    points, edges = read_graph(text)
    lines = [LineString([points[u], points[v]]) for u, v in edges]
    polygons = [mapping(p) for p in polygonize(lines)]
    return json.dumps({"type": "FeatureCollection",
                       "features": [{"type": "Feature", "properties": {}, "geometry": g} for g in polygons]})


def main():
    if "--stream" in sys.argv[1:]:
        for line in sys.stdin:
            if line.strip():
                sys.stdout.write(answer(line) + "\n")
                sys.stdout.flush()
    else:
        sys.stdout.write(answer(sys.stdin.read()) + "\n")


if __name__ == "__main__":
    main()
