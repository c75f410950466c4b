#!/usr/bin/env python3
"""Self-test of examples/python/dcel_session.py and its planted-bug variants
(session_*.py here): hand-worked sessions, each answer derived by hand in the
comments, run through each program with --stream (and once without).

    /usr/bin/python3 tests/data/impls/session_selftest.py     # prints "ok", or what failed (exit 1)

The correct program must give every expected answer and state; each variant
must differ on exactly the sessions its bug shows in (so it is otherwise
right on all of them).

How answers are compared, as dcel diff --sessions compares them: a face is
written here by its outer cycle, F(v0, v1, ...) (U: the unbounded face); a
name [u, v] in an answer is resolved through the answer's own state at that
step (every session asks for "each_step" and starts with an edit, so there
is always one): the record that has half-edge u -> v on one of its cycles.
Cycles are compared up to rotation, holes and isolated vertices as sets,
neighbours as a set, stab in order with consecutive repeats merged, an edge
in either order, refusals by kind only (the message is free).

Next rule used by hand below: at each vertex, list its neighbours by the
angle of the direction to them; next(a -> b) leaves b towards the neighbour
just clockwise (next smaller angle, wrapping) of the direction back to a.
"""
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ORACLE = os.path.join(HERE, "..", "..", "..", "examples", "python", "dcel_session.py")
PYTHON = sys.executable or "/usr/bin/python3"


def F(*cycle):
    return canon(list(cycle))


U = None
OK = {"ok": True}
ERR = {"error": ""}


def canon(cycle):
    """The cycle as its smallest rotation (a repeated first vertex at the end closes it)."""
    c = list(cycle)
    if len(c) >= 2 and c[0] == c[-1]:
        c.pop()
    return min(tuple(c[i:] + c[:i]) for i in range(len(c))) if c else ()


def state(*faces, vertices=None):
    """faces: (outer or None, [holes], [isolated])."""
    return {"faces": sorted(((None if o is None else canon(o), sorted(canon(h) for h in hs), sorted(iso))
                             for o, hs, iso in faces), key=sort_key), "vertices": vertices}


def sort_key(rec):
    return (rec[0] is not None, rec[0] or (), rec[1], rec[2])


# ---------------------------------------------------------------- the sessions

SESSIONS = []

# S1 (tests/test_session.cpp's session): a 4x4 square 0 1 2 3 with the
# isolated vertex 4 at (3, 1).
#   3 (0,4) ----- 2 (4,4)
#     |             |
#     |          4  |
#   0 (0,0) ----- 1 (4,0)
# 0: the diagonal 0-2. New face: left of 0->2, the upper triangle 0 2 3; the
#    square keeps the lower one, 0 1 2. Vertex 4 (y < x) is in the lower one.
# 1: (3, 1) is vertex 4.   2: (1, 3) is in the upper triangle.
# 3: (2, 2) is inside the diagonal.
# 4: the upper triangle's neighbours: across 0->2 the lower triangle, across
#    2->3 and 3->0 the unbounded face.
# 5: the diagonal removed (named backwards): one square again, 4 in it.
# 6: 4 removed.  7: a vertex at (2, 2): id 5 (4 is never reused), in the square.
# 8: vertex 9 does not exist: refused.  9: the square around (1, 1), no holes.
# 10: y = 2 from x = -1 to 5: unbounded, crosses 3-0, the square (through
#     the isolated vertex 5 at (2, 2): the same face, merged), crosses 1-2,
#     unbounded.
SESSIONS.append(dict(
    name="S1 square, isolated vertex, diagonal added and removed",
    doc={"vertices": [[0, 0], [4, 0], [4, 4], [0, 4], [3, 1]],
         "edges": [[0, 1], [1, 2], [2, 3], [3, 0]],
         "steps": [{"add_edge": {"from": 0, "to": 2}},
                   {"locate": {"at": [3, 1]}},
                   {"locate": {"at": [1, 3]}},
                   {"locate": {"at": [2, 2]}},
                   {"neighbours": {"at": [1, 3]}},
                   {"remove_edge": {"edge": [2, 0]}},
                   {"remove_isolated_vertex": {"vertex": 4}},
                   {"add_vertex": {"at": [2, 2]}},
                   {"add_edge": {"from": 5, "to": 9}},
                   {"face_boundary": {"at": [1, 1]}},
                   {"stab": {"from": [-1, 2], "to": [5, 2]}}]},
    steps=[OK, {"vertex": 4}, {"face": F(0, 2, 3)}, {"edge": (0, 2)}, {"neighbours": [F(0, 1, 2), U]},
           OK, OK, OK, ERR, {"boundary": F(0, 1, 2, 3), "outer": [0, 1, 2, 3], "holes": []},
           {"stab": [U, F(0, 1, 2, 3), U]}],
    states={0: state((None, [[0, 3, 2, 1]], []), ([0, 2, 3], [], []), ([0, 1, 2], [], [4])),
            10: state((None, [[0, 3, 2, 1]], []), ([0, 1, 2, 3], [], [5]),
                      vertices=[[0, 0], [4, 0], [4, 4], [0, 4], None, [2, 2]])},
))

# S2: a 10x10 square 0 1 2 3, a triangle 4 (4,4) 5 (6,4) 6 (5,6) inside it
# (a hole of the square's face, walked 4 6 5 with the square's face on its
# left), then a quadrilateral 10 11 12 13 drawn around the triangle from
# corner 0, closed by the edge 13-10.
#   0: (1, 5) -> 7, in the square's face.  1: (3, 5) -> 8, in it too.
#   2: (5, 5) -> 9, inside the triangle.
#   3: (5, 4.5) is in the triangle (a face inside a hole of the square's face).
#   4: the square's face around (0.5, 0.5): outer 0 1 2 3, the hole 4 6 5.
#   5-8: dangling path 0 - 10 (2,2) - 11 (8,2) - 12 (8,8) - 13 (2,8).
#   9: 13-10 (x = 2, from y = 8 down to 2) closes the quad; both ends on the
#      square face's outer cycle, so the new face is left of 13->10: east of
#      x = 2, the quad 10 11 12 13. It takes the triangle (hole) and 8 (3, 5);
#      7 (1, 5) stays. The square face's outer cycle now, by the next rule:
#      3->0, at 0 {1: 0 deg, 10: 45, 3: 90}: cw of 0->3 is 0->10; at 10
#      {11: 0, 13: 90, 0: 225}: cw of 10->0 is 10->13; 13->12, 12->11,
#      11->10; at 10 cw of 10->11 wraps to 10->0; at 0 cw of 0->10 is 0->1;
#      1->2->3: [0, 10, 13, 12, 11, 10, 0, 1, 2, 3].
#  10: 7-8 crosses 10-13 at (2, 5): refused.
#  11: 8-9 crosses the triangle's edge 6-4 at (4.5, 5): refused.
#  12: (3, 5) is vertex 8.  13: (3, 3) is in the quad.
#  14: the quad's neighbours: the square face (across its outer cycle) and
#      the triangle (across its hole).
#  15: the square face's: the unbounded face and the quad (across 0-10: itself).
#  16: y = 5 from vertex 7 to vertex 9: square face, crosses 13-10, quad
#      (through vertex 8: same face), crosses 4-6, triangle.
#  17: 13-10 removed: the quad opens into the square face, which gets the
#      triangle and 8 back; its outer cycle walks the path 0 10 11 12 13 out
#      and back: [0, 10, 11, 12, 13, 12, 11, 10, 0, 1, 2, 3].
SQUARE_FACE = F(0, 10, 13, 12, 11, 10, 0, 1, 2, 3)
SESSIONS.append(dict(
    name="S2 triangle hole in a square, an edge closes a cycle around it",
    doc={"vertices": [[0, 0], [10, 0], [10, 10], [0, 10], [4, 4], [6, 4], [5, 6]],
         "edges": [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 4]],
         "steps": [{"add_vertex": {"at": [1, 5]}},
                   {"add_vertex": {"at": [3, 5]}},
                   {"add_vertex": {"at": [5, 5]}},
                   {"locate": {"at": [5, 4.5]}},
                   {"face_boundary": {"at": [0.5, 0.5]}},
                   {"add_edge_to_point": {"from": 0, "to": [2, 2]}},
                   {"add_edge_to_point": {"from": 10, "to": [8, 2]}},
                   {"add_edge_to_point": {"from": 11, "to": [8, 8]}},
                   {"add_edge_to_point": {"from": 12, "to": [2, 8]}},
                   {"add_edge": {"from": 13, "to": 10}},
                   {"add_edge": {"from": 7, "to": 8}},
                   {"add_edge": {"from": 8, "to": 9}},
                   {"locate": {"at": [3, 5]}},
                   {"locate": {"at": [3, 3]}},
                   {"neighbours": {"at": [3, 3]}},
                   {"neighbours": {"at": [1, 9]}},
                   {"stab": {"from": [1, 5], "to": [5, 5]}},
                   {"remove_edge": {"edge": [13, 10]}}]},
    steps=[OK, OK, OK, {"face": F(4, 5, 6)},
           {"boundary": F(0, 1, 2, 3), "outer": [0, 1, 2, 3], "holes": [[4, 6, 5]]},
           OK, OK, OK, OK, OK, ERR, ERR, {"vertex": 8}, {"face": F(10, 11, 12, 13)},
           {"neighbours": [SQUARE_FACE, F(4, 5, 6)]}, {"neighbours": [U, F(10, 11, 12, 13)]},
           {"stab": [SQUARE_FACE, F(10, 11, 12, 13), F(4, 5, 6)]}, OK],
    states={2: state((None, [[0, 3, 2, 1]], []), ([0, 1, 2, 3], [[4, 6, 5]], [7, 8]), ([4, 5, 6], [], [9])),
            9: state((None, [[0, 3, 2, 1]], []), ([0, 10, 13, 12, 11, 10, 0, 1, 2, 3], [], [7]),
                     ([10, 11, 12, 13], [[4, 6, 5]], [8]), ([4, 5, 6], [], [9])),
            17: state((None, [[0, 3, 2, 1]], []), ([0, 10, 11, 12, 13, 12, 11, 10, 0, 1, 2, 3], [[4, 6, 5]], [7, 8]),
                      ([4, 5, 6], [], [9]),
                      vertices=[[0, 0], [10, 0], [10, 10], [0, 10], [4, 4], [6, 4], [5, 6], [1, 5], [3, 5], [5, 5],
                                [2, 2], [8, 2], [8, 8], [2, 8]])},
))

# S3: bridges. The square and triangle of S2 joined by the bridge 0-4 (the
# doc's examples/check/graph.json shape): the square face's outer cycle is
# [0, 1, 2, 3, 0, 4, 6, 5, 4] (at 0 {1: 0, 4: 45, 3: 90}: 3->0->4; at 4
# {5: 0, 6: 63, 0: 225}: 0->4->6; 6->5; 5->4; at 4 cw of 4->5 wraps to 4->0).
# Far right, two triangles A = 7 (20,0) 8 (24,0) 9 (22,3) and B = 10 (30,0)
# 11 (34,0) 12 (32,3) joined by the bridge 8-10: one hole of the unbounded
# face, [7, 9, 8, 10, 12, 11, 10, 8].
#   0: remove [4, 0]: the triangle breaks off (it holds the first end, 4) and
#      becomes a hole 4 6 5 of the square face; its outer cycle is 0 1 2 3.
#   1: the square face around (1, 2): outer 0 1 2 3, the hole 4 6 5.
#   2: 0-4 again: the hole joins the outer cycle (no new face).
#   3: remove [0, 4]: the same as 0, named from the square's end.
#   4: as 1.
#   5: remove [10, 8], a bridge on a hole's cycle: two holes of the unbounded
#      face, [7, 9, 8] and [10, 12, 11].
SESSIONS.append(dict(
    name="S3 bridges removed",
    doc={"vertices": [[0, 0], [10, 0], [10, 10], [0, 10], [4, 4], [6, 4], [5, 6],
                      [20, 0], [24, 0], [22, 3], [30, 0], [34, 0], [32, 3]],
         "edges": [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 4], [0, 4],
                   [7, 8], [8, 9], [9, 7], [10, 11], [11, 12], [12, 10], [8, 10]],
         "steps": [{"remove_edge": {"edge": [4, 0]}},
                   {"face_boundary": {"at": [1, 2]}},
                   {"add_edge": {"from": 0, "to": 4}},
                   {"remove_edge": {"edge": [0, 4]}},
                   {"face_boundary": {"at": [1, 2]}},
                   {"remove_edge": {"edge": [10, 8]}}]},
    steps=[OK, {"boundary": F(0, 1, 2, 3), "outer": [0, 1, 2, 3], "holes": [[4, 6, 5]]}, OK, OK,
           {"boundary": F(0, 1, 2, 3), "outer": [0, 1, 2, 3], "holes": [[4, 6, 5]]}, OK],
    states={0: state((None, [[0, 3, 2, 1], [7, 9, 8, 10, 12, 11, 10, 8]], []), ([0, 1, 2, 3], [[4, 6, 5]], []),
                     ([4, 5, 6], [], []), ([7, 8, 9], [], []), ([10, 11, 12], [], [])),
            2: state((None, [[0, 3, 2, 1], [7, 9, 8, 10, 12, 11, 10, 8]], []), ([0, 1, 2, 3, 0, 4, 6, 5, 4], [], []),
                     ([4, 5, 6], [], []), ([7, 8, 9], [], []), ([10, 11, 12], [], [])),
            5: state((None, [[0, 3, 2, 1], [7, 9, 8], [10, 12, 11]], []), ([0, 1, 2, 3], [[4, 6, 5]], []),
                     ([4, 5, 6], [], []), ([7, 8, 9], [], []), ([10, 11, 12], [], []))},
))

# S4: splits and merges on the triangle 0 (0,0) 1 (4,0) 2 (0,4) (T: outer
# 0 1 2; the unbounded face's hole 0 2 1), then queries on edges and vertices.
#   0: split 0-1 at (2, 0) -> 3: T is 0 3 1 2, the hole 0 2 1 3.
#   1: split 1-3 at (3, 0) -> 4: T is 0 3 4 1 2, the hole 0 2 1 4 3.
#   2: there is no edge 0-1 now: refused.  3: (1, 1) is not on 0-3: refused.
#   4: merge at 3 (between 0 and 4): T is 0 4 1 2.
#   5: merge at 2: its neighbours 0 and 1 are not collinear with it: refused.
#   6: merge at 4: T is 0 1 2 again.
#   7: (1, 1) -> 5, isolated in T.  8: merge at 5: no edges: refused.
#   9: 5 removed.  10: 5 again: removed already: refused.
#  11: (1, 1) -> 6 (5 is not reused).  12: (2, 0) is inside 0-1.
#  13: y = 0 from x = -1 to 5: unbounded, along 0-1 (no face), unbounded:
#      merged, [U].
#  14: y = x from (-1, -1) to (3, 3): unbounded, vertex 0, T (through the
#      isolated 6 at (1, 1): merged), crosses 1-2 at (2, 2), unbounded.
#  15: from == to at vertex 6: no face.  16: from == to inside T: [T].
#  17: (1, 0) to (3, 0): along 0-1 only: no face.
#  18: x = 2 from (2, 0) (inside 0-1) up to (2, 3): T, crosses 1-2, unbounded.
#  19: T's neighbours: the unbounded face.  20: the unbounded face's: T.
#  21-22: at a vertex and on an edge, face_boundary and neighbours answer as
#      locate does.  23-24: (0, 2) is inside the vertical edge 0-2.
#  25: x = 0 from y = -1 to 5: along 0-2: unbounded only.
#  26: y = 2 from x = -1 to 1: crosses 0-2 into T.
T = F(0, 1, 2)
SESSIONS.append(dict(
    name="S4 splits, merges, stab along edges and through vertices",
    doc={"vertices": [[0, 0], [4, 0], [0, 4]], "edges": [[0, 1], [1, 2], [2, 0]],
         "steps": [{"split_edge": {"edge": [0, 1], "at": [2, 0]}},
                   {"split_edge": {"edge": [1, 3], "at": [3, 0]}},
                   {"split_edge": {"edge": [0, 1], "at": [1, 0]}},
                   {"split_edge": {"edge": [0, 3], "at": [1, 1]}},
                   {"merge_collinear_edges": {"vertex": 3}},
                   {"merge_collinear_edges": {"vertex": 2}},
                   {"merge_collinear_edges": {"vertex": 4}},
                   {"add_vertex": {"at": [1, 1]}},
                   {"merge_collinear_edges": {"vertex": 5}},
                   {"remove_isolated_vertex": {"vertex": 5}},
                   {"remove_isolated_vertex": {"vertex": 5}},
                   {"add_vertex": {"at": [1, 1]}},
                   {"locate": {"at": [2, 0]}},
                   {"stab": {"from": [-1, 0], "to": [5, 0]}},
                   {"stab": {"from": [-1, -1], "to": [3, 3]}},
                   {"stab": {"from": [1, 1], "to": [1, 1]}},
                   {"stab": {"from": [0.5, 0.5], "to": [0.5, 0.5]}},
                   {"stab": {"from": [1, 0], "to": [3, 0]}},
                   {"stab": {"from": [2, 0], "to": [2, 3]}},
                   {"neighbours": {"at": [0.5, 0.5]}},
                   {"neighbours": {"at": [5, 5]}},
                   {"face_boundary": {"at": [0, 0]}},
                   {"neighbours": {"at": [2, 0]}},
                   {"locate": {"at": [0, 2]}},
                   {"face_boundary": {"at": [0, 2]}},
                   {"stab": {"from": [0, -1], "to": [0, 5]}},
                   {"stab": {"from": [-1, 2], "to": [1, 2]}}]},
    steps=[OK, OK, ERR, ERR, OK, ERR, OK, OK, ERR, OK, ERR, OK, {"edge": (0, 1)},
           {"stab": [U]}, {"stab": [U, T, U]}, {"stab": []}, {"stab": [T]}, {"stab": []}, {"stab": [T, U]},
           {"neighbours": [U]}, {"neighbours": [T]}, {"vertex": 0}, {"edge": (0, 1)},
           {"edge": (0, 2)}, {"edge": (0, 2)}, {"stab": [U]}, {"stab": [U, T]}],
    states={0: state((None, [[0, 2, 1, 3]], []), ([0, 3, 1, 2], [], []),
                     vertices=[[0, 0], [4, 0], [0, 4], [2, 0]]),
            1: state((None, [[0, 2, 1, 4, 3]], []), ([0, 3, 4, 1, 2], [], [])),
            4: state((None, [[0, 2, 1, 4]], []), ([0, 4, 1, 2], [], []),
                     vertices=[[0, 0], [4, 0], [0, 4], None, [3, 0]]),
            7: state((None, [[0, 2, 1]], []), ([0, 1, 2], [], [5]),
                     vertices=[[0, 0], [4, 0], [0, 4], None, None, [1, 1]]),
            11: state((None, [[0, 2, 1]], []), ([0, 1, 2], [], [6]),
                      vertices=[[0, 0], [4, 0], [0, 4], None, None, None, [1, 1]])},
))

# S5: refusals, and edges along the axes. The 4x4 square 0 1 2 3, the
# isolated 4 (1, 3), the lone edge 5 (6,2) - 6 (8,2), the isolated 7 (10, 2).
#   0: the diagonal 0-2: the new face is left of 0->2, the triangle 0 2 3,
#      and takes 4 (1, 3) (y > x); the square's face keeps 0 1 2.
#   1: 1-3 crosses 0-2.  2: u == v.  3: 0-1 exists.  4: no vertex 99.
#   5: (2, 0) is inside 0-1.  6: (4, 4) is vertex 2.
#   7: 6 to (5, 2) overlaps 5-6 (and passes through 5).
#   8: 6 to (12, 2) passes through the isolated 7.
#   9: 6-7, horizontal, meets 5-6 only at their shared end 6: accepted.
#  10: (4, 2) is inside 1-2.  11: (0, 0) is vertex 0.  12: no edge 1-3.
#  13: 0 has edges.  14: a coordinate that is not finite (written Infinity;
#      Python reads it, and the step is refused; the reference's own reader
#      would reject such a document before any step runs).
#  15: split 5-6 at (7, 2) -> 8: the path 5 8 6 7, one cycle
#      [5, 8, 6, 7, 6, 8] (a hole of the unbounded face).
SESSIONS.append(dict(
    name="S5 refusals and axis-parallel edges",
    doc={"vertices": [[0, 0], [4, 0], [4, 4], [0, 4], [1, 3], [6, 2], [8, 2], [10, 2]],
         "edges": [[0, 1], [1, 2], [2, 3], [3, 0], [5, 6]],
         "steps": [{"add_edge": {"from": 0, "to": 2}},
                   {"add_edge": {"from": 1, "to": 3}},
                   {"add_edge": {"from": 0, "to": 0}},
                   {"add_edge": {"from": 0, "to": 1}},
                   {"add_edge": {"from": 0, "to": 99}},
                   {"add_edge_to_point": {"from": 1, "to": [2, 0]}},
                   {"add_edge_to_point": {"from": 1, "to": [4, 4]}},
                   {"add_edge_to_point": {"from": 6, "to": [5, 2]}},
                   {"add_edge_to_point": {"from": 6, "to": [12, 2]}},
                   {"add_edge": {"from": 6, "to": 7}},
                   {"add_vertex": {"at": [4, 2]}},
                   {"add_vertex": {"at": [0, 0]}},
                   {"remove_edge": {"edge": [1, 3]}},
                   {"remove_isolated_vertex": {"vertex": 0}},
                   {"add_vertex": {"at": [1e999, 0]}},
                   {"split_edge": {"edge": [5, 6], "at": [7, 2]}}]},
    steps=[OK, ERR, ERR, ERR, ERR, ERR, ERR, ERR, ERR, OK, ERR, ERR, ERR, ERR, ERR, OK],
    states={0: state((None, [[0, 3, 2, 1], [5, 6]], [7]), ([0, 2, 3], [], [4]), ([0, 1, 2], [], [])),
            15: state((None, [[0, 3, 2, 1], [5, 8, 6, 7, 6, 8]], []), ([0, 2, 3], [], [4]), ([0, 1, 2], [], []),
                      vertices=[[0, 0], [4, 0], [4, 4], [0, 4], [1, 3], [6, 2], [8, 2], [10, 2], [7, 2]])},
))

# Where each planted bug shows (and nowhere else):
VARIANTS = {
    "session_holes_stay.py": {"S2", "S5"},          # S2 step 9 (triangle, 8), S5 step 0 (4)
    "session_stale_outer.py": {"S3"},               # S3 step 0 (first end 4 in the part that broke off)
    "session_locate_vertical.py": {"S4"},           # S4 steps 23, 24 on the vertical 0-2
    "session_locate_ignores_holes.py": {"S2"},      # S2 step 3: in the triangle, a hole of the square's face
    "session_split_twin.py": {"S4", "S5"},          # S4 step 0, S5 step 15
    "session_refuses_collinear.py": {"S2", "S5"},   # S2 step 9 (vertical), S5 step 9 (horizontal)
}


# ---------------------------------------------------------------- comparing

def resolve(name, st):
    """The face a name denotes, by the answer's own state st: F(outer) or U; "?" when none."""
    if name is None:
        return U
    if st is None or not isinstance(name, list) or len(name) < 2:
        return "?"
    found = set()
    for rec in st["faces"]:
        cycles = ([rec["outer"]] if rec["outer"] is not None else []) + rec["holes"]
        for i in range(len(name) - 1):
            a, b = name[i], name[i + 1]
            if any(c[k] == a and c[(k + 1) % len(c)] == b for c in cycles for k in range(len(c))):
                found.add(U if rec["outer"] is None else canon(rec["outer"]))
    return found.pop() if len(found) == 1 else "?"


def normal_step(got, op, st):
    """A step's answer in the comparable form of the expectations above."""
    if "error" in got:
        return ERR
    if "ok" in got:
        return OK
    if "vertex" in got:
        return {"vertex": got["vertex"]}
    if "edge" in got:
        return {"edge": tuple(sorted(got["edge"]))}
    if "outer" in got:
        return {"boundary": resolve(got["face"], st) if "face" in got else "(none)",
                "outer": None if got["outer"] is None else canon(got["outer"]),
                "holes": sorted(canon(h) for h in got["holes"])}
    if "faces" in got:
        faces = [resolve(f, st) for f in got["faces"]]
        if op == "stab":
            return {"stab": [f for i, f in enumerate(faces) if i == 0 or faces[i - 1] != f]}
        return {"neighbours": sorted(set(faces), key=lambda f: (f is not None, f or ()))}
    if "face" in got:
        return {"face": resolve(got["face"], st)}
    return {"unknown": got}


def normal_expected(want, op):
    if "edge" in want:
        return {"edge": tuple(sorted(want["edge"]))}
    if "boundary" in want:
        return {"boundary": want["boundary"], "outer": canon(want["outer"]) if want["outer"] else None,
                "holes": sorted(canon(h) for h in want["holes"])}
    if "neighbours" in want:
        return {"neighbours": sorted(set(want["neighbours"]), key=lambda f: (f is not None, f or ()))}
    return want


def normal_state(st):
    return {"faces": sorted(((None if r["outer"] is None else canon(r["outer"]), sorted(canon(h) for h in r["holes"]),
                              sorted(r["isolated"])) for r in st["faces"]), key=sort_key),
            "vertices": st.get("vertices")}


def differences(session, answer):
    """What is wrong with an answer to a session: a list of lines."""
    out = []
    steps = session["doc"]["steps"]
    if len(answer.get("steps", [])) != len(steps):
        return ["%d step answers for %d steps" % (len(answer.get("steps", [])), len(steps))]
    st = None
    for i, (step, got) in enumerate(zip(steps, answer["steps"])):
        (op, _), = step.items()
        if op not in ("locate", "face_boundary", "neighbours", "stab"):
            if "state" not in got:
                out.append("step %d (%s): no state with each_step" % (i, op))
                continue
            st = got["state"]
        have = normal_step(got, op, st)
        want = normal_expected(session["steps"][i], op)
        if have != want:
            out.append("step %d (%s): %s, expected %s" % (i, op, have, want))
        if i in session["states"]:
            exp = session["states"][i]
            exp = {"faces": sorted(exp["faces"], key=sort_key), "vertices": exp["vertices"]}
            have_st = normal_state(st)
            if exp["vertices"] is None:
                have_st["vertices"] = None
            if have_st != exp:
                out.append("state after step %d: %s, expected %s" % (i, have_st, exp))
    if answer.get("state") != st:
        out.append("the final state is not the state after the last edit")
    return out


def run(program, docs, stream=True):
    cmd = [PYTHON, program] + (["--stream"] if stream else [])
    text = "".join(json.dumps(d) + "\n" for d in docs)
    p = subprocess.run(cmd, input=text, capture_output=True, text=True, timeout=120)
    if p.returncode != 0:
        raise RuntimeError("%s exited %d: %s" % (program, p.returncode, p.stderr.strip()[-2000:]))
    lines = [line for line in p.stdout.splitlines() if line.strip()]
    return [json.loads(line) for line in lines]


def main():
    failures = []
    docs = [dict(s["doc"], each_step=True) for s in SESSIONS]

    try:
        answers = run(ORACLE, docs)
    except (RuntimeError, subprocess.TimeoutExpired, ValueError) as e:
        print("dcel_session.py: %s" % e)
        sys.exit(1)
    if len(answers) != len(docs):
        failures.append("dcel_session.py --stream: %d answers for %d sessions" % (len(answers), len(docs)))
    for s, a in zip(SESSIONS, answers):
        for line in differences(s, a):
            failures.append("dcel_session.py, %s: %s" % (s["name"], line))
    # Without each_step: the same answers, with no states but the last; and one process per session.
    for s, a in zip(SESSIONS, answers):
        try:
            plain = run(ORACLE, [s["doc"]], stream=False)[0]
        except (RuntimeError, subprocess.TimeoutExpired, ValueError, IndexError) as e:
            failures.append("dcel_session.py without --stream, %s: %s" % (s["name"], e))
            continue
        want = {"steps": [{k: v for k, v in step.items() if k != "state"} for step in a["steps"]], "state": a["state"]}
        if plain != want:
            failures.append("dcel_session.py without each_step or --stream, %s: answers differ" % s["name"])

    for program, where in VARIANTS.items():
        try:
            got = run(os.path.join(HERE, program), docs)
        except (RuntimeError, subprocess.TimeoutExpired, ValueError) as e:
            failures.append("%s: %s" % (program, e))
            continue
        differs = {s["name"].split()[0] for s, a in zip(SESSIONS, got) if differences(s, a)}
        if not differs:
            failures.append("%s: agrees on every session (its bug is never seen)" % program)
        elif differs != where:
            failures.append("%s: differs on %s, expected on %s" % (program, sorted(differs), sorted(where)))
        for s, a in zip(SESSIONS, got):
            if s["name"].split()[0] in where and os.environ.get("SESSION_SELFTEST_VERBOSE"):
                print("%s, %s:\n  %s" % (program, s["name"], "\n  ".join(differences(s, a))))

    if failures:
        print("\n".join(failures))
        sys.exit(1)
    print("ok")


if __name__ == "__main__":
    main()
