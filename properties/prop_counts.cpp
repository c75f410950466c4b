// Counting laws: Euler's formula with components from an independent
// union-find, and exact signed areas of every cycle.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "dcel/build.hpp"
#include "dcel/queries.hpp"
#include "oracles/exact.hpp"
#include "oracles/reference_dcel.hpp"
#include "oracles/union_find.hpp"
#include "support/dcel_views.hpp"
#include "support/graph_case.hpp"

namespace dcel::props {
namespace {

using oracle::Rational;

RC_GTEST_PROP(Counts, prop_euler_v_minus_e_plus_f_is_one_plus_components, ()) {
    const GraphCase c = *graphs();
    const Dcel d = build(c.graph);
    const std::size_t components = oracle::count_components(c.graph);
    RC_ASSERT(d.num_vertices() + d.num_faces() == d.num_edges() + 1 + components);
}

RC_GTEST_PROP(Areas, prop_cycle_area_signs_and_sums_are_exact, ()) {
    const GraphCase c = *graphs();
    const PlanarGraph& g = c.graph;
    const Dcel d = build(g);
    // A component encloses area exactly when it has a cycle: E_c >= V_c.
    const std::vector<Index> label = oracle::component_labels(g);
    std::vector<long> excess(g.vertices.size(), 0);  // E_c - V_c + 1 at each root
    for (Index v = 0; v < g.vertices.size(); ++v) excess[label[v]] -= 1;
    for (Index v = 0; v < g.vertices.size(); ++v) excess[v] += label[v] == v ? 1 : 0;
    for (const GraphEdge& e : g.edges) excess[label[e.u.index()]] += 1;

    // Top-level components, found by the reference DCEL: no bounded face of
    // another component contains them. Their outer boundaries enclose all
    // the area.
    const oracle::ReferenceDcel ref = oracle::reference_dcel(g);
    Rational all_cycles = 0, bounded_faces = 0, top_level_enclosed = 0;
    for (Index i = 0; i < d.num_faces(); ++i) {
        const FaceId f(i);
        Rational face = 0;
        if (!d.is_unbounded(f)) {
            const Rational outer = oracle::twice_area(test_support::cycle_points(d, d.outer(f)));
            RC_ASSERT(outer > 0);  // every bounded face's outer cycle is counterclockwise
            face += outer;
        }
        for (const HalfEdgeId h : d.inner(f)) {
            const Rational hole = oracle::twice_area(test_support::cycle_points(d, h));
            const bool encloses = excess[label[d.origin(h).index()]] > 0;
            RC_ASSERT((encloses ? hole < 0 : hole == 0));  // a hole is clockwise, flat for a tree
            face += hole;
            if (ref.face_of_cycle[ref.cycle_of[h.index()]] == 0) top_level_enclosed -= hole;
        }
        all_cycles += face;
        if (!d.is_unbounded(f)) {
            RC_ASSERT(face > 0);
            RC_ASSERT(face_area(d, f).sign == Sign::Positive);
            // The library's value is the exact area rounded once; with
            // integer coordinates and a small area it is the exact area.
            if (has_integer_coordinates(g) && face < Rational(std::int64_t{1} << 52)) {
                RC_ASSERT(Rational(face_area(d, f).value) * 2 == face);
            }
            bounded_faces += face;
        }
    }
    RC_ASSERT(all_cycles == 0);
    RC_ASSERT(bounded_faces == top_level_enclosed);
}

}  // namespace
}  // namespace dcel::props
