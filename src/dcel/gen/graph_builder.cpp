#include "dcel/gen/graph_builder.hpp"

#include <algorithm>
#include <cmath>

#include "dcel/gen/brute_force.hpp"

namespace dcel::gen {

std::optional<VertexId> GraphBuilder::add_point(Point p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || at_.contains(p)) return std::nullopt;
    for (const GraphEdge& e : g_.edges) {
        if (on_closed_segment(g_.vertices[e.u.index()], g_.vertices[e.v.index()], p)) return std::nullopt;
    }
    const VertexId id(static_cast<Index>(g_.vertices.size()));
    g_.vertices.push_back(p);
    at_.emplace(p, id);
    return id;
}

std::optional<VertexId> GraphBuilder::point(Point p) {
    const auto it = at_.find(p);
    if (it != at_.end()) return it->second;
    return add_point(p);
}

bool GraphBuilder::can_add_edge(VertexId u, VertexId v) const {
    if (u == v || edges_.contains(std::minmax(u.index(), v.index()))) return false;
    const Point a = g_.vertices[u.index()];
    const Point b = g_.vertices[v.index()];
    for (const GraphEdge& e : g_.edges) {
        if (segments_conflict(a, b, g_.vertices[e.u.index()], g_.vertices[e.v.index()])) return false;
    }
    for (Index w = 0; w < g_.vertices.size(); ++w) {
        if (w != u.index() && w != v.index() && on_closed_segment(a, b, g_.vertices[w])) return false;
    }
    return true;
}

bool GraphBuilder::add_edge(VertexId u, VertexId v) {
    if (!can_add_edge(u, v)) return false;
    g_.edges.push_back({u, v});
    edges_.insert(std::minmax(u.index(), v.index()));
    return true;
}

bool GraphBuilder::add_segment(Point a, Point b) {
    const std::optional<VertexId> u = point(a);
    if (!u) return false;
    const std::optional<VertexId> v = point(b);
    if (!v) return false;
    return add_edge(*u, *v);
}

}  // namespace dcel::gen
