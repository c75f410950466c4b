"""The binding against the CLI (the same library reached through JSON files
and a process): faces, build dumps, check reports, locate and stab, and the
messages for bad input, on graphs written here and generated ones. The
shared acceptance cases are read from where they are, when that directory
exists (they are not copied into the project)."""
import glob
import json
import os

import pytest

import dcel
from conftest import canonical_cycles, run_cli

# Written for this test: each one a kind of case the conventions single out.
HAND = {
    "square_with_diagonal": ([(0, 0), (4, 0), (4, 4), (0, 4)], [(0, 1), (1, 2), (2, 3), (3, 0), (0, 2)]),
    "nested_with_isolated": (
        [(0, 0), (10, 0), (10, 10), (0, 10), (2, 2), (5, 2), (2, 5), (8, 8), (20, 20), (3, 3)],
        [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 4)],
    ),
    "lone_edge": ([(1, 1), (3, 2)], [(0, 1)]),
    "empty": ([], []),
    "isolated_only": ([(0, 0), (5, -1)], []),
    "collinear_chain": ([(0, 0), (1, 0), (2, 0), (3, 0), (1, 1)], [(0, 1), (1, 2), (2, 3), (1, 4)]),
    "negative_zero": ([(-0.0, 0.0), (1, -0.0), (0, 1)], [(0, 1), (1, 2), (2, 0)]),
    "offset_1e15": ([(1e15, 1e15), (1e15 + 1, 1e15), (1e15, 1e15 + 1), (1e15 + 1, 1e15 + 1)],
                    [(0, 1), (1, 3), (3, 2), (2, 0)]),
    "tiny": ([(1e-300, 1e-300), (3e-300, 1e-300), (2e-300, 5e-300), (5e-324, 0)], [(0, 1), (1, 2), (2, 0)]),
    "star": ([(0, 0), (1, 0), (0, 1), (-1, 0), (0, -1), (1, 1)], [(0, 1), (0, 2), (0, 3), (0, 4), (0, 5)]),
}


def cases():
    out = dict(HAND)
    for family in dcel.families():
        for seed in (1, 2):
            out[f"{family}_{seed}"] = tuple(dcel.generate(family, seed, 30))
    return out


CASES = cases()


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    folder = tmp_path_factory.mktemp("graphs")
    paths = {}
    for name, (vertices, edges) in CASES.items():
        paths[name] = str(folder / f"{name}.json")
        with open(paths[name], "w", encoding="utf-8") as f:
            f.write(dcel.Graph(vertices, edges).to_json())
    return paths


@pytest.mark.parametrize("name", sorted(CASES))
def test_faces_and_build_are_the_cli_s(name, files):
    vertices, edges = CASES[name]
    d = dcel.build(vertices, edges)
    assert json.loads(run_cli("faces", files[name])) == {"faces": dcel.faces(vertices, edges)}
    assert run_cli("build", files[name]) == d.to_json()
    again = dcel.read_graph(open(files[name], encoding="utf-8").read())
    assert again.vertices.tolist() == [list(p) for p in vertices] or len(vertices) == 0
    assert dcel.build(again).to_json() == d.to_json()


def wrong_answers(d):
    cycles = d.boundary_cycles()
    yield "reversed", [list(reversed(c)) for c in cycles]
    yield "missing", cycles[1:]
    yield "extra", cycles + cycles[:1]
    yield "bad_vertex", cycles + [[d.num_vertices + 5]]
    yield "garbage", "{not json"
    dump = d.to_dump()
    if dump["half_edges"]:
        dump["half_edges"][0]["next"] = 0 if dump["half_edges"][0]["next"] != 0 else 1
    yield "broken_dump", dump


@pytest.mark.parametrize("name", ["square_with_diagonal", "nested_with_isolated", "star", "lone_edge",
                                  "triangulation_1", "near-degenerate_2", "components_1"])
def test_check_reports_are_the_cli_s(name, files, tmp_path):
    d = dcel.build(*CASES[name])
    for label, answer in wrong_answers(d):
        path = tmp_path / f"{label}.json"
        path.write_text(answer if isinstance(answer, str) else dcel.answer_text(answer))
        report = dcel.check(CASES[name], answer)
        if report.agrees:  # e.g. nothing to remove from an empty answer
            continue
        expected = report.text
        if report[0].kind == "unreadable-answer":  # the CLI names the file it read
            expected = expected.replace("unreadable-answer: answer: ", f"unreadable-answer: ANSWER {path}: ", 1)
        assert run_cli("check", files[name], str(path), expect=(1,)) == expected
        cli = json.loads(run_cli("check", "--json", files[name], str(path), expect=(1,)))
        assert cli["count"] == len(report) + report.unlisted and cli["unlisted"] == report.unlisted
        assert [(x["kind"], x["vertices"]) for x in cli["differences"]] == [(x.kind, x.vertices) for x in report]


def cli_location(text):
    doc = json.loads(text)
    for kind in ("vertex", "edge", "face"):
        if kind in doc:
            return dcel.Location(kind, doc[kind])
    raise AssertionError(text)


def cli_pieces(text):
    out = []
    for piece in json.loads(text)["pieces"]:
        ((kind, id_),) = [(k, v) for k, v in piece.items() if k != "along"]
        out.append(dcel.StabPiece(kind, id_, piece.get("along", False)))
    return out


@pytest.mark.parametrize("name", ["square_with_diagonal", "nested_with_isolated", "grid-with-holes_1",
                                  "nested-polygons_2"])
def test_locate_and_stab_are_the_cli_s(name, files):
    vertices, edges = CASES[name]
    d = dcel.build(vertices, edges)
    xs, ys = [p[0] for p in vertices], [p[1] for p in vertices]
    lo_x, hi_x, lo_y, hi_y = min(xs) - 1, max(xs) + 1, min(ys) - 1, max(ys) + 1
    probes = [(lo_x + (hi_x - lo_x) * i / 7, lo_y + (hi_y - lo_y) * j / 5) for i in range(8) for j in range(6)]
    probes += [tuple(vertices[u]) for u, _ in edges[:3]]
    for x, y in probes:
        assert d.locate((x, y)) == cli_location(run_cli("locate", files[name], repr(x), repr(y)))
    for (ax, ay), (bx, by) in zip(probes[::5], probes[3::7]):
        args = [files[name], repr(ax), repr(ay), repr(bx), repr(by)]
        assert d.stab((ax, ay), (bx, by)) == cli_pieces(run_cli("stab", *args))
        if (ax, ay) != (bx, by):
            assert d.stab((ax, ay), (bx, by), line=True) == cli_pieces(run_cli("stab", *args, "--line"))


@pytest.mark.parametrize(
    "text",
    [
        '{"vertices": [[0, 0], [2, 2], [0, 2], [2, 0]], "edges": [[0, 1], [2, 3]]}',
        '{"vertices": [[0, 0], [1, 1]], "edges": [[0, 1], [1, 0]]}',
        '{"vertices": [[0, 0]], "edges": [[0, 1]]}',
        '{"vertices": [[0, 0], [1, 1]], "edges": [[0, -1]]}',
        '{"vertices": [[0, 0], [1e999, 1]], "edges": []}',
        '{"vertices": [[0, 0], [1, 1]], "edges": [[0, 1]',
        '{"vertices": [[0, 0, 0]], "edges": []}',
    ],
)
def test_bad_input_messages_are_the_cli_s(text, tmp_path):
    path = tmp_path / "bad.json"
    path.write_text(text)
    with pytest.raises(dcel.InvalidInput) as caught:
        dcel.build(dcel.read_graph(text))
    import subprocess

    from conftest import cli_path

    done = subprocess.run([cli_path(), "faces", str(path)], capture_output=True, text=True)
    assert done.returncode == 1 and done.stdout == ""
    assert done.stderr == f"dcel: {path}: {caught.value}\n"


ACCEPTANCE = os.environ.get("DCEL_ACCEPTANCE_DIR", "")


@pytest.mark.skipif(not os.path.isdir(os.path.join(ACCEPTANCE, "cases")), reason="no acceptance fixtures here")
def test_the_acceptance_cases():
    valid = sorted(glob.glob(os.path.join(ACCEPTANCE, "cases", "*.json")))
    invalid = sorted(glob.glob(os.path.join(ACCEPTANCE, "invalid", "*.json")))
    assert valid and invalid
    for path in valid:
        graph = dcel.read_graph(open(path, encoding="utf-8").read())
        expected = json.load(open(os.path.join(ACCEPTANCE, "expected", os.path.basename(path)), encoding="utf-8"))
        expected = expected["faces"] if isinstance(expected, dict) else expected
        mine = dcel.faces(graph)
        assert canonical_cycles(mine) == canonical_cycles(expected), path
        assert {"faces": mine} == json.loads(run_cli("faces", path)), path
        assert dcel.check(graph, expected).agrees, path
    for path in invalid:
        text = open(path, "rb").read()  # bytes: read_graph takes them as they are
        with pytest.raises(dcel.InvalidInput):
            dcel.build(dcel.read_graph(text))
        run_cli("faces", path, expect=(1, 2))
