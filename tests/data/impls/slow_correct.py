#!/usr/bin/env python3
# Test impl: right, but slow in proportion to the graph's size (1 ms per
# vertex and edge), so a large case takes longer than --timeout-ms: it must
# pass, with a performance note, not be reported as a hang.
import time
import _correct


def answer(text):
    points, edges = _correct.graph(text)
    time.sleep(0.001 * (len(points) + len(edges)))
    return _correct.correct(text)


_correct.serve(answer)
