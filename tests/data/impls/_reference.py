"""Shared by the test impls that answer in other kinds than faces: the
reference's answer of that kind, from the dcel CLI itself (DCEL_CLI names it),
so that each impl states only its one misbehaviour on top of a right answer."""
import json
import os
import subprocess

# In the sanitized build this CLI is started once per case and per shrink
# candidate: its leak check at exit (a third of a start there) is left to the
# CLI's own tests, which run `dcel faces --answer` with it.
_ENV = dict(os.environ, ASAN_OPTIONS=os.environ.get("ASAN_OPTIONS", "") + ":detect_leaks=0")


def answer(text, kind):
    """The reference's answer of `kind` (faces, dump, polygons, rings), parsed."""
    out = subprocess.run([os.environ["DCEL_CLI"], "faces", "--answer", kind, "-"], input=text.encode(),
                         stdout=subprocess.PIPE, env=_ENV, check=True).stdout
    return json.loads(out)


def dump(text):
    return answer(text, "dump")


def walk(dump_doc, start):
    """The origins along next from half-edge `start`, round once."""
    half = dump_doc["half_edges"]
    ring, h = [], start
    while True:
        ring.append(half[h]["origin"])
        h = half[h]["next"]
        if h == start:
            return ring
