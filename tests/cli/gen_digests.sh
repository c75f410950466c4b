#!/bin/sh
# The same seed gives the same graph in every build: `dcel gen` for each
# family and a few sizes and seeds, and `dcel diff --print-case` over the
# schedule (coordinate classes and number spellings), hashed and compared with
# tests/data/gen_digests.txt. The digests were recorded with a gcc build and
# hold for clang builds too (CI's sanitized build, fuzzing images); a draw
# whose order the compiler picks (two draws in one call, see
# src/dcel/gen/rng.hpp) changes them in one of the two.
#
#   sh tests/cli/gen_digests.sh DCEL DIGESTS            compare
#   sh tests/cli/gen_digests.sh DCEL DIGESTS --record   rewrite DIGESTS
set -eu
dcel=$1
digests=$2
measure() {
  for family in random-segments triangulation grid-with-holes nested-polygons tree comb star collinear-chain components near-degenerate; do
    for n in 2 5 40 200; do
      h=$(for seed in 0 1 2; do "$dcel" gen --family "$family" --seed "$seed" --vertices "$n"; done | sha256sum | cut -c1-16)
      echo "gen $family $n $h"
    done
  done
  h=$(for c in $(seq 0 6 600); do "$dcel" diff --print-case "$c" --seed 3; done | sha256sum | cut -c1-16)
  echo "print-case 0..600/6 seed 3 $h"
}
if [ "${3:-}" = "--record" ]; then
  measure >"$digests"
  echo "recorded $(wc -l <"$digests") digests in $digests"
  exit 0
fi
measure >gen_digests.measured
if diff "$digests" gen_digests.measured; then
  echo "gen digests: all $(wc -l <"$digests") agree"
else
  echo "gen digests: the graphs above differ from the recorded ones (< recorded, > this build)"
  exit 1
fi
