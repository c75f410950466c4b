#!/usr/bin/env python3
# Test impl: correct, but with --stream it prints every answer twice, so from
# the second graph on it answers the graph before. Alone, each graph passes.
import sys
import _correct


def answer(text):
    a = _correct.correct(text)
    return a + "\n" + a if "--stream" in sys.argv[1:] else a


_correct.serve(answer)
