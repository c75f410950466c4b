#!/usr/bin/env python3
# Test impl (dump kind): the whole DCEL, right but for one thing: every
# isolated vertex is listed in the unbounded face, even one inside a bounded
# face (the vertex-to-face step forgotten).
import json
import _correct
import _reference


def answer(text):
    d = _reference.dump(text)
    moved = []
    for f in d["faces"][1:]:
        moved += f["isolated"]
        f["isolated"] = []
    d["faces"][0]["isolated"] += moved
    return json.dumps(d)


_correct.serve(answer)
