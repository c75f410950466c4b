#!/usr/bin/env python3
# Test impl (polygons kind): the bounded faces as polygons, plus one polygon
# too many per component: its outer boundary (the unbounded face's hole,
# walked the other way), as a polygonizer that mistakes the outside for a face.
import json
import _correct
import _reference


def area2(points, ring):
    return sum(points[a][0] * points[b][1] - points[b][0] * points[a][1]
               for a, b in zip(ring, ring[1:] + ring[:1]))


def answer(text):
    polygons = _reference.answer(text, "polygons")["polygons"]
    d = _reference.dump(text)
    points = d["vertices"]
    for hole in d["faces"][0]["inner"]:
        ring = list(reversed(_reference.walk(d, hole)))
        if area2(points, ring) != 0:  # a tree encloses nothing
            polygons.append([ring])
    return json.dumps({"polygons": polygons})


_correct.serve(answer)
