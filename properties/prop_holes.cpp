// Hole placement against a brute-force oracle (support/face_locator): each
// component, by its outer boundary or as an isolated vertex, must sit in the
// face that exact point-in-polygon tests pick for one of its vertices.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "dcel/build.hpp"
#include "support/face_locator.hpp"
#include "support/graph_case.hpp"
#include "support/union_find.hpp"

namespace dcel::props {
namespace {

RC_GTEST_PROP(Holes, prop_each_component_sits_in_the_face_point_in_polygon_picks, ()) {
    const GraphCase c = *graphs();
    const Dcel d = build(c.graph);
    const std::vector<Index> label = component_labels(c.graph);
    const FaceLocator locate(d, label);
    for (Index i = 0; i < d.num_faces(); ++i) {
        const FaceId f(i);
        for (const HalfEdgeId h : d.inner(f)) {
            const VertexId v = d.origin(h);
            RC_ASSERT(locate.face_containing(d.point(v), label[v.index()]) == f);
        }
        for (const VertexId v : d.isolated(f)) RC_ASSERT(locate.face_containing(d.point(v), label[v.index()]) == f);
    }
}

}  // namespace
}  // namespace dcel::props
