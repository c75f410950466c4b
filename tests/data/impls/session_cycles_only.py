#!/usr/bin/env python3
# Test impl (sessions): right in every step, but gives the state as boundary
# cycles only, {"faces": [[v, ...], ...]}, as a faces-only program would.
# Cycles cannot show which face a hole or an isolated vertex lies in, so
# dcel diff agrees with a warning that hole placement went unchecked.
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "examples", "python"))
import dcel_session as ds  # noqa: E402


class CyclesOnly(ds.SessionRunner):
    def state(self):
        full = super().state()
        cycles = []
        for face in full["faces"]:
            if face["outer"] is not None:
                cycles.append(face["outer"])
            cycles.extend(face["holes"])
        return {"faces": cycles}


if __name__ == "__main__":
    ds.main(CyclesOnly)
