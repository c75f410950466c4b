#!/usr/bin/env python3
# Test impl (sessions): split_edge [u, v] at w updates one side only: the
# cycle on the other side (through v -> u) still steps from v to u directly,
# without w, in the state and in face_boundary, while w is still exactly
# between u and v with no other edge.
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "examples", "python"))
import dcel_session as ds  # noqa: E402


class SplitTwin(ds.SessionRunner):
    def __init__(self, *args):
        super().__init__(*args)
        self.splits = []  # (u, w, v)

    def after_edit(self, op, args, created):
        if op == "split_edge":
            u, v = ds.read_id(args["edge"][0]), ds.read_id(args["edge"][1])
            self.splits.append((u, created, v))
        self.splits = [(u, w, v) for u, w, v in self.splits if self.adj[w] == {u, v}]

    def cycle_text(self, pic, c):
        cycle = super().cycle_text(pic, c)
        for u, w, v in self.splits:
            n = len(cycle)
            for i in range(n):
                if cycle[i] == v and cycle[(i + 1) % n] == w and cycle[(i + 2) % n] == u:
                    del cycle[(i + 1) % n]  # planted: v -> u, as before the split
                    break
        return cycle


if __name__ == "__main__":
    ds.main(SplitTwin)
