#!/usr/bin/env python3
# Test impl (sessions): an add_edge that splits a face leaves every hole and
# isolated vertex of the old face in the old face's record; none moves into
# the new face, even when it lies inside it. The boundary cycles stay right,
# so only the face records show it (the state, face_boundary's holes,
# neighbours). The stale entry lasts while the old face's half-edge and the
# hole's half-edge (or the isolated vertex) are still there.
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "examples", "python"))
import dcel_session as ds  # noqa: E402


class HolesStay(ds.SessionRunner):
    def __init__(self, *args):
        super().__init__(*args)
        self.stuck = []  # ("hole", a half-edge of it, or "iso", vertex; the old face: a half-edge on its left, or None)

    def after_edit(self, op, args, created):
        if op != "add_edge":
            return
        pic = self.picture()
        u, v = ds.read_id(args["from"]), ds.read_id(args["to"])
        left, right = pic.cycle_of[(u, v)], pic.cycle_of[(v, u)]
        if left == right:
            return  # no face split: two cycles joined, or a dangling edge
        if pic.area2[left] > 0 and pic.area2[right] > 0:
            new, old = left, (v, u)  # the old face's outer split: the new face is the part left of u -> v
        else:
            new = left if pic.area2[left] > 0 else right  # a hole's cycle split: the new face is the part closed off
            f = pic.hole_face[right if new == left else left]
            old = None if f is None else tuple(pic.cycles[f][:2])
        rec = pic.records()[new]
        already = {key for _, key, _ in self.stuck}  # already stale: stays where it was left
        self.stuck += [("hole", tuple(pic.cycles[c][:2]), old) for c in rec["holes"]
                       if tuple(pic.cycles[c][:2]) not in already]
        self.stuck += [("iso", w, old) for w in rec["isolated"] if w not in already]

    def adjust_records(self, pic, recs):
        kept, moved = [], set()
        for kind, key, old in self.stuck:
            if old is not None and old not in pic.cycle_of:
                continue  # the old face's half-edge is gone: the entry with it
            stay = None if old is None else pic.face_of_half_edge(old)
            if kind == "iso":
                if key not in pic.iso_face or ("iso", key) in moved:
                    continue
                recs[pic.iso_face[key]]["isolated"].remove(key)
                recs[stay]["isolated"].append(key)
                moved.add(("iso", key))
            else:
                c = pic.cycle_of.get(key)
                if c is None or pic.area2[c] > 0 or ("hole", c) in moved:
                    continue
                recs[pic.hole_face[c]]["holes"].remove(c)
                recs[stay]["holes"].append(c)
                moved.add(("hole", c))
            kept.append((kind, key, old))
        self.stuck = kept


if __name__ == "__main__":
    ds.main(HolesStay)
