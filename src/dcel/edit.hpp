// Editing a DCEL in place: the textbook operations (de Berg et al., ch. 2),
// each exact and each keeping every invariant. After any edit the DCEL is the
// one build() would make from the resulting graph, up to the numbering of
// faces (and the choice of representative half-edges and out(v)).
//
// Every edit first checks its precondition exactly and refuses, leaving the
// DCEL untouched, with
//   InvalidInput (BadIndex, BadCoordinate)  an id out of range, a coordinate
//                                           that is not finite;
//   TopologyError                           the edit would break the planar
//                                           subdivision (a crossing, a point
//                                           not on the edge, ...).
// Messages are one line and name the ids. All checks come before the first
// change, so a refusal changes nothing. (Running out of memory part way
// through an edit, std::bad_alloc, is not covered: the DCEL may then be
// inconsistent.)
//
// Every edit returns a Change (change.hpp): the ids it added, removed and
// renamed. Ids are stable except as a Change says: additions take the next
// id; a removal moves the last element into the freed id; in a merge the
// smaller id survives. Pass the Change to ElementData::follow()
// (user_data.hpp) to keep user data attached.
//
// Costs (V vertices, E edges, F faces, I isolated vertices; |f| the number
// of half-edges on the cycles of face f):
//   split_edge                 O(1)
//   add_edge                   O(V + E) for the exact no-crossing check, plus
//                              when it splits face f: O(|f| * (1 + k)) to place
//                              f's k holes and isolated vertices, plus the
//                              size of the holes that move
//   add_edge_to_point          as add_edge
//   add_vertex                 O(V + E) (the check, and point location by scan)
//   remove_edge                O(size of the cycles through the edge), plus
//                              when it merges faces: the boundary of the face
//                              that goes away, and of the face renumbered into
//                              its id
//   remove_isolated_vertex     O(F + I + degree of the last vertex)
//   merge_collinear_edges      O(1) plus the renumbering of the last vertex
//                              (its degree, or F + I when isolated) and of the
//                              last edge (the hole lists of the faces beside it)
// Whenever an edge moves into a freed id (the last edge), the faces beside it
// whose records name its half-edges are updated: O(holes of those two faces).
#pragma once

#include "dcel/change.hpp"
#include "dcel/dcel.hpp"
#include "dcel/geometry/point.hpp"

namespace dcel {

// Splits edge e at p, which must lie exactly on e strictly between its ends.
// The new vertex w (id V) sits at p. Edge e keeps its id and its first end:
// half-edge 2e still leaves origin(2e) and now ends at w; the new edge n (id
// E) continues it, 2n running from w to the old target(2e). Faces keep their
// ids. Change: vertices.added = w; edges.added = n, added_from = e.
Change split_edge(Dcel& d, EdgeId e, Point p);

// Adds the edge u-v; the new edge n (id E) has 2n running u -> v. Refused when
// u == v, when u and v are already joined, or when the segment would cross an
// edge, overlap one, or pass through a vertex.
//  - u and v on one boundary cycle of face f: f splits in two, the new face
//    (id F) gets f's holes and isolated vertices that lie inside it. When the
//    cycle is f's outer boundary, the new face is the part on the left of
//    u -> v; when the cycle is a hole's boundary (or f is the unbounded face),
//    the new face is the region the edge closes off.
//  - u and v on different cycles of f: the two cycles join (a hole joins f's
//    outer boundary, or two holes become one); faces do not change.
//  - an end with no edges stops being an isolated vertex of f; two such ends
//    make a new hole of f.
// Change: edges.added = n; faces.added = the new face, added_from = f, when
// a face splits.
Change add_edge(Dcel& d, VertexId u, VertexId v);

// Adds a vertex w (id V) at p and the edge u-w (id E, 2n running u -> w), in
// one step. Refused when p is at a vertex or on an edge, or the segment would
// cross, overlap or pass through anything. Change: vertices.added = w,
// edges.added = n.
Change add_edge_to_point(Dcel& d, VertexId u, Point p);

// Adds an isolated vertex (id V) at p, listed in the face that contains p.
// Refused when p is at a vertex or on an edge. Change: vertices.added.
Change add_vertex(Dcel& d, Point p);

// Removes edge e (both half-edges).
//  - Different faces on its two sides: they merge into the one with the
//    smaller id (so the unbounded face always survives); the other face's id
//    is freed. Change: faces.removed, merged_into.
//  - The same face f on both sides: the cycle through e splits in two, or
//    loses the edge; a new hole of f appears when a component breaks off (f
//    keeps the part that bounds it from outside), and an end left without
//    edges becomes an isolated vertex of f.
// The last edge then moves into id e. Change: edges.removed = e, moved.
Change remove_edge(Dcel& d, EdgeId e);

// Removes v, which must have no edges. The last vertex moves into its id.
// Change: vertices.removed = v, moved.
Change remove_isolated_vertex(Dcel& d, VertexId v);

// Removes v, which must have exactly two edges, v-a and v-b, with v strictly
// inside the segment a-b (exactly collinear): the two edges become one edge
// a-b. The inverse of split_edge. The edge with the smaller id survives, the
// other merges into it; the survivor's half-edge that ended at v keeps its
// origin. Change: vertices.removed = v (and moved); edges.removed, merged_into
// (and moved).
Change merge_collinear_edges(Dcel& d, VertexId v);

}  // namespace dcel
