#!/usr/bin/env python3
# Test impl (sessions): right in every step, but answers every stab with
# {"skip": ...}, as a library without that query would. The skipped steps go
# unchecked: dcel diff agrees and counts them in a warning. With
# --skip-edits it also skips every add_vertex, which no answer may do.
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "examples", "python"))
import dcel_session as ds  # noqa: E402

SKIP_EDITS = "--skip-edits" in sys.argv


class SkipsStab(ds.SessionRunner):
    def step(self, step, each_step):
        op = next(iter(step))
        if op == "stab" or (SKIP_EDITS and op == "add_vertex"):
            return {"skip": "no " + op + " in this library"}
        return super().step(step, each_step)


if __name__ == "__main__":
    ds.main(SkipsStab)
