#!/usr/bin/env python3
# Test impl (sessions): point location ignores holes: a point in a face is
# located in the first bounded face, largest first, whose outer boundary
# winds around it, never asking whether the point lies in one of that face's
# holes. So a point inside a hole's region (in a bounded face nested in a
# hole of a bounded face) is answered with the enclosing face; everywhere
# else the answer is right. In locate, face_boundary and neighbours.
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "examples", "python"))
import dcel_session as ds  # noqa: E402


class IgnoresHoles(ds.SessionRunner):
    def locate(self, p):
        where = super().locate(p)
        if where[0] != "face":
            return where
        pic = self.picture()
        for c in sorted(pic.positive, key=lambda c: -pic.area2[c]):
            if ds.winding([pic.pts[v] for v in pic.cycles[c]], p) != 0:
                return ("face", c)  # planted: the holes of c are not looked at
        return ("face", None)


if __name__ == "__main__":
    ds.main(IgnoresHoles)
