// locate_by_scan: the O(V + E) reference point location.
#include <algorithm>

#include "dcel/geometry/segments.hpp"
#include "dcel/geometry/winding.hpp"
#include "dcel/locate.hpp"

namespace dcel {

// From the internals of the core (dcel::detail).
using detail::strictly_inside_segment;
using detail::winding_number;
namespace {

int winding_of_cycle(const Dcel& d, HalfEdgeId start, Point p) {
    return winding_number(p, [&](auto&& f) {
        for (const HalfEdgeId h : d.cycle(start)) f(d.point(d.origin(h)), d.point(d.target(h)));
    });
}

}  // namespace

FaceId face_of_isolated_vertex(const Dcel& d, VertexId v) {
    for (Index f = 0; f < d.num_faces(); ++f) {
        const auto& iso = d.isolated(FaceId(f));
        if (std::find(iso.begin(), iso.end(), v) != iso.end()) return FaceId(f);
    }
    return {};
}

Location locate_by_scan(const Dcel& d, Point p) {
    for (Index v = 0; v < d.num_vertices(); ++v) {
        if (d.point(VertexId(v)) == p) return Location::at_vertex(VertexId(v));
    }
    for (Index e = 0; e < d.num_edges(); ++e) {
        const HalfEdgeId h = half_edge_of(EdgeId(e), 0);
        if (strictly_inside_segment(d.point(d.origin(h)), d.point(d.target(h)), p)) return Location::on_edge(EdgeId(e));
    }
    // p is on no cycle now. It is in face f when f's outer cycle winds around
    // it (winding 1) and none of f's holes does: the holes are the components
    // inside f, so a point inside one of them is in a deeper face. Each cycle
    // is walked at most once: O(E) in all.
    for (Index i = 1; i < d.num_faces(); ++i) {
        const FaceId f(i);
        if (winding_of_cycle(d, d.outer(f), p) == 0) continue;
        const auto& holes = d.inner(f);
        if (std::all_of(holes.begin(), holes.end(), [&](HalfEdgeId h) { return winding_of_cycle(d, h, p) == 0; })) {
            return Location::in_face(f);
        }
    }
    return Location::in_face(Dcel::kUnboundedFace);
}

}  // namespace dcel
