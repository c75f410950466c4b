#!/usr/bin/env node
// Edit sessions of a planar straight-line graph, answered by brute force, in
// JavaScript (Node, no packages): the `dcel diff --sessions` protocol
// (docs/checking.md, "Sessions: checking edits and queries").
//
//   dcel_session.mjs            one session JSON on stdin, one answer on stdout
//   dcel_session.mjs --stream   one session per line in, one answer per line out
//
// An oracle to be read, not a DCEL. It keeps only what the protocol names:
// the vertices (protocol id -> exact point, null once removed) and the set of
// edges. An edit checks its precondition exactly, refusing with
// {"error": "..."} and changing nothing exactly when the reference refuses
// (src/dcel/edit.hpp, edit/edit_checks.cpp), then changes those two. Every
// state and every query is computed from scratch (class Picture):
//   - next(u->v) is the half-edge leaving v just clockwise of v->u, as in
//     dcel_faces.mjs; the boundary cycles are its orbits;
//   - a cycle of positive signed area is the outer boundary of a bounded face
//     (the face on its left); every other cycle (area <= 0) is the outside of
//     a connected component: a hole of the face around it;
//   - that face, for a hole and for an isolated vertex, is the bounded face of
//     smallest area whose outer cycle winds around it (a vertex of it; the
//     cycles of the hole's own component left out), else the unbounded face.
//     Outer cycles are nested or disjoint, so the smallest is the innermost;
//   - a point that is on no vertex and no edge lies in the same way in the
//     face of the smallest outer cycle winding around it.
//
// Exact with BigInt, as dcel_faces.mjs: every finite double is an integer
// multiple of 2^-1074, so x * 2^1074 is an exact BigInt. Here each session
// holds its coordinates as x * 2^S for the smallest S that makes every
// number of its document an integer (S = 0 for integer coordinates, at most
// 1074): the same decisions, on smaller numbers. A point the queries make up
// (a point of a stab segment between two things it meets) is rational:
// (X / W, Y / W) with BigInts X, Y and W > 0. Every decision is the sign of
// an exact BigInt expression: no atan2, no epsilon.
//
// Names (the protocol's): vertex ids never change and are never reused (the
// start graph's are 0..V-1, each vertex a step creates takes the next id); an
// edge is named by its two ends; a bounded face by the first half-edge [u, v]
// of its outer cycle as the state prints it (the face on its left); the
// unbounded face by null.
import { createInterface } from "node:readline";
import { realpathSync } from "node:fs";
import { fileURLToPath } from "node:url";

// ---------------------------------------------------------------- exactness

// A finite double as m * 2^e exactly, m a BigInt (its sign the double's),
// -1074 <= e: read from the bits of the double.
function binary(x) {
  const view = new DataView(new ArrayBuffer(8));
  view.setFloat64(0, x);
  const hi = view.getUint32(0), lo = view.getUint32(4);
  const exponent = (hi >>> 20) & 0x7ff;
  const fraction = (BigInt(hi & 0xfffff) << 32n) | BigInt(lo);
  // normal: (2^52 + fraction) * 2^(exponent - 1075); subnormal: fraction * 2^-1074
  const m = exponent === 0 ? fraction : (1n << 52n) | fraction;
  return { m: hi >>> 31 === 1 ? -m : m, e: exponent === 0 ? -1074 : exponent - 1075 };
}

// The smallest S >= 0 for which every number in the document times 2^S is
// an integer (S <= 1074: every finite double is a multiple of 2^-1074). A
// session holds its coordinates as x * 2^S: exact, as small as it can be (S
// is 0 for integer coordinates), and every decision is the same at any scale.
function shiftFor(value) {
  if (typeof value === "number") {
    if (!Number.isFinite(value) || value === 0) return 0;
    let { m, e } = binary(value);
    while ((m & 1n) === 0n) [m, e] = [m >> 1n, e + 1];
    return Math.max(0, -e);
  }
  if (value !== null && typeof value === "object") return Object.values(value).reduce((s, v) => Math.max(s, shiftFor(v)), 0);
  return 0;
}

// x * 2^shift as a BigInt, exactly (an integer for the document's shift).
function scaled(x, shift) {
  const { m, e } = binary(x);
  if (e + shift >= 0) return m << BigInt(e + shift);
  const value = m >> BigInt(-(e + shift));
  if (value << BigInt(-(e + shift)) !== m) throw new Error(`${x} * 2^${shift} is no integer`); // never rounds
  return value;
}

const sign = (v) => (v > 0n ? 1 : v < 0n ? -1 : 0);

// A refused step: {"error": message}, and nothing changes. Any other Error
// means the document itself is malformed.
class Refusal extends Error {}
const refuse = (why) => {
  throw new Refusal(why);
};

// A point (X / W, Y / W), W > 0, with (bx, by) = (X / W, Y / W) rounded
// towards zero: within 1 of the point, so a point whose (bx, by) lies outside
// a box of integer corners (vertices' points are integers) lies outside it.
// A cheap first test, before the exact one.
const point = (X, Y, W = 1n) => ({ X, Y, W, bx: X / W, by: Y / W });
const outsideBox = (p, { loX, hiX, loY, hiY }) => p.bx < loX || p.bx > hiX || p.by < loY || p.by > hiY;
const boxOf = (a, b) => ({
  loX: a.X < b.X ? a.X : b.X,
  hiX: a.X < b.X ? b.X : a.X,
  loY: a.Y < b.Y ? a.Y : b.Y,
  hiY: a.Y < b.Y ? b.Y : a.Y,
});

// A point of the document: {x, y} the doubles as written (printed back as
// they are), and the point (x * 2^shift, y * 2^shift), W = 1.
function readPoint(value, what, shift) {
  if (!Array.isArray(value) || value.length !== 2 || value.some((c) => typeof c !== "number")) {
    throw new Error(`${what}: expected a point [x, y]`);
  }
  const [x, y] = value;
  // JSON.parse reads 1e999 as Infinity; the reference refuses such a point.
  if (!Number.isFinite(x) || !Number.isFinite(y)) refuse(`${what} (${x}, ${y}) is not finite`);
  return { x, y, ...point(scaled(x, shift), scaled(y, shift)) };
}

const text = (p) => `(${p.x}, ${p.y})`;

// ---------------------------------------------------------------- geometry
// a and b are always vertices or points of the document (W = 1); c, p may be
// made-up rational points.

// The side of c from the line a -> b: 1 left, -1 right, 0 on it.
function orient(a, b, c) {
  return sign((b.X - a.X) * (c.Y - a.Y * c.W) - (b.Y - a.Y) * (c.X - a.X * c.W));
}

const samePoint = (p, q) => p.X * q.W === q.X * p.W && p.Y * q.W === q.Y * p.W;

// Is p on the segment ab (a != b), and neither of its ends?
function strictlyInside(a, b, p) {
  if (outsideBox(p, boxOf(a, b)) || orient(a, b, p) !== 0) return false;
  const dx = b.X - a.X, dy = b.Y - a.Y;
  const pastA = (p.X - a.X * p.W) * dx + (p.Y - a.Y * p.W) * dy; // (p - a).(b - a), times W
  const beforeB = (b.X * p.W - p.X) * dx + (b.Y * p.W - p.Y) * dy; // (b - p).(b - a), times W
  return pastA > 0n && beforeB > 0n;
}

// Do the closed segments pq and ab meet anywhere but at an end they share?
// They do when an end of one lies strictly inside the other (a touch, or a
// collinear overlap), when they are the same segment, or when they cross at
// a point inside both. (Collinear segments that overlap in more than a point
// always have an end of one strictly inside the other, or are the same.)
function meetBeyondSharedEnd(p, q, a, b) {
  const box = boxOf(p, q), other = boxOf(a, b);
  if (other.hiX < box.loX || other.loX > box.hiX || other.hiY < box.loY || other.loY > box.hiY) return false;
  if (strictlyInside(p, q, a) || strictlyInside(p, q, b)) return true;
  if (strictlyInside(a, b, p) || strictlyInside(a, b, q)) return true;
  if ((samePoint(p, a) && samePoint(q, b)) || (samePoint(p, b) && samePoint(q, a))) return true;
  return orient(p, q, a) * orient(p, q, b) < 0 && orient(a, b, p) * orient(a, b, q) < 0;
}

// The winding number of a closed walk of vertex points around p, p on none
// of its edges (Sunday's crossing rule: an edge going up with p on its left
// counts +1, one going down with p on its right -1).
function winding(walk, p) {
  let w = 0;
  for (let i = 0; i < walk.length; ++i) {
    const a = walk[i], b = walk[(i + 1) % walk.length];
    const aBelow = a.Y * p.W <= p.Y, bBelow = b.Y * p.W <= p.Y;
    if (aBelow && !bBelow && orient(a, b, p) > 0) ++w;
    else if (!aBelow && bBelow && orient(a, b, p) < 0) --w;
  }
  return w;
}

// Directions around a vertex in counterclockwise order from angle 0: by
// half-plane (0 for angles in [0, pi), 1 for [pi, 2 pi)), then by the sign of
// the cross product.
const halfPlane = ([dx, dy]) => (dy > 0n || (dy === 0n && dx > 0n) ? 0 : 1);
function counterclockwise(a, b) {
  const ha = halfPlane(a), hb = halfPlane(b);
  if (ha !== hb) return ha - hb;
  const cross = a[0] * b[1] - a[1] * b[0];
  return cross > 0n ? -1 : cross < 0n ? 1 : 0;
}

// Rationals n / d with d > 0, for positions along a segment.
const compareRational = (s, t) => sign(s.n * t.d - t.n * s.d);

// ---------------------------------------------------------------- the subdivision

// Everything about the subdivision of the current vertices and edges, from
// scratch. Faces: index 0 is the unbounded face; each cycle of positive area
// makes one bounded face. A cycle is {halfEdges, vertices (their origins),
// walk (their points), area2 (twice its signed area), box, component, face}.
class Picture {
  constructor(points, edges) {
    this.points = points;
    this.edges = edges;
    // Half-edge 2k is u->v of edge k = [u, v], 2k+1 is v->u: twin(h) = h ^ 1.
    const origin = edges.flatMap(([u, v]) => [u, v]);
    const leaving = new Map(); // vertex -> its half-edges, counterclockwise
    origin.forEach((u, h) => {
      if (!leaving.has(u)) leaving.set(u, []);
      leaving.get(u).push(h);
    });
    const direction = origin.map((u, h) => {
      const p = points[u], q = points[origin[h ^ 1]];
      return [q.X - p.X, q.Y - p.Y];
    });
    const position = new Array(origin.length);
    for (const ring of leaving.values()) {
      ring.sort((g, h) => counterclockwise(direction[g], direction[h]));
      ring.forEach((h, i) => (position[h] = i));
    }
    // next(h): the half-edge leaving target(h) just clockwise of twin(h).
    const next = origin.map((_, h) => {
      const ring = leaving.get(origin[h ^ 1]);
      return ring[(position[h ^ 1] + ring.length - 1) % ring.length];
    });

    // Connected components, by union-find over the edges (with path halving).
    const parent = points.map((_, v) => v);
    const find = (v) => {
      while (parent[v] !== v) v = parent[v] = parent[parent[v]];
      return v;
    };
    for (const [u, v] of edges) parent[find(v)] = find(u);

    // The boundary cycles: the orbits of next, each from its smallest half-edge.
    this.cycleOf = new Array(origin.length);
    this.cycles = [];
    for (let start = 0; start < origin.length; ++start) {
      if (this.cycleOf[start] !== undefined) continue;
      const cycle = { halfEdges: [], vertices: [], walk: [], area2: 0n, component: find(origin[start]), face: 0 };
      cycle.box = boxOf(points[origin[start]], points[origin[start]]); // grown to its bounding box
      for (let h = start; this.cycleOf[h] === undefined; h = next[h]) {
        this.cycleOf[h] = this.cycles.length;
        const p = points[origin[h]], q = points[origin[h ^ 1]];
        cycle.halfEdges.push(h);
        cycle.vertices.push(origin[h]);
        cycle.walk.push(p);
        cycle.area2 += p.X * q.Y - p.Y * q.X;
        const box = cycle.box;
        if (p.X < box.loX) box.loX = p.X;
        if (p.X > box.hiX) box.hiX = p.X;
        if (p.Y < box.loY) box.loY = p.Y;
        if (p.Y > box.hiY) box.hiY = p.Y;
      }
      this.cycles.push(cycle);
    }

    // The faces: their outer cycles first, then where each hole and
    // isolated vertex lies.
    this.faces = [{ outer: null, holes: [], isolated: [] }];
    for (const c of this.cycles) {
      if (c.area2 > 0n) {
        c.face = this.faces.length;
        this.faces.push({ outer: c, holes: [], isolated: [] });
      }
    }
    for (const c of this.cycles) {
      if (c.area2 <= 0n) {
        c.face = this.faceAround(c.walk[0], c.component);
        this.faces[c.face].holes.push(c);
      }
    }
    points.forEach((p, v) => {
      if (p !== null && !leaving.has(v)) this.faces[this.faceAround(p, null)].isolated.push(v);
    });
  }

  // The face whose interior holds p, which is on no edge and at no vertex
  // except those of `component` (whose cycles are left out): the bounded
  // face of the smallest outer cycle that winds around p, else the unbounded
  // face.
  faceAround(p, component) {
    let best = 0;
    for (let f = 1; f < this.faces.length; ++f) {
      const c = this.faces[f].outer;
      // Outside the cycle's box, the winding number is 0: a shortcut.
      if (c.component === component || outsideBox(p, c.box) || winding(c.walk, p) === 0) continue;
      if (best === 0 || c.area2 < this.faces[best].outer.area2) best = f;
    }
    return best;
  }

  // Where p is: {vertex: v}, {edge: [u, v]} (p strictly inside it), or
  // {face: f} (an index into this.faces).
  where(p) {
    const v = this.points.findIndex((q) => q !== null && samePoint(p, q));
    if (v >= 0) return { vertex: v };
    const e = this.edges.find(([a, b]) => strictlyInside(this.points[a], this.points[b], p));
    if (e) return { edge: [e[0], e[1]] };
    return { face: this.faceAround(p, null) };
  }

  // A face's protocol name: null, or the first half-edge of its outer cycle.
  name(f) {
    return f === 0 ? null : this.faces[f].outer.vertices.slice(0, 2);
  }

  // The faces across the edges of f's cycles (outer and holes), f left out.
  neighbours(f) {
    const { outer, holes } = this.faces[f];
    const found = new Set();
    for (const c of outer ? [outer, ...holes] : holes) {
      for (const h of c.halfEdges) {
        const g = this.cycles[this.cycleOf[h ^ 1]].face; // the face across
        if (g !== f) found.add(g);
      }
    }
    return [...found].sort((a, b) => a - b);
  }

  // The faces of the open stretches of the segment a -> b that lie inside
  // faces, in order, a repeat of the face before merged. The segment is cut
  // at every vertex on it and every edge crossing it; between two cuts the
  // open stretch meets nothing, so it runs along one edge (no face) or lies
  // in one face, the face of its midpoint. When a == b: the face a lies in,
  // if it lies in one.
  stab(a, b) {
    if (samePoint(a, b)) {
      const at = this.where(a);
      return at.face !== undefined ? [at.face] : [];
    }
    // The segment is a + t (b - a), 0 <= t <= 1; the cuts are values of t.
    const dx = b.X - a.X, dy = b.Y - a.Y;
    const cuts = [{ n: 0n, d: 1n }, { n: 1n, d: 1n }];
    const inside = (t) => t.n > 0n && t.n < t.d;
    const length2 = dx * dx + dy * dy;
    // Only what meets the segment's box can cut it or be run along.
    const box = boxOf(a, b);
    for (const p of this.points) {
      if (p === null || outsideBox(p, box) || orient(a, b, p) !== 0) continue;
      const t = { n: (p.X - a.X) * dx + (p.Y - a.Y) * dy, d: length2 };
      if (inside(t)) cuts.push(t);
    }
    const onLine = []; // the edges on the line, which the segment may run along
    for (const [u, v] of this.edges) {
      const p = this.points[u], q = this.points[v];
      const { loX, hiX, loY, hiY } = boxOf(p, q);
      if (hiX < box.loX || loX > box.hiX || hiY < box.loY || loY > box.hiY) continue;
      const sp = orient(a, b, p), sq = orient(a, b, q);
      if (sp === 0 && sq === 0) onLine.push([p, q]);
      if (sp * sq >= 0) continue; // p and q not strictly on opposite sides: no crossing
      // a + t (b - a) = p + s (q - p): t = cross(p - a, q - p) / cross(b - a, q - p).
      const ex = q.X - p.X, ey = q.Y - p.Y;
      let n = (p.X - a.X) * ey - (p.Y - a.Y) * ex;
      let d = dx * ey - dy * ex;
      if (d < 0n) [n, d] = [-n, -d];
      if (inside({ n, d })) cuts.push({ n, d });
    }
    cuts.sort(compareRational);
    const faces = [];
    for (let i = 0; i + 1 < cuts.length; ++i) {
      const s = cuts[i], t = cuts[i + 1];
      if (compareRational(s, t) === 0) continue;
      // The midpoint of the stretch: t = (s + t) / 2 = n / d.
      const n = s.n * t.d + t.n * s.d, d = 2n * s.d * t.d;
      const mid = point(a.X * d + n * dx, a.Y * d + n * dy, d);
      // mid is at no vertex (that would be a cut), and inside an edge only
      // when the stretch runs along it.
      if (onLine.some(([p, q]) => strictlyInside(p, q, mid))) continue;
      const f = this.faceAround(mid, null);
      if (faces.length === 0 || faces[faces.length - 1] !== f) faces.push(f);
    }
    return faces;
  }
}

// ---------------------------------------------------------------- a session

const edgeKey = (u, v) => (u < v ? `${u},${v}` : `${v},${u}`);

const EDITS = new Set([
  "split_edge",
  "add_vertex",
  "add_edge",
  "add_edge_to_point",
  "remove_edge",
  "remove_isolated_vertex",
  "merge_collinear_edges",
]);
const QUERIES = new Set(["locate", "face_boundary", "neighbours", "stab"]);

// Exported for tests (the self-test, a generator of sessions).
export class Session {
  constructor(doc) {
    if (!Array.isArray(doc.vertices) || !Array.isArray(doc.edges)) throw new Error("a session needs vertices and edges");
    this.shift = shiftFor([doc.vertices, doc.steps]); // coordinates are held as x * 2^shift
    this.points = doc.vertices.map((p, v) => {
      try {
        return this.read(p, `vertex ${v}`);
      } catch (e) {
        throw new Error(`the start graph is not valid: ${e.message}`);
      }
    });
    this.edges = new Map(); // edgeKey -> [u, v]
    for (const [u, v] of doc.edges) this.edges.set(edgeKey(u, v), [u, v]);
    this.cached = null;
  }

  get picture() {
    return (this.cached ??= new Picture(this.points, [...this.edges.values()]));
  }

  read(value, what) {
    return readPoint(value, what, this.shift);
  }

  // ---- names

  // The point of vertex id u; refused when there is none (never was, or removed).
  vertex(u) {
    if (!Number.isInteger(u) || u < 0) throw new Error(`${JSON.stringify(u)} is not a vertex id`);
    if (u >= this.points.length) refuse(`vertex ${u} does not exist`);
    if (this.points[u] === null) refuse(`vertex ${u} was removed earlier in the session`);
    return this.points[u];
  }

  requireEdge(pair) {
    if (!Array.isArray(pair) || pair.length !== 2) throw new Error("an edge is [u, v]");
    const [u, v] = pair;
    this.vertex(u);
    this.vertex(v);
    if (!this.edges.has(edgeKey(u, v))) refuse(`there is no edge [${u}, ${v}]`);
    return [u, v];
  }

  edgesAt(v) {
    return [...this.edges.values()].filter(([a, b]) => a === v || b === v);
  }

  // ---- the changes (each after its checks)

  newVertex(p) {
    this.points.push(p);
    return this.points.length - 1;
  }

  addEdge(u, v) {
    this.edges.set(edgeKey(u, v), [u, v]);
  }

  removeEdge(u, v) {
    this.edges.delete(edgeKey(u, v));
  }

  // ---- the checks shared by the edits

  // p is at no vertex and strictly inside no edge.
  requireFree(p, edit) {
    const v = this.points.findIndex((q) => q !== null && samePoint(p, q));
    if (v >= 0) refuse(`${edit}: the point ${text(p)} is vertex ${v} already`);
    for (const [a, b] of this.edges.values()) {
      if (strictlyInside(this.points[a], this.points[b], p)) {
        refuse(`${edit}: the point ${text(p)} lies inside edge [${a}, ${b}]`);
      }
    }
  }

  // The segment from vertex u to q (vertex v's point, or a free new point
  // when v is null) meets the graph only at u and v: it crosses, overlaps or
  // touches no edge, and no other vertex lies on it.
  requireClear(u, q, v, edit) {
    const p = this.points[u];
    const segment = `the segment from ${text(p)} to ${text(q)}`;
    for (const [a, b] of this.edges.values()) {
      if (meetBeyondSharedEnd(p, q, this.points[a], this.points[b])) {
        refuse(`${edit}: ${segment} crosses, overlaps or touches edge [${a}, ${b}]`);
      }
    }
    this.points.forEach((r, w) => {
      // Another vertex on the closed segment can only be strictly inside it:
      // the ends are u's point and v's (or a free point).
      if (r !== null && w !== u && w !== v && strictlyInside(p, q, r)) {
        refuse(`${edit}: ${segment} passes through vertex ${w}`);
      }
    });
  }

  // ---- the edits: each returns {ok: true} or refuses, changing nothing

  split_edge({ edge, at }) {
    const [u, v] = this.requireEdge(edge);
    const p = this.read(at, "split_edge: the point");
    if (!strictlyInside(this.points[u], this.points[v], p)) {
      refuse(`split_edge: the point ${text(p)} is not exactly on edge [${u}, ${v}] strictly between its ends`);
    }
    const w = this.newVertex(p);
    this.removeEdge(u, v);
    this.addEdge(u, w);
    this.addEdge(w, v);
  }

  add_vertex({ at }) {
    const p = this.read(at, "add_vertex: the point");
    this.requireFree(p, "add_vertex");
    this.newVertex(p);
  }

  add_edge({ from: u, to: v }) {
    this.vertex(u);
    this.vertex(v);
    if (u === v) refuse(`add_edge: an edge needs two different vertices, but both ends are ${u}`);
    if (this.edges.has(edgeKey(u, v))) refuse(`add_edge: ${u} and ${v} are already joined`);
    this.requireClear(u, this.points[v], v, "add_edge");
    this.addEdge(u, v);
  }

  add_edge_to_point({ from: u, to }) {
    this.vertex(u);
    const p = this.read(to, "add_edge_to_point: the point");
    this.requireFree(p, "add_edge_to_point");
    this.requireClear(u, p, null, "add_edge_to_point");
    this.addEdge(u, this.newVertex(p));
  }

  remove_edge({ edge }) {
    const [u, v] = this.requireEdge(edge);
    this.removeEdge(u, v);
  }

  remove_isolated_vertex({ vertex: v }) {
    this.vertex(v);
    const n = this.edgesAt(v).length;
    if (n !== 0) refuse(`remove_isolated_vertex: vertex ${v} has ${n} edge(s); remove them first`);
    this.points[v] = null;
  }

  merge_collinear_edges({ vertex: v }) {
    const p = this.vertex(v);
    const at = this.edgesAt(v);
    if (at.length !== 2) refuse(`merge_collinear_edges: vertex ${v} has ${at.length} edge(s); merging needs exactly two`);
    const [a, b] = at.map(([x, y]) => (x === v ? y : x));
    if (!strictlyInside(this.points[a], this.points[b], p)) {
      refuse(`merge_collinear_edges: vertex ${v} is not exactly on the segment from vertex ${a} to vertex ${b}`);
    }
    this.removeEdge(v, a);
    this.removeEdge(v, b);
    this.addEdge(a, b);
    this.points[v] = null;
  }

  // ---- the queries

  // A point at a vertex or on an edge is answered as locate answers it, by
  // every query but stab.
  located(at) {
    if (at.vertex !== undefined) return { vertex: at.vertex };
    if (at.edge !== undefined) return { edge: at.edge };
    return null;
  }

  locate({ at }) {
    const pic = this.picture;
    const where = pic.where(this.read(at, "locate: the point"));
    return this.located(where) ?? { face: pic.name(where.face) };
  }

  face_boundary({ at }) {
    const pic = this.picture;
    const where = pic.where(this.read(at, "face_boundary: the point"));
    const located = this.located(where);
    if (located) return located;
    const { outer, holes } = pic.faces[where.face];
    return { face: pic.name(where.face), outer: outer && outer.vertices, holes: holes.map((c) => c.vertices) };
  }

  neighbours({ at }) {
    const pic = this.picture;
    const where = pic.where(this.read(at, "neighbours: the point"));
    return this.located(where) ?? { faces: pic.neighbours(where.face).map((g) => pic.name(g)) };
  }

  stab({ from, to }) {
    const pic = this.picture;
    const a = this.read(from, "stab: from"), b = this.read(to, "stab: to");
    return { faces: pic.stab(a, b).map((f) => pic.name(f)) };
  }

  // ---- steps and state

  // One step: {"operation": {operands}}. An edit answers {ok: true} or
  // {error}; a query its answer.
  apply(step) {
    const keys = step !== null && typeof step === "object" ? Object.keys(step) : [];
    const op = keys[0];
    if (keys.length !== 1 || !(EDITS.has(op) || QUERIES.has(op))) throw new Error(`not a step: ${JSON.stringify(step)}`);
    const operands = { ...step[op] };
    // session_io.cpp reads "point" as "at" too (not in docs/checking.md).
    if (operands.at === undefined && operands.point !== undefined) operands.at = operands.point;
    try {
      if (QUERIES.has(op)) return this[op](operands);
      this[op](operands);
      this.cached = null;
      return { ok: true };
    } catch (e) {
      if (e instanceof Refusal) return { error: e.message };
      throw e;
    }
  }

  // Every face as a record, and every protocol id's point (null: removed).
  state() {
    const pic = this.picture;
    return {
      faces: pic.faces.map(({ outer, holes, isolated }) => ({
        outer: outer && outer.vertices,
        holes: holes.map((c) => c.vertices),
        isolated,
      })),
      vertices: this.points.map((p) => p && [p.x, p.y]),
    };
  }
}

// The answer to a session document: one answer per step (with "each_step":
// true, each edit's carries the state after it, refused or not) and the
// state after the last.
export function runSession(doc) {
  if (doc === null || typeof doc !== "object" || !Array.isArray(doc.steps)) {
    throw new Error('a session is {"vertices": [...], "edges": [...], "steps": [...]}');
  }
  const session = new Session(doc);
  const steps = doc.steps.map((step) => {
    const reply = session.apply(step);
    if (doc.each_step === true && EDITS.has(Object.keys(step)[0])) reply.state = session.state();
    return reply;
  });
  return { steps, state: session.state() };
}

// JSON with every number as JSON.stringify writes it (the shortest decimal
// that reads back as the same double), except -0, kept as "-0".
export function toJson(value) {
  if (typeof value === "number") return Object.is(value, -0) ? "-0" : JSON.stringify(value);
  if (Array.isArray(value)) return `[${value.map(toJson).join(", ")}]`;
  if (value !== null && typeof value === "object") {
    return `{${Object.entries(value)
      .map(([k, v]) => `${JSON.stringify(k)}: ${toJson(v)}`)
      .join(", ")}}`;
  }
  return JSON.stringify(value);
}

// One session's text in, one answer line out. A document that is no session
// (or a start graph that is not valid) is answered {"refused": why}, the
// protocol's answer for input a program rejects (a failure in dcel diff,
// which sends only valid sessions), and the stack goes to stderr.
export function answer(text) {
  try {
    return toJson(runSession(JSON.parse(text)));
  } catch (e) {
    process.stderr.write(`dcel_session.mjs: ${e.stack}\n`);
    return toJson({ refused: e.message });
  }
}

async function main() {
  if (process.argv.slice(2).includes("--stream")) {
    // One answer line per session line (written before the next line is read).
    for await (const line of createInterface({ input: process.stdin, crlfDelay: Infinity })) {
      if (line.trim() !== "") process.stdout.write(answer(line) + "\n");
    }
  } else {
    let input = "";
    process.stdin.setEncoding("utf8");
    for await (const chunk of process.stdin) input += chunk;
    process.stdout.write(answer(input) + "\n");
  }
}

// Run as a program (not imported, as the self-test does).
if (process.argv[1] && realpathSync(process.argv[1]) === fileURLToPath(import.meta.url)) await main();
