#!/usr/bin/env node
// Hand-worked sessions for dcel_session.mjs: prints "ok" and exits 0 when
// every answer is the one derived by hand below, else what differs and 1.
//
//   node examples/javascript/dcel_session_selftest.mjs
//
// The expected answers are written as the protocol compares them: cycles up
// to rotation, holes and isolated vertices as sets, neighbours as a set, and
// a face as its outer cycle (null for the unbounded face): the program's
// name for it, a half-edge [u, v], must be a step of that cycle.
//
// Deriving a cycle by hand: next(u->v) is the half-edge leaving v just
// clockwise of v->u. At a vertex, list its edges by angle counterclockwise
// (east 0, north 90, west 180, south 270); the one after v->u is the one
// listed just before it (wrapping round). A bounded face's outer cycle runs
// counterclockwise, a hole's boundary (the outside of a component) clockwise.
import { spawnSync } from "node:child_process";
import { fileURLToPath } from "node:url";
import { runSession } from "./dcel_session.mjs";

const program = fileURLToPath(new URL("./dcel_session.mjs", import.meta.url));
const failures = [];
const fail = (where, what) => failures.push(`${where}: ${what}`);
const show = (v) => JSON.stringify(v);

// ---------------------------------------------------------------- comparing

// The rotation of a cycle that is smallest, as text: equal for the same cycle.
function canonical(cycle) {
  let best = null;
  for (let i = 0; i < cycle.length; ++i) {
    const r = [...cycle.slice(i), ...cycle.slice(0, i)].join(" ");
    if (best === null || r < best) best = r;
  }
  return best ?? "";
}
const cycleSet = (cycles) => cycles.map(canonical).sort().join(" | ");

// Is the face name (null, or a walk [u, v, ...]) a walk along `outer` (null:
// the unbounded face)?
function names(name, outer) {
  if (outer === null || name === null) return outer === null && name === null;
  if (!Array.isArray(name) || name.length < 2) return false;
  const steps = new Set(outer.map((u, i) => `${u} ${outer[(i + 1) % outer.length]}`));
  return name.slice(1).every((v, i) => steps.has(`${name[i]} ${v}`));
}

function checkStep(where, got, want) {
  const keys = Object.keys(got).filter((k) => k !== "state");
  const kind = Object.keys(want)[0];
  if (kind === "error") {
    if (keys.join() !== "error" || typeof got.error !== "string") fail(where, `expected a refusal, got ${show(got)}`);
  } else if (kind === "ok" || kind === "vertex") {
    if (show(got) !== show({ ...want, ...(got.state ? { state: got.state } : {}) })) fail(where, `expected ${show(want)}, got ${show(got)}`);
  } else if (kind === "edge") {
    const ok = keys.join() === "edge" && [...got.edge].sort().join() === [...want.edge].sort().join();
    if (!ok) fail(where, `expected edge ${show(want.edge)} (either way), got ${show(got)}`);
  } else if (kind === "face" && !("outer" in want)) {
    if (keys.join() !== "face" || !names(got.face, want.face)) fail(where, `expected the face with outer cycle ${show(want.face)}, got ${show(got)}`);
  } else if (kind === "face") {
    // face_boundary: {face, outer, holes}
    const ok =
      keys.sort().join() === "face,holes,outer" &&
      names(got.face, want.outer) &&
      (want.outer === null ? got.outer === null : got.outer !== null && canonical(got.outer) === canonical(want.outer)) &&
      cycleSet(got.holes) === cycleSet(want.holes);
    if (!ok) fail(where, `expected ${show(want)}, got ${show(got)}`);
  } else if (kind === "faces") {
    // want.faces: outer cycles (or null); a set for neighbours, in order for stab
    const ok =
      keys.join() === "faces" &&
      got.faces.length === want.faces.length &&
      (want.ordered
        ? got.faces.every((f, i) => names(f, want.faces[i]))
        : want.faces.every((outer) => got.faces.some((f) => names(f, outer))));
    if (!ok) fail(where, `expected the faces ${show(want.faces)}${want.ordered ? " in order" : ""}, got ${show(got)}`);
  } else {
    fail(where, `bad expectation ${show(want)}`);
  }
}

function checkState(where, got, want) {
  if (got === undefined) return fail(where, "no state");
  const key = (outer) => (outer === null ? "unbounded" : canonical(outer));
  const records = new Map(got.faces.map((f) => [key(f.outer), f]));
  if (records.size !== got.faces.length) fail(where, `two faces have one outer cycle: ${show(got.faces)}`);
  if (got.faces.length !== want.faces.length) fail(where, `${got.faces.length} faces, expected ${want.faces.length}: ${show(got.faces)}`);
  for (const f of want.faces) {
    const g = records.get(key(f.outer));
    if (!g) {
      fail(where, `no face with outer cycle ${show(f.outer)} in ${show(got.faces)}`);
      continue;
    }
    if (cycleSet(g.holes) !== cycleSet(f.holes)) fail(where, `face ${show(f.outer)} has holes ${show(g.holes)}, expected ${show(f.holes)}`);
    const iso = (vs) => [...vs].sort((a, b) => a - b).join();
    if (iso(g.isolated) !== iso(f.isolated)) fail(where, `face ${show(f.outer)} has isolated ${show(g.isolated)}, expected ${show(f.isolated)}`);
  }
  const same = (a, b) => a === null ? b === null : b !== null && Object.is(a[0], b[0]) && Object.is(a[1], b[1]);
  if (got.vertices.length !== want.vertices.length || !got.vertices.every((p, i) => same(p, want.vertices[i]))) {
    fail(where, `vertices ${show(got.vertices)}, expected ${show(want.vertices)}`);
  }
}

// Runs a session; `expect` has one entry per step, each {step, answer,
// state?} (state: after that edit, with "each_step"), and `final`.
function check(title, start, expect, final, eachStep = false) {
  const doc = { ...start, steps: expect.map((e) => e.step), ...(eachStep ? { each_step: true } : {}) };
  let got;
  try {
    got = runSession(doc);
  } catch (e) {
    return fail(title, `threw ${e.stack}`);
  }
  if (got.steps.length !== expect.length) return fail(title, `${got.steps.length} answers for ${expect.length} steps`);
  expect.forEach((e, i) => {
    const where = `${title}, step ${i} ${show(e.step)}`;
    checkStep(where, got.steps[i], e.answer);
    const edit = "ok" in e.answer || "error" in e.answer;
    if (eachStep && edit) checkState(`${where}, state after it`, got.steps[i].state, e.state ?? final);
    if ((!eachStep || !edit) && "state" in got.steps[i]) fail(where, "a state where none was asked for");
  });
  checkState(`${title}, final state`, got.state, final);
}

// ---------------------------------------------------------------- the sessions

const OK = { ok: true };
const ERROR = { error: true };
const stab = (faces) => ({ faces, ordered: true });

// A: a square with an isolated vertex; a diagonal added and removed.
//
//   3 (0,4) ---- 2 (4,4)     4 (1,3) isolated, inside the square
//   |               |
//   0 (0,0) ---- 1 (4,0)
//
// The square's face: outer [0, 1, 2, 3] (counterclockwise). The unbounded
// face's hole: the square walked clockwise, [1, 0, 3, 2].
// The diagonal 0-2 (y = x) splits the square into [0, 1, 2] (below it) and
// [0, 2, 3] (above it). At 2 the edges counterclockwise are 2->3 (180),
// 2->0 (225), 2->1 (270): next(1->2) = 2->0, so 0->1->2->0 is [0, 1, 2]; and
// next(0->2) = 2->3, next(2->3) = 3->0, next(3->0) = 0->2: [0, 2, 3]. The
// isolated vertex (1, 3) is above the diagonal: in [0, 2, 3].
{
  const square = { vertices: [[0, 0], [4, 0], [4, 4], [0, 4], [1, 3]], edges: [[0, 1], [1, 2], [2, 3], [3, 0]] };
  const SQ = [0, 1, 2, 3], LOW = [0, 1, 2], HIGH = [0, 2, 3];
  const start = {
    faces: [
      { outer: null, holes: [[1, 0, 3, 2]], isolated: [] },
      { outer: SQ, holes: [], isolated: [4] },
    ],
    vertices: [[0, 0], [4, 0], [4, 4], [0, 4], [1, 3]],
  };
  const split = {
    faces: [
      { outer: null, holes: [[1, 0, 3, 2]], isolated: [] },
      { outer: LOW, holes: [], isolated: [] },
      { outer: HIGH, holes: [], isolated: [4] },
    ],
    vertices: start.vertices,
  };
  check(
    "A (square, diagonal)",
    square,
    [
      { step: { locate: { at: [2, 2] } }, answer: { face: SQ } },
      { step: { locate: { at: [1, 3] } }, answer: { vertex: 4 } },
      { step: { locate: { at: [2, 0] } }, answer: { edge: [0, 1] } },
      { step: { locate: { at: [5, 5] } }, answer: { face: null } },
      { step: { add_edge: { from: 0, to: 2 } }, answer: OK, state: split },
      // (3, 1) is below the diagonal; across 0->1 and 1->2 lies the unbounded
      // face, across 2->0 the upper triangle.
      { step: { neighbours: { at: [3, 1] } }, answer: { faces: [null, HIGH] } },
      { step: { face_boundary: { at: [1, 2] } }, answer: { face: HIGH, outer: HIGH, holes: [] } },
      // y = 1 from x = -1 to 5: crosses 3-0 at x = 0, the diagonal at x = 1,
      // 1-2 at x = 4.
      { step: { stab: { from: [-1, 1], to: [5, 1] } }, answer: stab([null, HIGH, LOW, null]) },
      // 1-3 crosses the diagonal at (2, 2).
      { step: { add_edge: { from: 1, to: 3 } }, answer: ERROR, state: split },
      { step: { remove_edge: { edge: [2, 0] } }, answer: OK, state: start },
      { step: { locate: { at: [3, 1] } }, answer: { face: SQ } },
    ],
    start,
    true,
  );
}

// B: a triangle inside a square (a hole), a bridge to it added and removed,
// a cycle closed around it, a split and a merge.
//
//   3 (0,8) ---------- 2 (8,8)
//   |   6 (2,4)           |
//   |   4 (2,2)  5 (4,2)  |
//   0 (0,0) ---------- 1 (8,0)
//
// The triangle's face: [4, 5, 6]; its outside, a hole of the square's face,
// runs clockwise: 4 -> 6 -> 5, [4, 6, 5].
// The bridge 0-4: at 0 the edges are 0->1 (0), 0->4 (45), 0->3 (90); at 4:
// 4->5 (0), 4->6 (90), 4->0 (225). next(3->0) = 0->4, next(0->4) = 4->6,
// then 6->5, 5->4, next(5->4) = 4->0, next(4->0) = 0->1: the square's outer
// cycle becomes [0, 1, 2, 3, 0, 4, 6, 5, 4], the bridge on it both ways.
// Closing 1-8-3 (8 at (6, 6)): at 1: 1->2 (90), 1->8 (108), 1->0 (180); at
// 8: 8->3 (162), 8->1 (288); at 3: 3->2 (0), 3->0 (270), 3->8 (342). So
// next(0->1) = 1->8, next(1->8) = 8->3, next(8->3) = 3->0: [0, 1, 8, 3]; and
// 1->2, 2->3, next(2->3) = 3->8, next(3->8) = 8->1: [1, 2, 3, 8]. The
// triangle and 7 (7, 1) lie below the chord 8-3 and left of 1-8 (at y = 1
// it is at x = 7.67): both move into [0, 1, 8, 3].
{
  const graph = {
    vertices: [[0, 0], [8, 0], [8, 8], [0, 8], [2, 2], [4, 2], [2, 4]],
    edges: [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 4]],
  };
  const SQ = [0, 1, 2, 3], TRI = [4, 5, 6], BRIDGED = [0, 1, 2, 3, 0, 4, 6, 5, 4];
  const LOW = [0, 1, 8, 3], HIGH = [1, 2, 3, 8];
  check("B (hole, bridge, closing a cycle)", graph, [
    { step: { face_boundary: { at: [1, 1] } }, answer: { face: SQ, outer: SQ, holes: [[4, 6, 5]] } },
    { step: { locate: { at: [2.5, 2.5] } }, answer: { face: TRI } },
    { step: { add_edge: { from: 0, to: 4 } }, answer: OK },
    { step: { face_boundary: { at: [1, 5] } }, answer: { face: BRIDGED, outer: BRIDGED, holes: [] } },
    // The bridge has the square's face on both sides: not a neighbour.
    { step: { neighbours: { at: [1, 5] } }, answer: { faces: [null, TRI] } },
    { step: { neighbours: { at: [3, 2.5] } }, answer: { faces: [BRIDGED] } },
    { step: { remove_edge: { edge: [4, 0] } }, answer: OK },
    { step: { face_boundary: { at: [1, 1] } }, answer: { face: SQ, outer: SQ, holes: [[4, 6, 5]] } },
    { step: { add_vertex: { at: [7, 1] } }, answer: OK }, // vertex 7
    { step: { add_vertex: { at: [6, 6] } }, answer: OK }, // vertex 8
    // 1-8 from (8, 0) to (6, 6) passes (7.67, 1), not 7: a dangling edge.
    { step: { add_edge: { from: 1, to: 8 } }, answer: OK },
    { step: { locate: { at: [7, 3] } }, answer: { edge: [1, 8] } },
    { step: { add_edge: { from: 8, to: 3 } }, answer: OK },
    { step: { face_boundary: { at: [3, 5] } }, answer: { face: LOW, outer: LOW, holes: [[4, 6, 5]] } },
    { step: { face_boundary: { at: [7, 7] } }, answer: { face: HIGH, outer: HIGH, holes: [] } },
    { step: { neighbours: { at: [7, 7] } }, answer: { faces: [null, LOW] } },
    { step: { split_edge: { edge: [8, 1], at: [7, 3] } }, answer: OK }, // vertex 9, halfway
    { step: { locate: { at: [7, 3] } }, answer: { vertex: 9 } },
    { step: { face_boundary: { at: [7, 7] } }, answer: { face: [1, 2, 3, 8, 9], outer: [1, 2, 3, 8, 9], holes: [] } },
    { step: { merge_collinear_edges: { vertex: 9 } }, answer: OK },
    // 0's two neighbours, 1 (8, 0) and 3 (0, 8), are not in line with it.
    { step: { merge_collinear_edges: { vertex: 0 } }, answer: ERROR },
    // y = x from (1, 1): into the triangle at its corner 4 (between 4->5 at
    // 0 and 4->6 at 90), out across 5-6 at (3, 3), through 8 (6, 6) into
    // the wedge between 8->1 (288) and 8->3 (162) that holds 45: HIGH.
    { step: { stab: { from: [1, 1], to: [7, 7] } }, answer: stab([LOW, TRI, LOW, HIGH]) },
  ], {
    faces: [
      { outer: null, holes: [[1, 0, 3, 2]], isolated: [] },
      { outer: LOW, holes: [[4, 6, 5]], isolated: [7] },
      { outer: HIGH, holes: [], isolated: [] },
      { outer: TRI, holes: [], isolated: [] },
    ],
    vertices: [[0, 0], [8, 0], [8, 8], [0, 8], [2, 2], [4, 2], [2, 4], [7, 1], [6, 6], null],
  });
}

// C: every kind of refusal, ids never reused, stabs along edges and through
// vertices.
//
//   3 (0,4) ------- 2 (4,4)
//                      |        5 (2,2), 6 (6,2) isolated
//   0 (0,0) ------- 1 (4,0) ------- 4 (8,0)
//
// Degrees: 0: 1, 1: 3, 2: 2 (not in line), 3: 1, 4: 1, 5 and 6: 0.
// Closing 0-3 at the end makes the square [0, 1, 2, 3] around 5; the
// unbounded face's hole is then the square clockwise with the dangling 1-4:
// 1->0, next = 0->3, 3->2, 2->1, then at 1 (1->4 at 0, 1->2 at 90, 1->0 at
// 180) next(2->1) = 1->4, 4->1, next(4->1) = 1->0: [1, 0, 3, 2, 1, 4].
{
  const graph = {
    vertices: [[0, 0], [4, 0], [4, 4], [0, 4], [8, 0], [2, 2], [6, 2]],
    edges: [[0, 1], [1, 2], [2, 3], [1, 4]],
  };
  const SQ = [0, 1, 2, 3];
  check("C (refusals, ids, stabs)", graph, [
    { step: { add_edge: { from: 0, to: 0 } }, answer: ERROR }, // u == v
    { step: { add_edge: { from: 0, to: 1 } }, answer: ERROR }, // joined already
    { step: { add_edge: { from: 1, to: 0 } }, answer: ERROR }, // the same, named backwards
    { step: { add_edge: { from: 0, to: 17 } }, answer: ERROR }, // no vertex 17
    { step: { add_edge: { from: 0, to: 2 } }, answer: ERROR }, // through the isolated 5 (2, 2)
    { step: { add_edge: { from: 0, to: 6 } }, answer: ERROR }, // crosses 1-2 at (4, 4/3)
    { step: { add_edge: { from: 0, to: 4 } }, answer: ERROR }, // overlaps 0-1 and 1-4
    { step: { add_edge_to_point: { from: 6, to: [6, 0] } }, answer: ERROR }, // ends inside 1-4
    { step: { add_edge_to_point: { from: 3, to: [2, 2] } }, answer: ERROR }, // ends at vertex 5
    { step: { add_edge_to_point: { from: 5, to: [6, 6] } }, answer: ERROR }, // through vertex 2 (4, 4)
    { step: { add_edge_to_point: { from: 4, to: [10, 0] } }, answer: OK }, // vertex 7 at (10, 0)
    { step: { add_edge_to_point: { from: 7, to: [9, 0] } }, answer: ERROR }, // ends inside 4-7
    { step: { add_edge_to_point: { from: 0, to: [-1, 0] } }, answer: OK }, // vertex 8: goes the other way from 0-1
    { step: { add_vertex: { at: [4, 2] } }, answer: ERROR }, // inside 1-2
    { step: { add_vertex: { at: [8, 0] } }, answer: ERROR }, // vertex 4
    { step: { add_vertex: { at: [Infinity, 0] } }, answer: ERROR }, // not finite
    { step: { split_edge: { edge: [0, 1], at: [5, 0] } }, answer: ERROR }, // beyond its end
    { step: { split_edge: { edge: [0, 1], at: [4, 0] } }, answer: ERROR }, // at its end
    { step: { split_edge: { edge: [0, 1], at: [2, 0.5] } }, answer: ERROR }, // off the line
    { step: { split_edge: { edge: [0, 1], at: [2, -Infinity] } }, answer: ERROR }, // not finite
    { step: { split_edge: { edge: [0, 2], at: [2, 2] } }, answer: ERROR }, // no edge 0-2
    { step: { remove_edge: { edge: [0, 2] } }, answer: ERROR }, // no edge 0-2
    { step: { remove_edge: { edge: [5, 6] } }, answer: ERROR }, // two isolated vertices
    { step: { remove_edge: { edge: [0, 99] } }, answer: ERROR }, // no vertex 99
    { step: { remove_isolated_vertex: { vertex: 1 } }, answer: ERROR }, // has edges
    { step: { merge_collinear_edges: { vertex: 1 } }, answer: ERROR }, // three edges
    { step: { merge_collinear_edges: { vertex: 2 } }, answer: ERROR }, // two, not in line
    { step: { merge_collinear_edges: { vertex: 5 } }, answer: ERROR }, // none
    { step: { remove_isolated_vertex: { vertex: 6 } }, answer: OK },
    { step: { remove_isolated_vertex: { vertex: 6 } }, answer: ERROR }, // removed already
    { step: { add_edge: { from: 5, to: 6 } }, answer: ERROR }, // 6 was removed
    { step: { add_vertex: { at: [6, 2] } }, answer: OK }, // vertex 9: 6 is never reused
    { step: { locate: { at: [6, 2] } }, answer: { vertex: 9 } },
    { step: { remove_edge: { edge: [7, 4] } }, answer: OK }, // 7 left isolated
    { step: { remove_isolated_vertex: { vertex: 7 } }, answer: OK },
    { step: { remove_edge: { edge: [0, 8] } }, answer: OK },
    { step: { remove_isolated_vertex: { vertex: 8 } }, answer: OK },
    { step: { split_edge: { edge: [1, 4], at: [6, 0] } }, answer: OK }, // vertex 10
    { step: { merge_collinear_edges: { vertex: 10 } }, answer: OK },
    { step: { merge_collinear_edges: { vertex: 10 } }, answer: ERROR }, // removed by the merge
    { step: { add_edge: { from: 0, to: 3 } }, answer: OK }, // closes the square around 5
    // Along the x axis: the unbounded face, then along 0-1 and 1-4 (no
    // face), then the unbounded face again: one face once merged.
    { step: { stab: { from: [-2, 0], to: [10, 0] } }, answer: stab([null]) },
    // x = 2: across 0-1 into the square, through the isolated 5 (still the
    // square), across 2-3 out.
    { step: { stab: { from: [2, -1], to: [2, 5] } }, answer: stab([null, SQ, null]) },
    // y = x: through the corner 0, through 5, through the corner 2.
    { step: { stab: { from: [-1, -1], to: [5, 5] } }, answer: stab([null, SQ, null]) },
    { step: { stab: { from: [1, 0], to: [3, 0] } }, answer: stab([]) }, // along 0-1 only
    { step: { stab: { from: [4, 0], to: [8, 0] } }, answer: stab([]) }, // vertex to vertex along 1-4
    { step: { stab: { from: [1, 1], to: [1, 1] } }, answer: stab([SQ]) }, // a point in a face
    { step: { stab: { from: [4, 0], to: [4, 0] } }, answer: stab([]) }, // a point at a vertex
    { step: { stab: { from: [2, 2], to: [2, 2] } }, answer: stab([]) }, // at the isolated 5
    { step: { stab: { from: [2, 4], to: [2, 4] } }, answer: stab([]) }, // a point inside an edge
    // From inside 1-4 across it, up through the isolated 9 (6, 2).
    { step: { stab: { from: [6, 0], to: [6, 3] } }, answer: stab([null]) },
    // From inside 1-2 out of the square, ending at the isolated 9.
    { step: { stab: { from: [4, 2], to: [6, 2] } }, answer: stab([null]) },
    // From inside 1-2 into the square, ending at the corner 3.
    { step: { stab: { from: [4, 2], to: [0, 4] } }, answer: stab([SQ]) },
    { step: { face_boundary: { at: [2, 2] } }, answer: { vertex: 5 } }, // at a vertex: as locate
    { step: { neighbours: { at: [0, 2] } }, answer: { edge: [3, 0] } }, // on an edge: as locate
    { step: { neighbours: { at: [1, 1] } }, answer: { faces: [null] } },
    { step: { neighbours: { at: [9, 9] } }, answer: { faces: [SQ] } },
    { step: { face_boundary: { at: [9, 9] } }, answer: { face: null, outer: null, holes: [[1, 0, 3, 2, 1, 4]] } },
  ], {
    faces: [
      { outer: null, holes: [[1, 0, 3, 2, 1, 4]], isolated: [9] },
      { outer: SQ, holes: [], isolated: [5] },
    ],
    vertices: [[0, 0], [4, 0], [4, 4], [0, 4], [8, 0], [2, 2], null, null, null, [6, 2], null],
  });
}

// E: nested holes, placed the same however the graph is listed (a hole's
// own triangle must not count as around it, whichever vertex is tested).
//
//   square 0 (0,0) 1 (12,0) 2 (12,12) 3 (0,12)
//   triangle 4 (2,2) 5 (10,2) 6 (2,10), and inside it 7 (3,3) 8 (6,3) 9 (3,6)
//   isolated: 10 (4,4) inside the small triangle (4 + 4 <= 9), 11 (7,4)
//   between the triangles (9 < 7 + 4 <= 12)
//
// Each triangle's outside is a hole of the face around it, walked
// clockwise: [4, 6, 5] in the square's face, [7, 9, 8] in the big
// triangle's.
{
  const vertices = [[0, 0], [12, 0], [12, 12], [0, 12], [2, 2], [10, 2], [2, 10], [3, 3], [6, 3], [3, 6], [4, 4], [7, 4]];
  const square = [[0, 1], [1, 2], [2, 3], [3, 0]];
  const big = [[4, 5], [5, 6], [6, 4]];
  const small = [[7, 8], [8, 9], [9, 7]];
  const rotate = (es, k) => [...es.slice(k), ...es.slice(0, k)];
  const flip = (es) => es.map(([u, v]) => [v, u]);
  const listings = [
    [...square, ...big, ...small],
    [...rotate(small, 1), ...rotate(big, 1), ...square],
    [...flip(rotate(big, 2)), ...flip(small), ...flip(square)],
    [...rotate(flip(small), 2), ...square, ...rotate(flip(big), 1)],
  ];
  listings.forEach((edges, i) =>
    check(`E (nested holes, listing ${i})`, { vertices, edges }, [
      { step: { locate: { at: [4, 3.5] } }, answer: { face: [7, 8, 9] } },
      { step: { locate: { at: [8, 3] } }, answer: { face: [4, 5, 6] } },
      { step: { locate: { at: [1, 1] } }, answer: { face: [0, 1, 2, 3] } },
      // y = 3.5 from x = 1 to 11: square, big triangle (across 6-4), small
      // triangle (across 9-7), big (across 8-9), square (across 5-6).
      { step: { stab: { from: [1, 3.5], to: [11, 3.5] } }, answer: stab([[0, 1, 2, 3], [4, 5, 6], [7, 8, 9], [4, 5, 6], [0, 1, 2, 3]]) },
    ], {
      faces: [
        { outer: null, holes: [[1, 0, 3, 2]], isolated: [] },
        { outer: [0, 1, 2, 3], holes: [[4, 6, 5]], isolated: [] },
        { outer: [4, 5, 6], holes: [[7, 9, 8]], isolated: [11] },
        { outer: [7, 8, 9], holes: [], isolated: [10] },
      ],
      vertices,
    }),
  );
}

// D: exactness. d = 2^-1000; a lone edge from 0 (0, 0) to 1 (3, d), and
// points beside it by one unit in the last place; the subnormal 2^-1074, and
// -0.
{
  const d = 2 ** -1000;
  const tiny = 5e-324; // 2^-1074, the smallest positive double
  check("D (exactness)", { vertices: [[0, 0], [3, d], [0, 1]], edges: [[0, 1]] }, [
    // d / 3 is not a double (d is a power of two): (1, d / 3) rounded is off the edge.
    { step: { split_edge: { edge: [0, 1], at: [1, d / 3] } }, answer: ERROR },
    { step: { split_edge: { edge: [0, 1], at: [1.5, d / 2] } }, answer: OK }, // vertex 3, exactly halfway
    { step: { locate: { at: [0.75, d / 4] } }, answer: { edge: [0, 3] } },
    // One unit in the last place above the edge (d / 4 = 2^-1002, its ulp 2^-1054).
    { step: { locate: { at: [0.75, d / 4 + 2 ** -1054] } }, answer: { face: null } },
    { step: { add_vertex: { at: [-0, 1] } }, answer: ERROR }, // -0 and 0 are one point: vertex 2
    { step: { add_vertex: { at: [-0, -tiny] } }, answer: OK }, // vertex 4, just below 0
    // From 2 (0, 1) straight down: through the vertices 0 and 4.
    { step: { add_edge_to_point: { from: 2, to: [0, -1] } }, answer: ERROR },
    // Down to (-2^-1074, -1) instead: at y = 0 it passes 2^-1075 left of 0,
    // and left of 4 too; it touches nothing. Vertex 5.
    { step: { add_edge_to_point: { from: 2, to: [-tiny, -1] } }, answer: OK },
    { step: { add_edge: { from: 4, to: 2 } }, answer: ERROR }, // through vertex 0
    // 4-0, of length 2^-1074, right of the edge 2-5 all along.
    { step: { add_edge: { from: 4, to: 0 } }, answer: OK },
    { step: { locate: { at: [0, -tiny / 2] } }, answer: { vertex: 0 } }, // -2^-1075 rounds to -0: vertex 0
  ], {
    // The tree 4-0-3-1: from 0->3, next 3->1, 1->3, 3->0, then at 0 (0->3 at
    // a hair above 0 degrees, 0->4 at 270) next(3->0) = 0->4, then 4->0:
    // [0, 3, 1, 3, 0, 4]. The lone edge 2-5: [2, 5].
    faces: [{ outer: null, holes: [[0, 3, 1, 3, 0, 4], [2, 5]], isolated: [] }],
    vertices: [[0, 0], [3, d], [0, 1], [1.5, d / 2], [-0, -tiny], [-tiny, -1]],
  });
}

// ---------------------------------------------------------------- the program itself

// The exact answer line, through stdin and stdout, and --stream. The triangle
// 0 (0,0), 1 (1,0), 2 (0,1): from half-edge 0 (0->1) the cycle [0, 1, 2],
// from half-edge 1 (1->0) the cycle [1, 0, 2]; the bounded face is named by
// its first half-edge, [0, 1]. The refused add_vertex takes no id.
{
  const session =
    '{"vertices": [[0, 0], [1, 0], [0, 1]], "edges": [[0, 1], [1, 2], [2, 0]], "steps": [' +
    '{"locate": {"at": [0.25, 0.25]}}, {"add_vertex": {"at": [0, 0.5]}}, {"add_vertex": {"at": [-0.0, -5e-324]}}]}';
  const want =
    '{"steps": [{"face": [0, 1]}, {"error": "..."}, {"ok": true}], "state": {"faces": [' +
    '{"outer": null, "holes": [[1, 0, 2]], "isolated": [3]}, {"outer": [0, 1, 2], "holes": [], "isolated": []}], ' +
    '"vertices": [[0, 0], [1, 0], [0, 1], [-0, -5e-324]]}}';
  const masked = (out) => out.replace(/"error": "(?:[^"\\]|\\.)*"/g, '"error": "..."');
  const one = spawnSync(process.execPath, [program], { input: session + "\n", encoding: "utf8" });
  if (one.status !== 0 || masked(one.stdout) !== want + "\n") fail("one session on stdin", `exit ${one.status}, printed ${one.stdout}${one.stderr}`);
  const stream = spawnSync(process.execPath, [program, "--stream"], { input: `${session}\n\n${session}\n`, encoding: "utf8" });
  const lines = stream.stdout.split("\n");
  if (stream.status !== 0 || lines.length !== 3 || lines[2] !== "" || lines.slice(0, 2).some((l) => masked(l) !== want)) {
    fail("--stream", `exit ${stream.status}, printed ${show(stream.stdout)}${stream.stderr}`);
  }
}

if (failures.length === 0) {
  console.log("ok");
} else {
  for (const f of failures) console.log(f);
  console.log(`${failures.length} failed`);
  process.exit(1);
}
