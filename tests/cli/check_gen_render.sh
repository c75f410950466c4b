#!/bin/sh
# Exit codes and output of `dcel check`, `dcel gen` and `dcel render`.
# Usage: check_gen_render.sh DCEL DATA_DIR check|gen|render
# Answers are derived from the reference's own output (dcel faces / build)
# by a known change, or written for a triangle whose cycles are known by hand.
set -u
dcel=$1
data=$2
section=$3
. "$(dirname "$0")/lib.sh"

g="$data/square_hole.json"
t="$data/triangle.json"
D="\"$dcel\""

case $section in
check)
    run "$D faces $g > $tmp/faces.json && $D check $g $tmp/faces.json"
    expect faces-agree 0 '^agrees: the answer has the 4 boundary cycles of the reference$'
    run "$D build $g | $D check $g -"
    expect dump-agrees 0 '^agrees: the dump is the reference DCEL \(8 vertices, 14 half-edges, 3 faces\)'
    run "$D build --compact $g > $tmp/dump.json && $D check - $tmp/dump.json < $g"
    expect graph-on-stdin 0 '^agrees'
    run "echo '[[0, 1, 2], [0, 2, 1]]' | $D check $t -"
    expect bare-array-form 0 '^agrees'
    run "echo '{\"faces\": [[2, 0, 1], [1, 0, 2]]}' | $D check $t -"
    expect rotation-and-order-free 0 '^agrees'
    # The answer kinds and conventions (--answer, --face-on, --one-based,
    # --unoriented), on the square with a triangle inside: cycles written by
    # hand (the square's inside [0, 1, 2, 3] and outside [1, 0, 3, 2], the
    # triangle's inside [4, 5, 6] and outside [5, 4, 6]).
    run "echo '{\"rings\": [[0, 1, 2, 3], [4, 5, 6]]}' | $D check $g - --answer rings"
    expect answer-rings 0 '^agrees'
    run "echo '{\"polygons\": [[[0, 1, 2, 3], [5, 4, 6]], [[4, 5, 6]]]}' | $D check $g - --answer polygons"
    expect answer-polygons 0 '^agrees'
    run "echo '{\"polygons\": [[[3, 2, 1, 0], [4, 5, 6]], [[6, 5, 4]]]}' | $D check $g - --answer polygons --unoriented"
    expect answer-polygons-unoriented 0 '^agrees'
    run "echo '[[3, 2, 1, 0], [2, 3, 0, 1], [6, 5, 4], [6, 4, 5]]' | $D check $g - --answer faces --face-on right"
    expect face-on-right 0 '^agrees'
    run "echo '[[1, 2, 3, 4], [2, 1, 4, 3], [5, 6, 7], [6, 5, 7]]' | $D check $g - --answer auto --one-based"
    expect one-based 0 '^agrees'
    run "echo '[[1, 2, 3, 4], [2, 1, 4, 3], [5, 6, 7], [6, 5, 7]]' | $D check $g -"
    expect one-based-hint 1 'note: the answer agrees with --one-based: its ids count from 1'
    run "echo '[[0, 1, 2, 3], [4, 5, 6]]' | $D check $g - --answer dump"
    expect answer-kind-forced 1 'unreadable-answer: ANSWER <stdin>'
    run "$D check $g $g --answer shapes"
    expect answer-kind-unknown 2 'answer: shapes not in \{auto,faces,dump,polygons,rings,even-odd\}'
    # The first cycle dropped: one missing cycle, the count first.
    run "$D faces $g | sed 's/\\[\\[[^]]*\\], /[/' | $D check $g -"
    expect missing-cycle 1 '^1 difference
missing-cycle: the reference cycle \[0, 1, 2, 3\] is missing from the answer$'
    run "echo '[[0, 2, 1], [0, 2, 1]]' | $D check $t -"
    expect reversed-cycle 1 'reversed-cycle: answer cycle [01] \[0, 2, 1\] is the reference cycle \[0, 1, 2\] walked backwards'
    run "echo '[[0, 1, 2], [0, 2, 1], [0, 9]]' | $D check $t -"
    expect vertex-count 1 'vertex-count: answer cycle 2 \[0, 9\] names vertex 9, but the graph has 3 vertices'
    run "echo '[[0, 1, 2], [0, 2, 1]]' | $D check $t - --json; echo '[[0, 1], [1, 2], [2, 0]]' | $D check $t - --json"
    expect json 1 '^\{"agrees": true, "count": 0, "unlisted": 0, "differences": \[\]\}
\{"agrees": false, "count": 11, "unlisted": 0, "differences": \[
  \{"kind": "wrong-next", "message": "at v0->v1 the answer continues to v1->v0'
    run "$D build $g | sed 's/\"next\": 1,/\"next\": 0,/' | $D check $g -"
    expect broken-invariant 1 '^broken-invariant: \[next-prev\]'
    run "echo 'not json' | $D check $g -"
    expect unreadable-answer 1 '^1 difference
unreadable-answer: ANSWER <stdin>: line 1, column 1'
    run "$D check $g $tmp/no-such-answer.json"
    expect missing-answer-file 1 'unreadable-answer: ANSWER: cannot open'
    run "echo '{\"faces\": 3}' | $D check $g -"
    expect answer-wrong-shape 1 'unreadable-answer: ANSWER <stdin>: faces'
    run "$D faces $g | $D check $data/duplicate_points.json -"
    expect invalid-graph 2 'GRAPH .*duplicate_points.json is not a valid graph: vertices 0 and 1 are at the same point'
    run "$D check $tmp/no-such-graph.json $t"
    expect missing-graph-file 2 'GRAPH: cannot open'
    run "$D check - - < $t"
    expect both-stdin 2 'cannot both be -'
    run "$D check $g"
    expect missing-answer-argument 2 'ANSWER is required'
    run "$D check --help"
    expect help 0 'Example:'
    ;;
gen)
    run "$D gen | $D faces - > /dev/null && echo valid"
    expect default-is-valid 0 '^valid$'
    for f in random-segments triangulation grid-with-holes nested-polygons tree comb star collinear-chain \
             components near-degenerate; do
        run "$D gen --family $f --seed 11 --vertices 60 > $tmp/g.json && $D faces $tmp/g.json | $D check $tmp/g.json -"
        expect "family-$f" 0 '^agrees'
    done
    run "a=\$($D gen --family star --seed 5); b=\$($D gen --family star --seed 5); [ \"\$a\" = \"\$b\" ] && echo same"
    expect deterministic 0 '^same$'
    run "a=\$($D gen --seed 5); b=\$($D gen --seed 6); [ \"\$a\" != \"\$b\" ] && echo differ"
    expect seed-matters 0 '^differ$'
    run "$D gen --family bogus"
    expect unknown-family 2 'unknown family "bogus"; the families are random-segments, triangulation, .*near-degenerate'
    run "$D gen --vertices 20000"
    expect too-many-vertices 2 '^dcel: gen: --vertices: expected an integer from 0 to 10000, found "20000"'
    run "$D gen --seed -1"
    expect negative-seed 2 '^dcel: gen: --seed: expected a non-negative integer \(at most 18446744073709551615\), found "-1"'
    run "$D gen --help"
    expect help 0 'Families: random-segments'
    ;;
render)
    run "$D render $g"
    expect stdout 0 '^<svg xmlns="http://www.w3.org/2000/svg"'
    run "$D render $g -o $tmp/out.svg --title 'a <b> & \"c\"' && grep -c '<title>a &lt;b&gt; &amp; &quot;c&quot;</title>' $tmp/out.svg"
    expect file-and-escaped-title 0 '^1$'
    run "$D render $g -o $tmp/out.svg --title \"it's\" && grep -c '<title>it&apos;s</title>' $tmp/out.svg"
    expect apostrophe-in-title 0 '^1$'
    if command -v rsvg-convert >/dev/null 2>&1; then
        run "$D gen --family near-degenerate --seed 2 --vertices 40 | $D render - | rsvg-convert -o $tmp/out.png && echo converted"
        expect rsvg-converts 0 '^converted$'
    fi
    run "$D render $data/duplicate_points.json"
    expect invalid-graph 1 'same point'
    run "$D render $g -o $tmp/no/such/dir/out.svg"
    expect unwritable-output 2 'cannot open'
    ;;
*)
    echo "unknown section $section"
    exit 2
    ;;
esac

finish
