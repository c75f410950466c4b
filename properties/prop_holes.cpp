// Hole placement against a brute-force oracle: each component (its outer
// boundary, or an isolated vertex) belongs to the smallest bounded face
// whose outer cycle, from another component, strictly contains one of its
// vertices (exact point in polygon); to the unbounded face when none does.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <optional>

#include "dcel/build.hpp"
#include "support/dcel_views.hpp"
#include "support/exact_oracle.hpp"
#include "support/graph_case.hpp"
#include "support/union_find.hpp"

namespace dcel::props {
namespace {

struct OuterRing {
    FaceId face;
    Index component;
    std::vector<Point> ring;
    Rational twice_area;
    double x0, x1, y0, y1;  // bounding box
};

FaceId containing_face(const std::vector<OuterRing>& rings, Index component, Point p) {
    const OuterRing* best = nullptr;
    for (const OuterRing& r : rings) {
        if (r.component == component || p.x < r.x0 || p.x > r.x1 || p.y < r.y0 || p.y > r.y1) continue;
        if (!strictly_inside(p, r.ring)) continue;
        if (best == nullptr || r.twice_area < best->twice_area) best = &r;
    }
    return best == nullptr ? Dcel::kUnboundedFace : best->face;
}

RC_GTEST_PROP(Holes, prop_each_component_sits_in_the_face_point_in_polygon_picks, ()) {
    const GraphCase c = *graphs();
    const PlanarGraph& g = c.graph;
    const Dcel d = build(g);
    const std::vector<Index> label = component_labels(g);
    std::vector<OuterRing> rings;
    for (Index i = 1; i < d.num_faces(); ++i) {
        const FaceId f(i);
        if (d.is_unbounded(f)) continue;
        OuterRing r{f, label[d.origin(d.outer(f)).index()], cycle_points(d, d.outer(f)), 0, 0, 0, 0, 0};
        r.twice_area = twice_area(r.ring);
        auto [xl, xh] = std::minmax_element(r.ring.begin(), r.ring.end(), [](Point a, Point b) { return a.x < b.x; });
        auto [yl, yh] = std::minmax_element(r.ring.begin(), r.ring.end(), [](Point a, Point b) { return a.y < b.y; });
        r.x0 = xl->x, r.x1 = xh->x, r.y0 = yl->y, r.y1 = yh->y;
        rings.push_back(std::move(r));
    }
    for (Index i = 0; i < d.num_faces(); ++i) {
        const FaceId f(i);
        for (const HalfEdgeId h : d.inner(f)) {
            const VertexId v = d.origin(h);
            RC_ASSERT(containing_face(rings, label[v.index()], d.point(v)) == f);
        }
        for (const VertexId v : d.isolated(f)) RC_ASSERT(containing_face(rings, label[v.index()], d.point(v)) == f);
    }
}

}  // namespace
}  // namespace dcel::props
