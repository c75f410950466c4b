#!/usr/bin/env python3
"""SpatiaLite's ISO SQL/MM topology behind the `dcel diff` protocol: a
library whose own answer is a half-edge structure (edges with next-left and
next-right pointers), checked as the `faces` kind.

    topology.py              one graph JSON on stdin, one answer on stdout
    topology.py --stream     one graph per line in, one answer per line out
    topology.py --polygons   the faces as ST_GetFaceGeometry returns them
                             (GeoJSON polygons with holes) instead

The three parts of an adapter (examples/shapely/polygonize.py is the
template):
  1. read the graph;
  2. call the library as its users do: CreateTopology, ST_AddIsoNode for
     each vertex, then ST_AddEdgeNewFaces for each edge, which splits a face
     in two when the edge closes a cycle (Debian's libsqlite3-mod-spatialite,
     loaded into Python's sqlite3);
  3. print what the library stores. An edge e runs from start_node to
     end_node; the half-edge +e has left_face on its left and is followed by
     next_left_edge, the half-edge -e runs back with right_face on its left
     and is followed by next_right_edge (a signed edge id: -k is edge k
     walked from its end). Walking those pointers gives the boundary cycles,
     printed as node ids mapped back to the graph's vertex ids. With
     --polygons, each bounded face's geometry instead, read from its WKB.

A graph the library refuses (an exception from SQLite) is answered
{"refused": message}, so dcel diff groups refusals by message without
restarting the adapter. Each graph gets its own topology, dropped after.

    build/bin/dcel diff --impl '/usr/bin/python3 examples/spatialite/topology.py' --stream --answer faces
"""
import json
import sqlite3
import struct
import sys


def read_graph(text):
    doc = json.loads(text)
    if isinstance(doc, list):  # the positional form
        doc = {"vertices": doc[0], "edges": doc[1]}
    points = [(float(x), float(y)) for x, y in doc["vertices"]]
    return points, [(int(u), int(v)) for u, v in doc["edges"]]


def connect():
    db = sqlite3.connect(":memory:")
    db.enable_load_extension(True)
    db.load_extension("mod_spatialite")
    db.execute("SELECT InitSpatialMetadata(1)")
    return db


def build_topology(db, name, points, edges):
    """The node id of each vertex; raises sqlite3.Error when refused."""
    db.execute("SELECT CreateTopology(?, 0, 0, 0)", (name,))
    node = [db.execute("SELECT ST_AddIsoNode(?, NULL, MakePoint(?, ?, 0))", (name, x, y)).fetchone()[0]
            for x, y in points]
    for u, v in edges:
        (x0, y0), (x1, y1) = points[u], points[v]
        db.execute("SELECT ST_AddEdgeNewFaces(?, ?, ?, MakeLine(MakePoint(?, ?, 0), MakePoint(?, ?, 0)))",
                   (name, node[u], node[v], x0, y0, x1, y1))
    return node


def cycles(db, name, node):
    """The orbits of next over the half-edges +e and -e, as vertex ids."""
    vertex_of = {n: i for i, n in enumerate(node)}
    origin, following = {}, {}
    for e, start, end, next_left, next_right in db.execute(
            f'SELECT edge_id, start_node, end_node, next_left_edge, next_right_edge FROM "{name}_edge"'):
        origin[e], following[e] = start, next_left
        origin[-e], following[-e] = end, next_right
    seen, out = set(), []
    for start in sorted(origin):
        if start in seen:
            continue
        cycle, h = [], start
        while h not in seen and h in origin:
            seen.add(h)
            cycle.append(vertex_of.get(origin[h], -1))
            h = following[h]
        out.append(cycle)
    return out


def wkb_polygons(blob):
    """The polygons of a WKB Polygon or MultiPolygon, each a list of rings
    of [x, y]: read from the binary form, since the text forms round the
    coordinates."""
    def read(offset):
        order = "<" if blob[offset] == 1 else ">"
        (kind,) = struct.unpack_from(order + "I", blob, offset + 1)
        offset += 5
        if kind % 1000 == 6:
            (count,) = struct.unpack_from(order + "I", blob, offset)
            offset += 4
            out = []
            for _ in range(count):
                polygons, offset = read(offset)
                out += polygons
            return out, offset
        if kind % 1000 != 3:
            raise ValueError(f"WKB geometry type {kind} is not a polygon")
        width = 3 if kind // 1000 in (1, 2) else 4 if kind // 1000 == 3 else 2
        (ring_count,) = struct.unpack_from(order + "I", blob, offset)
        offset += 4
        rings = []
        for _ in range(ring_count):
            (n,) = struct.unpack_from(order + "I", blob, offset)
            offset += 4
            values = struct.unpack_from(order + "d" * (width * n), blob, offset)
            offset += 8 * width * n
            rings.append([[values[i], values[i + 1]] for i in range(0, width * n, width)])
        return [rings], offset
    return read(0)[0]


def face_polygons(db, name):
    faces = [f for (f,) in db.execute(f'SELECT face_id FROM "{name}_face" WHERE face_id > 0')]
    polygons = []
    for f in faces:
        (blob,) = db.execute("SELECT AsBinary(ST_GetFaceGeometry(?, ?))", (name, f)).fetchone()
        if blob is not None:
            polygons += wkb_polygons(blob)
    return {"polygons": polygons}


def answer(db, text, number, polygons):
    points, edges = read_graph(text)
    name = f"t{number}"
    try:
        node = build_topology(db, name, points, edges)
        result = face_polygons(db, name) if polygons else {"faces": cycles(db, name, node)}
    except sqlite3.Error as e:
        result = {"refused": str(e)}
    try:
        db.execute("SELECT DropTopology(?)", (name,))
    except sqlite3.Error:
        pass  # a topology half made is dropped with the connection
    return json.dumps(result)


def main():
    polygons = "--polygons" in sys.argv[1:]
    db = connect()
    if "--stream" in sys.argv[1:]:
        for number, line in enumerate(sys.stdin):
            if line.strip():
                sys.stdout.write(answer(db, line, number, polygons) + "\n")
                sys.stdout.flush()
    else:
        sys.stdout.write(answer(db, sys.stdin.read(), 0, polygons) + "\n")


if __name__ == "__main__":
    main()
