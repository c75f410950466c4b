// validate()'s own plane sweep over the edges of a graph (Shamos-Hoey), for
// the embedding and hole-placement checks.
//
// Why not the builder's sweep (build/sweep): validate() judges dumps, build()'s
// included, so it must not share the code that decides the same questions in
// build(): a bug there would hide in both at once. This sweep is written apart
// from it and shares only the exact predicates of dcel/geometry/ (orient2d,
// lex_less), which are tested on their own against exact rationals. It is also
// built differently: the status is a std::set (a red-black tree) ordered by a
// comparator that needs no sweep position (two segments that are both active
// and do not cross are ordered by where the later-starting one starts), each
// event locates its point with one search, and no ring order is used (the
// edges starting at a vertex are ordered by the same comparator).
//
// Cost: O((V + E) log(V + E)) time for every input, valid or not (each edge
// enters and leaves the status once, each vertex makes one search and at most
// two pair tests), O(V + E) memory. No input can make it slower: there is no
// hashing, bucketing or walk whose length depends on the geometry.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "dcel/graph.hpp"
#include "dcel/ids.hpp"

namespace dcel::detail {

// Two edges meeting other than at a shared endpoint, as the sweep met them.
struct SweepContact {
    enum class Kind {
        Crossing,      // `edge` and `other` cross at a point inside both
        VertexInside,  // `vertex` (an end of `other`, or a lone vertex) lies inside `edge`
        SameSegment,   // `edge` and `other` join the same two points
    };
    Kind kind = Kind::Crossing;
    EdgeId edge;
    EdgeId other;
    VertexId vertex;
};

// Every vertex of g sorted by lex_less (x, then y), equal points by id: the
// order the sweep visits them in. O(V log V).
[[nodiscard]] std::vector<VertexId> sweep_order(const PlanarGraph& g);

struct SweepAnswers {
    std::optional<SweepContact> contact;  // the first one met (when looked for)
    std::vector<EdgeId> below;            // per vertex; null: nothing below, or not asked
};

// Sweeps the edges of g in `order` (sweep_order(g)). For each vertex v with
// wanted[v] set (wanted may be empty), below[v] is the edge directly below v:
// the first one a ray from v straight down meets, where a ray through a
// vertex w passes just right of w (the sweep line is turned a little
// clockwise so that points with one x are met bottom to top); null when the
// ray meets nothing.
//
// With find_contact, the sweep stops at the first improper contact it meets
// and reports it (Shamos and Hoey: the leftmost one always shows up as two
// edges made neighbours in the status, or as a vertex located on an edge);
// the answers below are then only those of the vertices before it.
// Requires finite coordinates, pairwise distinct points and no self-loops;
// when find_contact is not set the edges must not meet improperly either, or
// the answers are unspecified (but the sweep is memory safe and terminates).
[[nodiscard]] SweepAnswers sweep_segments(const PlanarGraph& g, std::span<const VertexId> order,
                                          std::span<const char> wanted, bool find_contact);

}  // namespace dcel::detail
