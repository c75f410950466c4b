#!/usr/bin/env node
// Every boundary cycle of a planar straight-line graph, exactly, in
// JavaScript (Node, no packages): the same algorithm as examples/python, for
// the `dcel diff` protocol (docs/checking.md).
//
//   dcel_faces.mjs            one graph JSON on stdin, one answer on stdout
//   dcel_faces.mjs --stream   one graph per line in, one answer per line out
//
// Exact with BigInt: every finite double is an integer multiple of 2^-1074,
// so x * 2^1074 is an exact BigInt, and differences and cross products of
// those are exact too. Directions around a vertex are ordered by half-plane,
// then by the sign of a cross product: no Math.atan2, no epsilon.
import { createInterface } from "node:readline";

// x * 2^1074 as a BigInt, exactly, read from the bits of the double.
function scaled(x) {
  const view = new DataView(new ArrayBuffer(8));
  view.setFloat64(0, x);
  const hi = view.getUint32(0), lo = view.getUint32(4);
  const negative = hi >>> 31 === 1;
  const exponent = (hi >>> 20) & 0x7ff;
  const fraction = (BigInt(hi & 0xfffff) << 32n) | BigInt(lo);
  if (exponent === 0x7ff) throw new Error("coordinates must be finite");
  // normal: (2^52 + fraction) * 2^(exponent - 1075); subnormal: fraction * 2^-1074
  const value = exponent === 0 ? fraction : ((1n << 52n) | fraction) << BigInt(exponent - 1);
  return negative ? -value : value;
}

function readGraph(text) {
  let doc = JSON.parse(text);
  if (Array.isArray(doc)) doc = { vertices: doc[0], edges: doc[1] }; // the positional form
  const points = doc.vertices.map(([x, y]) => [scaled(x), scaled(y)]);
  const edges = doc.edges.map(([u, v]) => [u, v]);
  return { points, edges };
}

// 0 for directions of angle in [0, pi), 1 for [pi, 2 pi).
const halfPlane = ([dx, dy]) => (dy > 0n || (dy === 0n && dx > 0n) ? 0 : 1);

function counterclockwise(a, b) {
  const ha = halfPlane(a), hb = halfPlane(b);
  if (ha !== hb) return ha - hb;
  const cross = a[0] * b[1] - a[1] * b[0];
  return cross > 0n ? -1 : cross < 0n ? 1 : 0;
}

function faces({ points, edges }) {
  // Half-edge 2k is u->v of edge k, 2k+1 is v->u: twin(h) = h ^ 1.
  const origin = edges.flatMap(([u, v]) => [u, v]);
  const rings = points.map(() => []);
  origin.forEach((u, h) => rings[u].push(h));
  const direction = (h) => {
    const [x0, y0] = points[origin[h]], [x1, y1] = points[origin[h ^ 1]];
    return [x1 - x0, y1 - y0];
  };
  const position = new Array(origin.length);
  for (const ring of rings) {
    ring.sort((g, h) => counterclockwise(direction(g), direction(h)));
    ring.forEach((h, i) => (position[h] = i));
  }
  // next(h): the half-edge leaving target(h) just clockwise of twin(h).
  const next = origin.map((_, h) => {
    const ring = rings[origin[h ^ 1]];
    return ring[(position[h ^ 1] + ring.length - 1) % ring.length];
  });
  const seen = new Array(origin.length).fill(false);
  const cycles = [];
  for (let start = 0; start < origin.length; ++start) {
    if (seen[start]) continue;
    const cycle = [];
    for (let h = start; !seen[h]; h = next[h]) {
      seen[h] = true;
      cycle.push(origin[h]);
    }
    cycles.push(cycle);
  }
  return cycles;
}

const answer = (text) => JSON.stringify({ faces: faces(readGraph(text)) });

if (process.argv.slice(2).includes("--stream")) {
  // One answer line per graph line (written before the next line is read).
  for await (const line of createInterface({ input: process.stdin, crlfDelay: Infinity })) {
    if (line.trim() !== "") process.stdout.write(answer(line) + "\n");
  }
} else {
  let text = "";
  process.stdin.setEncoding("utf8");
  for await (const chunk of process.stdin) text += chunk;
  process.stdout.write(answer(text) + "\n");
}
