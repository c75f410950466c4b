#!/usr/bin/env python3
# Test impl: correct, but killed by SIGSEGV on a graph with a vertex of degree >= 3.
import os
import signal
import _correct


def answer(text):
    points, edges = _correct.graph(text)
    if max(_correct.degrees(points, edges), default=0) >= 3:
        os.kill(os.getpid(), signal.SIGSEGV)
    return _correct.correct(text)


_correct.serve(answer)
