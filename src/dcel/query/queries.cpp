#include "dcel/queries.hpp"

#include <algorithm>
#include <limits>

#include "dcel/geometry/area.hpp"
#include "dcel/geometry/exact_sum.hpp"
#include "dcel/query/cycle_scan.hpp"

namespace dcel {

// From the internals of the core (dcel::detail).
using detail::ExactSum;
using detail::for_each_boundary_cycle;
namespace {

void add_cycle(const Dcel& d, HalfEdgeId start, ExactSum& sum) {
    for (const HalfEdgeId h : d.cycle(start)) {
        const Point a = d.point(d.origin(h));
        const Point b = d.point(d.target(h));
        sum.add_product(a.x, b.y);
        sum.subtract_product(a.y, b.x);
    }
}

// Halved before rounding: twice an area may overflow, or round in the
// subnormal range, where the area itself does not.
Area halved(const ExactSum& twice) { return {twice.to_double(-1), twice.sign()}; }

}  // namespace

Area cycle_area(const Dcel& d, HalfEdgeId h) {
    ExactSum sum;
    add_cycle(d, h, sum);
    return halved(sum);
}

Area face_area(const Dcel& d, FaceId f) {
    if (d.is_unbounded(f)) return {std::numeric_limits<double>::infinity(), Sign::Positive};
    ExactSum sum;
    add_cycle(d, d.outer(f), sum);
    for (const HalfEdgeId h : d.inner(f)) add_cycle(d, h, sum);  // holes are clockwise: they subtract
    return halved(sum);
}

std::vector<FaceId> neighbours(const Dcel& d, FaceId f) {
    std::vector<FaceId> out;
    auto visit = [&](HalfEdgeId start) {
        for (const HalfEdgeId h : d.cycle(start)) {
            const FaceId g = d.face(Dcel::twin(h));
            if (g != f) out.push_back(g);
        }
    };
    if (!d.is_unbounded(f)) visit(d.outer(f));
    for (const HalfEdgeId h : d.inner(f)) visit(h);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

std::vector<FaceId> faces_around(const Dcel& d, VertexId v) {
    std::vector<FaceId> out;
    const HalfEdgeId start = d.out(v);
    if (start.is_null()) {
        for (Index f = 0; f < d.num_faces(); ++f) {
            const auto& iso = d.isolated(FaceId(f));
            if (std::find(iso.begin(), iso.end(), v) != iso.end()) out.push_back(FaceId(f));
        }
        return out;
    }
    for (const HalfEdgeId h : d.around_origin_ccw(start)) out.push_back(d.face(h));
    return out;
}

std::vector<std::vector<VertexId>> boundary_cycles(const Dcel& d) {
    std::vector<std::vector<VertexId>> cycles;
    for_each_boundary_cycle(d,
                            [&](std::span<const VertexId> origins) { cycles.emplace_back(origins.begin(), origins.end()); });
    return cycles;
}

std::size_t count_components(const Dcel& d) { return d.num_vertices() - d.num_edges() + d.num_faces() - 1; }

}  // namespace dcel
