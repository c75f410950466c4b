#!/bin/sh
# The downstream fuzzing template (examples/downstream-fuzzing/) as a project
# that copied it would build it: its own .clusterfuzzlite/build.sh, against the
# installed dcel package, with this build's compiler and flags and no fuzzing
# engine (LIB_FUZZING_ENGINE empty: replay_main.cpp runs the files it is given).
# The harness must pass an input on which the stand-in solver is right, and
# stop with the shrunk graph and the report on one where its atan2 order is
# wrong (data/fuzz_template/atan2_input: the one byte "1", family 49 mod 10 =
# near-degenerate, seed 0, 16 vertices; libFuzzer found it from an empty
# corpus).
# Usage: fuzz_template.sh TEMPLATE PREFIX WORK CXX FLAGS DATA
set -u
template=$1 prefix=$2 work=$3 cxx=$4 flags=$5 data=$6
rm -rf "$work"
mkdir -p "$work/out"
if ! env PROJECT_SRC="$template" CXX="$cxx" CXXFLAGS="$flags" LIB_FUZZING_ENGINE= WORK="$work" OUT="$work/out" \
    DCEL_PREFIX="$prefix" bash "$template/.clusterfuzzlite/build.sh" > "$work/build.log" 2>&1; then
    cat "$work/build.log"
    echo "FAIL: the template's build.sh failed"
    exit 1
fi
fuzzer=$work/out/faces_fuzzer
status=0
"$fuzzer" "$data/agrees" > "$work/agrees.log" 2>&1 || status=$?
if [ "$status" -ne 0 ] || ! grep -q '^replay: 1 inputs ran without a failure$' "$work/agrees.log"; then
    cat "$work/agrees.log"
    echo "FAIL: the harness did not pass an input the solver gets right (status $status)"
    exit 1
fi
status=0
"$fuzzer" "$data/atan2_input" > "$work/atan2.log" 2>&1 || status=$?
cat "$work/atan2.log"
if [ "$status" -eq 0 ]; then
    echo "FAIL: the harness passed the atan2 counterexample"
    exit 1
fi
for expect in 'dcel fuzz: the solver disagrees with the reference DCEL' \
              "the input's graph (16 vertices" \
              'shrunk to a graph that fails the same way (4 vertices, 3 edges' \
              'reversed-cycle: answer cycle 0'; do
    if ! grep -qF "$expect" "$work/atan2.log"; then
        echo "FAIL: no \"$expect\" in the harness's report"
        exit 1
    fi
done
echo "PASS: the template builds, passes a right answer and reports the atan2 bug (status $status)"
