// Invariance: relabelling the input gives an isomorphic DCEL; translating,
// rotating by 90 degrees or scaling by 2 gives the same cycles; mirroring
// reverses every cycle. Transforms come from gen::apply, which is exact.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <numeric>

#include "dcel/build.hpp"
#include "support/dcel_views.hpp"
#include "support/graph_case.hpp"
#include "support/permutations.hpp"

namespace dcel::props {
namespace {

using test_support::face_shapes_renamed;

std::vector<Index> identity(std::size_t n) {
    std::vector<Index> v(n);
    std::iota(v.begin(), v.end(), Index{0});
    return v;
}

RC_GTEST_PROP(Invariance, prop_relabelling_gives_an_isomorphic_dcel, ()) {
    const GraphCase c = *graphs();
    const PlanarGraph& g = c.graph;
    // New vertex ids, a new edge order, and some edges turned round; a
    // failure shrinks them towards the identity and no edge turned.
    const std::vector<Index> vertex_to_new = *permutations(g.vertices.size());
    const std::vector<Index> new_edge_to_old = *permutations(g.edges.size());
    const auto flipped = *rc::gen::container<std::vector<char>>(g.edges.size(), rc::gen::element<char>(0, 1));
    PlanarGraph r;
    r.vertices.resize(g.vertices.size());
    std::vector<Index> new_to_vertex(g.vertices.size());
    for (Index v = 0; v < g.vertices.size(); ++v) {
        r.vertices[vertex_to_new[v]] = g.vertices[v];
        new_to_vertex[vertex_to_new[v]] = v;
    }
    for (Index k = 0; k < g.edges.size(); ++k) {
        const GraphEdge& e = g.edges[new_edge_to_old[k]];
        const VertexId u(vertex_to_new[e.u.index()]), v(vertex_to_new[e.v.index()]);
        r.edges.push_back(flipped[new_edge_to_old[k]] != 0 ? GraphEdge{v, u} : GraphEdge{u, v});
    }
    const Dcel a = build(g);
    const Dcel b = build(r);
    // The half-edge bijection phi: new half-edge -> old one; next must commute with it.
    auto phi = [&](HalfEdgeId h) {
        const Index old_edge = new_edge_to_old[h.index() / 2];
        return HalfEdgeId(2 * old_edge + ((h.index() % 2) ^ static_cast<Index>(flipped[old_edge])));
    };
    RC_ASSERT(a.num_half_edges() == b.num_half_edges());
    RC_ASSERT(a.num_faces() == b.num_faces());
    for (Index h = 0; h < b.num_half_edges(); ++h) {
        const HalfEdgeId x(h);
        RC_ASSERT(phi(b.next(x)) == a.next(phi(x)));
        RC_ASSERT(new_to_vertex[b.origin(x).index()] == a.origin(phi(x)).index());
    }
    RC_ASSERT(face_shapes_renamed(b, new_to_vertex) == face_shapes_renamed(a, identity(g.vertices.size())));
}

RC_GTEST_PROP(Invariance, prop_translation_rotation_and_doubling_keep_every_cycle, ()) {
    const GraphCase c = *graphs();
    const std::vector<Index> same = identity(c.graph.vertices.size());
    const auto expected = face_shapes_renamed(build(c.graph), same);
    const std::int64_t shift = *rc::gen::inRange<std::int64_t>(-(1 << 20), 1 << 20);
    const int turns = *rc::gen::inRange(1, 4);
    std::optional<PlanarGraph> rotated = c.graph;
    for (int i = 0; i < turns; ++i) rotated = gen::apply(*rotated, gen::Transform::Rotate90);
    RC_ASSERT(rotated.has_value());  // rotation never rounds
    RC_ASSERT(face_shapes_renamed(build(*rotated), same) == expected);
    // Translation and scaling are skipped only when they would round.
    const std::optional<PlanarGraph> translated = gen::apply(c.graph, gen::Transform::Translate, shift);
    RC_CLASSIFY(translated.has_value(), "translated");
    if (translated) RC_ASSERT(face_shapes_renamed(build(*translated), same) == expected);
    const std::optional<PlanarGraph> doubled = gen::apply(c.graph, gen::Transform::ScalePow2, 1);
    RC_CLASSIFY(doubled.has_value(), "doubled");
    if (doubled) RC_ASSERT(face_shapes_renamed(build(*doubled), same) == expected);
}

RC_GTEST_PROP(Invariance, prop_mirroring_reverses_every_cycle, ()) {
    const GraphCase c = *graphs();
    const std::vector<Index> same = identity(c.graph.vertices.size());
    const std::optional<PlanarGraph> mirrored = gen::apply(c.graph, gen::Transform::Mirror);
    RC_ASSERT(mirrored.has_value());
    RC_ASSERT(face_shapes_renamed(build(*mirrored), same, /*reverse=*/true) == face_shapes_renamed(build(c.graph), same));
}

}  // namespace
}  // namespace dcel::props
