// Differential tests against Boost.Graph (see oracles/boost_oracle.hpp for
// how its semantics are encoded).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "dcel/build.hpp"
#include "oracles/boost_oracle.hpp"
#include "support/dcel_views.hpp"
#include "support/graph_case.hpp"

namespace dcel::props {
namespace {

RC_GTEST_PROP(Boost, prop_cycles_match_planar_face_traversal, ()) {
    const GraphCase c = *graphs();
    RC_ASSERT(test_support::dcel_cycles(build(c.graph)) == oracle::boost_face_cycles(c.graph));
}

RC_GTEST_PROP(Boost, prop_boyer_myrvold_finds_planar_with_the_same_face_count, ()) {
    const GraphCase c = *graphs();
    const Dcel d = build(c.graph);
    const oracle::BoyerMyrvoldAnswer bm = oracle::boyer_myrvold(c.graph);
    RC_ASSERT(bm.planar);
    // Every embedding of a component with edges has E - V + 2 faces, one of
    // them its outer face. The DCEL merges those outer faces into one
    // unbounded face (holes), whatever embedding Boyer-Myrvold chose.
    RC_ASSERT(d.num_faces() == 1 + bm.faces - bm.components);
}

}  // namespace
}  // namespace dcel::props
