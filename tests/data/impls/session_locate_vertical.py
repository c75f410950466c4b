#!/usr/bin/env python3
# Test impl (sessions): a point exactly inside a vertical edge is located in
# the face on the edge's left (the face left of the edge walked upwards, so
# west of it) instead of on the edge: in locate, and in face_boundary and
# neighbours, which then answer for that face.
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "examples", "python"))
import dcel_session as ds  # noqa: E402


class LocateVertical(ds.SessionRunner):
    def locate(self, p):
        where = super().locate(p)
        if where[0] == "edge":
            u, v = where[1], where[2]
            if self.pts[u][0] == self.pts[v][0]:
                lower, upper = (u, v) if self.pts[u][1] < self.pts[v][1] else (v, u)
                return ("face", self.picture().face_of_half_edge((lower, upper)))
        return where


if __name__ == "__main__":
    ds.main(LocateVertical)
