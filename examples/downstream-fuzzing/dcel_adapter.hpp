// Your solver as the dcel helpers call it: a dcel::PlanarGraph in, every
// boundary cycle out (dcel::check::FacesAnswer). Only type conversion here.
#pragma once

#include "dcel/check/compare.hpp"
#include "dcel/graph.hpp"
#include "my_dcel.hpp"

inline dcel::check::FacesAnswer my_faces(const dcel::PlanarGraph& graph) {
    std::vector<my_dcel::Point> points;
    for (const dcel::Point& p : graph.vertices) points.push_back({p.x, p.y});
    std::vector<my_dcel::Edge> edges;
    for (const dcel::GraphEdge& e : graph.edges) {
        edges.push_back({static_cast<int>(e.u.index()), static_cast<int>(e.v.index())});
    }
    dcel::check::FacesAnswer out;
    for (const auto& cycle : my_dcel::faces(points, edges)) out.emplace_back(cycle.begin(), cycle.end());
    return out;
}
