#include "peers/cgal_arrangement.hpp"

#include <map>
#include <utility>

#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

namespace dcel::bench {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Traits = CGAL::Arr_segment_traits_2<Kernel>;
using Arrangement = CGAL::Arrangement_2<Traits>;

void read_ccb(Arrangement::Ccb_halfedge_const_circulator first, const std::map<std::pair<double, double>, std::uint32_t>& id,
              Cycles& out) {
    std::vector<std::uint32_t> cycle;
    auto h = first;
    do {
        const auto& p = h->source()->point();
        cycle.push_back(id.at({CGAL::to_double(p.x()), CGAL::to_double(p.y())}));
    } while (++h != first);
    out.push_back(std::move(cycle));
}

}  // namespace

PeerResult cgal_cycles(const PlanarGraph& g, bool want_cycles) {
    std::vector<Traits::X_monotone_curve_2> segments;
    segments.reserve(g.edges.size());
    std::vector<char> used(g.vertices.size(), 0);
    for (const GraphEdge& e : g.edges) {
        const Point a = g.vertices[e.u.index()];
        const Point b = g.vertices[e.v.index()];
        segments.emplace_back(Kernel::Point_2(a.x, a.y), Kernel::Point_2(b.x, b.y));
        used[e.u.index()] = used[e.v.index()] = 1;
    }
    std::vector<Kernel::Point_2> isolated;
    for (std::size_t v = 0; v < g.vertices.size(); ++v) {
        if (used[v] == 0) isolated.emplace_back(g.vertices[v].x, g.vertices[v].y);
    }
    Arrangement arr;
    CGAL::non_intersecting_insert_empty(arr, segments.begin(), segments.end(), isolated.begin(), isolated.end());

    PeerResult result;
    if (!want_cycles) {
        // Each face has one outer CCB (none for the unbounded one) and its holes.
        result.count = arr.number_of_faces() - 1;
        for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
            result.count += static_cast<std::size_t>(std::distance(f->inner_ccbs_begin(), f->inner_ccbs_end()));
        }
        return result;
    }
    Cycles& cycles = result.cycles;
    std::map<std::pair<double, double>, std::uint32_t> id;
    for (std::size_t v = 0; v < g.vertices.size(); ++v)
        id[{g.vertices[v].x, g.vertices[v].y}] = static_cast<std::uint32_t>(v);
    for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
        for (auto c = f->outer_ccbs_begin(); c != f->outer_ccbs_end(); ++c) read_ccb(*c, id, cycles);
        for (auto c = f->inner_ccbs_begin(); c != f->inner_ccbs_end(); ++c) read_ccb(*c, id, cycles);
    }
    result.count = cycles.size();
    return result;
}

}  // namespace dcel::bench
