// Stabbing: the faces, edges and vertices that a segment or a line meets,
// in order along it (the "faces cut by a line" query of de Berg et al., ch. 2).
//
// The walk starts where the segment starts (or, for a line, at an edge the
// line meets) and goes from face to face: from each face to the next thing
// the line meets (a vertex on it, an edge it crosses), steps across it, and
// continues. Every decision is exact: crossing points are never computed,
// only ordered (line_order.hpp).
//
// Costs: O(V + E + k log k) for k pieces: one pass over the vertices and
// edges finds everything on the line, which is then sorted along it (the
// walk moves from one to the next by binary search, so re-entering a large
// face costs nothing extra), plus the degrees of the vertices passed
// through. stab_segment adds O(V + E) to locate the start.
#pragma once

#include <vector>

#include "dcel/dcel.hpp"

namespace dcel {

struct StabPiece {
    enum class Kind : unsigned char { Face, Edge, Vertex };
    Kind kind = Kind::Face;
    FaceId face;         // Face: the open stretch lies inside this face
    EdgeId edge;         // Edge: crossed at one interior point, or run along
    VertexId vertex;     // Vertex: passed through (or started or ended at)
    bool along = false;  // Edge: true when the stretch runs along the edge

    [[nodiscard]] static StabPiece in_face(FaceId f) { return {Kind::Face, f, {}, {}, false}; }
    [[nodiscard]] static StabPiece across(EdgeId e) { return {Kind::Edge, {}, e, {}, false}; }
    [[nodiscard]] static StabPiece along_edge(EdgeId e) { return {Kind::Edge, {}, e, {}, true}; }
    [[nodiscard]] static StabPiece at(VertexId v) { return {Kind::Vertex, {}, {}, v, false}; }
    friend bool operator==(const StabPiece&, const StabPiece&) = default;
};

// Everything the closed segment from a to b meets, in order from a: starting
// with where a lies and ending with where b lies (a single piece when a == b).
// Requires finite coordinates (InvalidInput otherwise).
[[nodiscard]] std::vector<StabPiece> stab_segment(const Dcel& d, Point a, Point b);

// Everything the line through a and b meets, in order from a towards b: it
// starts and ends in the unbounded face. The walk starts at `cut`, a
// half-edge whose edge the line meets (TopologyError otherwise). Requires a != b.
[[nodiscard]] std::vector<StabPiece> stab_line(const Dcel& d, Point a, Point b, HalfEdgeId cut);

// As above, finding an edge or vertex on the line by an O(V + E) scan; the
// line lies in the unbounded face when it meets nothing.
[[nodiscard]] std::vector<StabPiece> stab_line(const Dcel& d, Point a, Point b);

// The faces in order, one per Face piece.
[[nodiscard]] std::vector<FaceId> faces_in_order(const std::vector<StabPiece>& pieces);

}  // namespace dcel
