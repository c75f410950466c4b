#!/usr/bin/env python3
# Test impl (sessions): remove_edge of a bridge on a bounded face's outer
# boundary (the same face on both sides, both ends keep edges) where the part
# that breaks off (the new hole) is the one holding the step's first end: the
# face record keeps that part's cycle as its outer boundary and lists the
# real outer boundary as the hole (the two are swapped). The cycles stay
# right; the state and face_boundary show it, while both cycles last.
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "examples", "python"))
import dcel_session as ds  # noqa: E402


class StaleOuter(ds.SessionRunner):
    def __init__(self, *args):
        super().__init__(*args)
        self.swapped = []  # (a half-edge of the real outer cycle, a half-edge of the broken-off part's cycle)

    def after_edit(self, op, args, created):
        if op != "remove_edge":
            return
        u, v = ds.read_id(args["edge"][0]), ds.read_id(args["edge"][1])
        if not self.adj[u] or not self.adj[v]:
            return  # an end left alone: nothing broke off as a cycle
        pic = self.picture()
        if pic.component[u] == pic.component[v]:
            return  # not a bridge
        hole = pic.exterior[pic.component[u]]
        f = pic.hole_face[hole]
        if f is not None and pic.component[pic.cycles[f][0]] == pic.component[v]:
            # u's part broke off inside f, whose outer boundary is v's part
            self.swapped.append((tuple(pic.cycles[f][:2]), tuple(pic.cycles[hole][:2])))

    def adjust_records(self, pic, recs):
        kept = []
        for outer_h, hole_h in self.swapped:
            o, h = pic.cycle_of.get(outer_h), pic.cycle_of.get(hole_h)
            if o is None or h is None or pic.area2[o] <= 0 or h not in recs[o]["holes"]:
                continue
            rec = recs[o]
            rec["holes"][rec["holes"].index(h)] = rec["outer"]
            rec["outer"] = h
            kept.append((outer_h, hole_h))
        self.swapped = kept


if __name__ == "__main__":
    ds.main(StaleOuter)
