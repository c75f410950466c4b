#!/usr/bin/env python3
# Test impl (sessions): refuses every add_edge whose segment is horizontal or
# vertical (the reference accepts them when nothing is in the way).
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "examples", "python"))
import dcel_session as ds  # noqa: E402


class RefusesCollinear(ds.SessionRunner):
    def refusal(self, op, args):
        if op == "add_edge":
            p, q = self.pts[ds.read_id(args["from"])], self.pts[ds.read_id(args["to"])]
            if p[0] == q[0] or p[1] == q[1]:
                return "an axis-parallel edge is not supported"
        return None


if __name__ == "__main__":
    ds.main(RefusesCollinear)
