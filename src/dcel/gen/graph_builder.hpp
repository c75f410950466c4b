// GraphBuilder: grows a planar straight-line graph one point and one edge at
// a time, refusing anything that would make it invalid (a duplicate point, a
// point on an edge, an edge that meets another other than at a shared
// endpoint or runs through a vertex). Each check is brute force over what is
// already there, O(V + E), which is cheap at generator sizes.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <utility>

#include "dcel/graph.hpp"

namespace dcel::gen {

class GraphBuilder {
public:
    // The id of a new vertex at p, or nothing when p is taken or lies on an edge.
    std::optional<VertexId> add_point(Point p);
    // The vertex at p, adding it if it is free; nothing when p lies on an edge.
    std::optional<VertexId> point(Point p);
    // Adds edge u-v when that keeps the graph valid; false otherwise.
    bool add_edge(VertexId u, VertexId v);
    [[nodiscard]] bool can_add_edge(VertexId u, VertexId v) const;
    // Convenience: the points (added or found) and the edge between them.
    bool add_segment(Point a, Point b);

    [[nodiscard]] std::size_t num_vertices() const { return g_.vertices.size(); }
    [[nodiscard]] const PlanarGraph& graph() const { return g_; }
    [[nodiscard]] PlanarGraph take() { return std::move(g_); }

private:
    struct PointLess {
        bool operator()(Point a, Point b) const { return lex_less(a, b); }
    };
    PlanarGraph g_;
    std::map<Point, VertexId, PointLess> at_;
    std::set<std::pair<Index, Index>> edges_;
};

}  // namespace dcel::gen
