// GraphBuilder: grows a planar straight-line graph one point and one edge at
// a time, refusing anything that would make it invalid (a duplicate point, a
// point on an edge, an edge that meets another other than at a shared
// endpoint or runs through a vertex). Every decision is exact (brute_force's
// segments_conflict and on_closed_segment).
//
// What a new point or edge is tested against comes from a uniform grid of
// square cells of side `cell`: a vertex is filed in the cell that holds it,
// an edge in every cell its closed segment meets (computed exactly in
// integers). Two closed segments that meet share the cell of their meeting
// point, and a vertex on a segment is in one of the segment's cells, so the
// grid never hides a conflict; it only spares the tests against everything
// far away. Cells live in a hash table of buckets that grows with the
// graph; cells sharing a bucket only cost extra tests. A check costs
// O(cells the segment crosses + items filed there): O(1) for edges a few
// cells long in a graph of bounded density, so n insertions cost O(n)
// (amortized, with the table's growth) instead of brute force's O(n^2).
// Points that are not integers of magnitude below 2^40 are not filed: they
// are tested against everything, and everything against them (still exact,
// just slow).
#pragma once

#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "dcel/graph.hpp"

namespace dcel::gen {

class GraphBuilder {
public:
    // `cell` is the grid's cell side in coordinate units (at least 1). About
    // the distance between neighbouring vertices is a good choice; any value
    // gives the same decisions.
    explicit GraphBuilder(std::int64_t cell = 8);

    // The id of a new vertex at p, or nothing when p is taken or lies on an edge.
    std::optional<VertexId> add_point(Point p);
    // The vertex at p, adding it if it is free; nothing when p lies on an edge.
    std::optional<VertexId> point(Point p);
    // Adds edge u-v when that keeps the graph valid; false otherwise.
    bool add_edge(VertexId u, VertexId v);
    [[nodiscard]] bool can_add_edge(VertexId u, VertexId v) const;
    // The points (found or added) and the edge between them; all or nothing:
    // when the edge is refused, points it added are taken away again.
    bool add_segment(Point a, Point b);

    [[nodiscard]] std::optional<VertexId> find(Point p) const;
    [[nodiscard]] std::size_t num_vertices() const { return g_.vertices.size(); }
    [[nodiscard]] const PlanarGraph& graph() const { return g_; }
    [[nodiscard]] PlanarGraph take() { return std::move(g_); }

private:
    // A bucket lists the vertices (tagged with kVertex: ids stay below 2^31)
    // and the edges filed in the cells that map to it.
    static constexpr Index kVertex = Index{1} << 31U;
    struct PointHash {
        std::size_t operator()(Point p) const;
    };

    [[nodiscard]] bool filed(Point p) const;
    [[nodiscard]] std::int64_t cell_of(double coordinate) const;
    [[nodiscard]] std::size_t bucket(std::int64_t cx, std::int64_t cy) const;
    [[nodiscard]] std::size_t bucket_of(Point p) const { return bucket(cell_of(p.x), cell_of(p.y)); }
    // Calls visit(bucket) for every cell the closed segment ab meets (a, b
    // filed); a bucket may come more than once.
    template <class Visit>
    void for_each_bucket(Point a, Point b, Visit visit) const;
    [[nodiscard]] bool on_some_edge(Point p) const;
    void file_edge(Index e);
    void grow_if_full();
    void file_vertex(Index v);
    void remove_last_vertex();

    std::int64_t cell_;
    PlanarGraph g_;
    std::unordered_map<Point, VertexId, PointHash> at_;
    int bucket_bits_ = 6;
    std::vector<std::vector<Index>> buckets_;          // 2^bucket_bits_ of them
    std::size_t filed_items_ = 0;                      // vertex and edge filings, to decide growth
    std::vector<Index> loose_vertices_, loose_edges_;  // not filed: tested always
    // Per-edge and per-vertex marks so that an item filed in several cells
    // is tested once per query.
    mutable std::vector<std::uint32_t> edge_mark_, vertex_mark_;
    mutable std::uint32_t query_ = 0;
};

}  // namespace dcel::gen
