// Hole placement against the reference DCEL (oracles/reference_dcel.hpp):
// each component, by its outer boundary or as an isolated vertex, must sit
// in the face whose outer cycle is the innermost of another component
// around it (exact winding numbers and areas), or in the unbounded face.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "dcel/build.hpp"
#include "oracles/reference_dcel.hpp"
#include "support/graph_case.hpp"

namespace dcel::props {
namespace {

RC_GTEST_PROP(Holes, prop_each_component_sits_in_the_face_point_in_polygon_picks, ()) {
    const GraphCase c = *graphs();
    const Dcel d = build(c.graph);
    // Half-edge 2k runs u->v of edge k in both, so ids carry over.
    const oracle::ReferenceDcel ref = oracle::reference_dcel(c.graph);
    auto outer_of = [&](FaceId f) { return d.is_unbounded(f) ? kNoIndex : ref.cycle_of[d.outer(f).index()]; };
    for (Index i = 0; i < d.num_faces(); ++i) {
        const FaceId f(i);
        for (const HalfEdgeId h : d.inner(f)) {
            RC_ASSERT(outer_of(f) == ref.outer_cycle[ref.face_of_cycle[ref.cycle_of[h.index()]]]);
        }
        for (const VertexId v : d.isolated(f)) RC_ASSERT(outer_of(f) == ref.outer_cycle[ref.face_of_vertex[v.index()]]);
    }
}

}  // namespace
}  // namespace dcel::props
