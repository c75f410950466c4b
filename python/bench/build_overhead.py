#!/usr/bin/env python3
"""What dcel.build() costs through Python, against the C++ call alone.

    python/bench/build_overhead.py GRAPH.json [--repeat N] [--lists]

Reads the graph once (dcel.read_graph: numpy arrays), then alternates N
runs of the C++ call dcel::build on a graph converted once (timed inside
the extension, _dcel._build_seconds) with N runs of dcel.build(vertices,
edges) timed from Python, each side first in every other round (conversion of the arrays, the build, the Dcel
object), both in thread CPU time (the machine is shared). Prints the medians and their ratio. --lists passes Python lists
instead of arrays (numpy reads them first). A 1e6-point Delaunay input:
    dcel_bench --write-input delaunay-1e6 FILE   (scripts/bench builds dcel_bench)
"""
import argparse
import statistics
import sys
import time

import dcel
from dcel import _dcel


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("graph")
    parser.add_argument("--repeat", type=int, default=6)
    parser.add_argument("--lists", action="store_true", help="pass Python lists, not numpy arrays")
    args = parser.parse_args()
    with open(args.graph, encoding="utf-8") as f:
        g = dcel.read_graph(f.read())
    vertices, edges = (g.vertices.tolist(), g.edges.tolist()) if args.lists else (g.vertices, g.edges)
    cpp, python = [], []

    def run_python():
        start = time.thread_time()
        d = dcel.build(vertices, edges)
        python.append(time.thread_time() - start)
        del d

    def run_cpp():
        cpp.extend(_dcel._build_seconds(g.vertices, g.edges, 1))

    # A run right after the other freed its DCEL reuses that memory and is
    # faster (about 15% here): each side goes first in half of the rounds.
    for i in range(args.repeat):
        for run in ((run_cpp, run_python) if i % 2 == 0 else (run_python, run_cpp)):
            run()
    c, p = statistics.median(cpp), statistics.median(python)
    print(f"{len(g.vertices)} vertices, {len(g.edges)} edges, {'lists' if args.lists else 'numpy arrays'}, "
          f"median of {args.repeat}")
    print(f"C++ dcel::build: {c * 1000:.0f} ms   (runs: {', '.join(f'{t * 1000:.0f}' for t in cpp)})")
    print(f"dcel.build():    {p * 1000:.0f} ms   (runs: {', '.join(f'{t * 1000:.0f}' for t in python)})")
    print(f"ratio: {p / c:.2f}x")
    return 0


if __name__ == "__main__":
    sys.exit(main())
