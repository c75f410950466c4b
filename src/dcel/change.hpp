// Change: what one edit did to the ids. Every edit (edit.hpp) returns one, so
// that callers can follow the ids they hold and user data (user_data.hpp) can
// follow its elements.
//
// The id rules, for each kind of element (vertices, edges, faces):
//  - An edit adds at most one element and removes at most one.
//  - An added element takes the next free id (the old count); nothing else is
//    renamed by an addition.
//  - A removal frees an id; the element with the last id then moves into it
//    (swap with last), so ids stay dense: 0 .. count-1. Exactly that one
//    element is renamed, and `moved` names it.
//  - When the removed element was merged into another (two faces become one,
//    two collinear edges become one), the survivor is the one with the smaller
//    id, so it is never the one that moves, and face 0 (the unbounded face)
//    always survives.
// Half-edges follow their edge: edge k owns 2k and 2k+1, and when edge m
// moves to k, half-edge 2m+i becomes 2k+i (same direction).
#pragma once

#include "dcel/ids.hpp"

namespace dcel {

template <class Id>
struct IdChange {
    Id added;        // the element the edit created (always the new last id), or null
    Id added_from;   // the element `added` was split off (its user data is copied), or null
    Id removed;      // the element the edit deleted, or null
    Id merged_into;  // the element that absorbed `removed`, or null when it just went away
    Id moved;        // the former last id, now renamed to `removed`; null when nothing moved

    // The id, after the edit, of what had id `before`: itself; `removed` for
    // the moved element; `merged_into` (possibly null) for the removed one.
    // An id added by this edit is returned unchanged.
    [[nodiscard]] Id renamed(Id before) const {
        if (!removed.is_null() && before == removed) return merged_into;
        if (!moved.is_null() && before == moved) return removed;
        return before;
    }
    friend bool operator==(const IdChange&, const IdChange&) = default;
};

struct Change {
    IdChange<VertexId> vertices;
    IdChange<EdgeId> edges;
    IdChange<FaceId> faces;

    [[nodiscard]] VertexId renamed(VertexId v) const { return vertices.renamed(v); }
    [[nodiscard]] EdgeId renamed(EdgeId e) const { return edges.renamed(e); }
    [[nodiscard]] FaceId renamed(FaceId f) const { return faces.renamed(f); }
    // A half-edge of a removed edge becomes null, even when the edge was merged.
    [[nodiscard]] HalfEdgeId renamed(HalfEdgeId h) const {
        const EdgeId e = edge_of(h);
        if (!edges.removed.is_null() && e == edges.removed) return {};
        return half_edge_of(edges.renamed(e), h.index() & 1U);
    }

    template <class Id>
    [[nodiscard]] const IdChange<Id>& of() const;
    friend bool operator==(const Change&, const Change&) = default;
};

template <>
inline const IdChange<VertexId>& Change::of<VertexId>() const {
    return vertices;
}
template <>
inline const IdChange<EdgeId>& Change::of<EdgeId>() const {
    return edges;
}
template <>
inline const IdChange<FaceId>& Change::of<FaceId>() const {
    return faces;
}

}  // namespace dcel
