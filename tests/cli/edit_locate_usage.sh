#!/bin/sh
# Exit codes and output of `dcel edit` (every operation, --graph-out, bad
# scripts), `dcel locate --points`, and the usage errors of `dcel` itself.
# Usage: edit_locate_usage.sh DCEL SOURCE_DIR edit|locate|usage
# Expected answers are worked out by hand on examples/map/countries.json:
# West = face 1 (vertices 0 1 4 5), East = face 2 (1 2 3 4), Enclave = face 3
# (6 7 8 9, inside East), vertex 10 isolated in West, edge 6 = 1-4.
set -u
dcel=$1
src=$2
section=$3
. "$(dirname "$0")/lib.sh"

D="\"$dcel\""
map="$src/examples/map/countries.json"
data="$src/tests/data"

case $section in
edit)
    run "$D edit $map $data/edit/every_operation_script.json --graph-out $tmp/g.json"
    expect add-vertex 0 '"op": "add_vertex", "at": \[1, 1\], "change": \{"vertices": \{"added": 11\}\}'
    expect remove-vertex 0 '"op": "remove_vertex", "vertex": 11, "change": \{"vertices": \{"removed": 11\}\}'
    expect add-edge-to-point 0 '"op": "add_edge_to_point", "from": 10, "to": \[3, 3\], "change": \{"vertices": \{"added": 11\}, "edges": \{"added": 11\}\}'
    expect merge-edges 0 '"op": "merge_edges", "vertex": 12, "change": \{"vertices": \{"removed": 12\}, "edges": \{"removed": 12, "merged_into": 0\}\}'
    # The name holds '"', '\', a newline, a tab and U+0001: RFC 8259 escapes.
    expect escaped-name 0 '"op": "locate", "at": \[1, 1\], "face": 1, "name": "Quote \\"q\\" back\\\\slash\\nnew\\ttab\\u0001"'
    expect west-after 0 '"face": 1, "name": "Quote.*", "outer": \[0, 1, 4, 5\], "holes": 1, "isolated": \[\]'
    run "cat $tmp/g.json"
    expect graph-out 0 '^\{"vertices": \[\[0, 0\], \[4, 0\], \[8, 0\], \[8, 6\], \[4, 6\], \[0, 6\], \[5, 2\], \[7, 2\], \[7, 4\], \[5, 4\], \[2, 3\], \[3, 3\]\], "edges": \[\[0, 1\], \[1, 2\], \[2, 3\], \[3, 4\], \[4, 5\], \[5, 0\], \[1, 4\], \[6, 7\], \[7, 8\], \[8, 9\], \[9, 6\], \[10, 11\]\]\}$'
    printf '%s\n' '{"steps": [{"frobnicate": {"edge": 1}}]}' >"$tmp/unknown.json"
    run "$D edit $map $tmp/unknown.json"
    expect unknown-operation 1 'steps\[0\]\.frobnicate: unknown operation "frobnicate": expected one of name, split_edge, add_edge, add_edge_to_point, add_vertex, remove_edge, remove_vertex, merge_edges, locate, stab'
    printf '%s\n' '{"steps": [{"add_vertex": {"at": [1]}}]}' >"$tmp/arity.json"
    run "$D edit $map $tmp/arity.json"
    expect point-arity 1 'steps\[0\]\.add_vertex\.at: expected a point \[x, y\], found an array of 1 element'
    printf '%s\n' '{"steps": [{"add_vertex": {"at": [1, 2, 3]}}]}' >"$tmp/arity3.json"
    run "$D edit $map $tmp/arity3.json"
    expect point-arity-3 1 'steps\[0\]\.add_vertex\.at: expected a point \[x, y\], found an array of 3 elements'
    printf '%s\n' '{"steps": [{"add_edge": {"from": 0, "to": 99}}]}' >"$tmp/bad_id.json"
    run "$D edit $map $tmp/bad_id.json"
    expect bad-vertex-id 1 '^dcel: .*bad_id.json: steps\[0\]: .*v99'
    printf '%s\n' '{"steps": [{"remove_vertex": {"vertex": 4}}]}' >"$tmp/busy.json"
    run "$D edit $map $tmp/busy.json"
    expect remove-vertex-with-edges 1 '^dcel: .*steps\[0\]: remove_isolated_vertex: .*v4'
    run "$D edit $map $data/edit/every_operation_script.json --graph-out $tmp/no/such/dir/g.json"
    expect unwritable-graph-out 2 '^dcel: cannot open .*/no/such/dir/g.json for writing: No such file or directory$'
    ;;
locate)
    run "$D locate $map --points $data/locate/points.json"
    expect_whole points 0 '^\{"locations": \[
  \{"point": \[6, 3\], "face": 3\},
  \{"point": \[4, 0\], "vertex": 1\},
  \{"point": \[4, 3\], "edge": 6, "faces": \[1, 2\]\},
  \{"point": \[-1, -1\], "face": 0\}
\]\}
$'
    run "$D locate $map --points $data/locate/points.json --names $src/examples/map/names.json"
    expect_whole points-named 0 '"face": 3, "name": "Enclave"\},.*"faces": \[1, 2\], "names": \["West", "East"\]\},.*"face": 0, "name": null\}'
    run "$D locate $map --points $data/locate/not_points.json"
    expect points-not-an-array 1 'not_points.json: top level: expected an array of points \[\[x, y\], \.\.\.\], found an object'
    run "$D locate $map"
    expect neither 2 'give either X Y or --points FILE'
    run "$D locate $map 1 1 --points $data/locate/points.json"
    expect both 2 'give either X Y or --points FILE'
    ;;
usage)
    run "$D --help"
    expect help 0 'Usage: dcel \[OPTIONS\] SUBCOMMAND'
    run "$D --version"
    expect version 0 '^dcel [0-9]+\.[0-9]+\.[0-9]+ \(commit ([0-9a-f]{12}|unknown)\)$'
    run "$D"
    expect no-command 2 '^dcel: no command given; the commands are faces, build, locate, stab, edit, session, check, gen, render, diff, diff-merge \(dcel --help\)$'
    run "$D --bogus"
    expect unknown-global-option 2 '^dcel: unknown option "--bogus"; options go after the command \(dcel --help\)$'
    run "$D facs $map"
    expect misspelt-command 2 '^dcel: unknown command "facs"; the commands are faces, build, locate, stab, edit, session, check, gen, render, diff, diff-merge \(dcel --help\)$'
    run "$D faces --frobnicate $map"
    expect unknown-option 2 '^dcel: faces: unexpected argument "--frobnicate" \(dcel faces --help\)$'
    run "$D faces $tmp/nonexistent.json"
    expect missing-file 2 'cannot open .*nonexistent.json: No such file or directory'
    run "$D faces - < $src/tests/consumer/square.json"
    expect stdin 0 '^\{"faces": \[\[0, 1, 2\], \[1, 0, 3, 2\], \[2, 3, 0\]\]\}$'
    run "$D faces < /dev/null"
    expect empty-stdin 1 '<stdin>: line 1, column 1: empty input: expected a JSON document'
    ;;
*)
    echo "unknown section $section"
    exit 2
    ;;
esac

finish
