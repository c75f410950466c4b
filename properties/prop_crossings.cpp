// Crossing detection against brute force (oracles/brute_force.hpp's
// find_defects): on valid graphs, on graphs with one planted crossing, touch or
// overlap, and on raw random segments that may meet in any way. build()
// must reject exactly the graphs brute force finds a defect in, and the pair
// it names must really meet the way it says. So must validate()'s embedding
// check, which has its own sweep (src/dcel/validate/), on a dump of the graph.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dcel/build.hpp"
#include "dcel/dump.hpp"
#include "dcel/error.hpp"
#include "dcel/io/graph_json.hpp"
#include "dcel/validate.hpp"
#include "oracles/brute_force.hpp"
#include "support/check_helpers.hpp"
#include "support/graph_case.hpp"

namespace dcel::props {
namespace {

using oracle::Defects;
using oracle::find_defects;
using oracle::Meeting;

bool has_pair(const Defects& d, EdgeId a, EdgeId b, Meeting how) {
    const Index lo = std::min(a.index(), b.index()), hi = std::max(a.index(), b.index());
    return std::any_of(d.edge_pairs.begin(), d.edge_pairs.end(),
                       [&](const Defects::EdgePair& p) { return p.e1 == lo && p.e2 == hi && p.how == how; });
}

// The error names a defect that brute force found too.
void check_named_defect(const InvalidInput& e, const Defects& found) {
    switch (e.kind()) {
        case InputErrorKind::Crossing:
            RC_ASSERT(e.edges().size() == 2u);
            RC_ASSERT(has_pair(found, e.edges()[0], e.edges()[1], Meeting::Crossing));
            break;
        case InputErrorKind::VertexOnEdge: {
            RC_ASSERT(e.vertices().size() == 1u && e.edges().size() == 1u);
            const std::pair<Index, Index> named{e.vertices()[0].index(), e.edges()[0].index()};
            RC_ASSERT(std::count(found.vertex_in_edge.begin(), found.vertex_in_edge.end(), named) == 1);
            break;
        }
        case InputErrorKind::Overlap:
            RC_ASSERT(e.edges().size() == 2u);
            RC_ASSERT(has_pair(found, e.edges()[0], e.edges()[1], Meeting::Overlap));
            break;
        case InputErrorKind::DuplicatePoint: RC_ASSERT(!found.duplicate_points.empty()); break;
        case InputErrorKind::DuplicateEdge: RC_ASSERT(!found.duplicate_edges.empty()); break;
        default: RC_FAIL(std::string("unexpected error kind: ") + e.what());
    }
}

// validate()'s embedding check on a dump that carries just the graph (edge
// k is half-edges 2k and 2k + 1, next = twin, one face: check_embedding reads
// only the points and the twin pairs), as an InvalidInput: the kind from
// the words of the message (build()'s words), the edges from the half-edges.
std::optional<InvalidInput> embedding_refusal(const PlanarGraph& g) {
    const DcelDump d = test_support::edges_only_dump(g);
    const CheckResult v = check_embedding(d);
    if (!v) return std::nullopt;
    RC_ASSERT(v->invariant == Invariant::Embedding);
    const std::pair<const char*, InputErrorKind> words[] = {
        {" cross; ", InputErrorKind::Crossing},
        {" lies inside ", InputErrorKind::VertexOnEdge},
        {" overlap", InputErrorKind::Overlap},
        {" are at the same point ", InputErrorKind::DuplicatePoint},
        {" both join vertices ", InputErrorKind::DuplicateEdge},
    };
    for (const auto& [text, kind] : words) {
        if (v->message.find(text) == std::string::npos) continue;
        std::vector<EdgeId> edges;
        for (const HalfEdgeId h : v->half_edges) edges.push_back(edge_of(h));
        return InvalidInput(kind, v->message, v->vertices, edges);
    }
    RC_FAIL("an embedding violation of no known kind: " + v->message);
    return std::nullopt;
}

RC_GTEST_PROP(Crossings, prop_generated_graphs_have_no_contact_and_build_accepts, ()) {
    const GraphCase c = *graphs();
    RC_ASSERT(find_defects(c.graph).empty());
    try {
        (void)build(c.graph);
    } catch (const InvalidInput& e) {
        RC_FAIL(std::string("build rejected a valid graph: ") + e.what());
    }
}

RC_GTEST_PROP(Crossings, prop_planted_defect_is_rejected_naming_a_real_contact, ()) {
    const GraphCase c = *graphs();
    const gen::Defect defect = *rc::gen::element(gen::Defect::Crossing, gen::Defect::Touch, gen::Defect::Overlap);
    const std::optional<PlanarGraph> bad = gen::plant(c.graph, defect, *rc::gen::arbitrary<std::uint64_t>());
    RC_PRE(bad.has_value());  // a graph without edges has no place for a defect
    const Defects found = find_defects(*bad);
    RC_ASSERT(!found.empty());
    try {
        (void)build(*bad);
        RC_FAIL("build accepted a graph with a planted defect: " + io::write_graph(*bad));
    } catch (const InvalidInput& e) {
        check_named_defect(e, found);
        // One defect was planted, so its kind is known in advance.
        const InputErrorKind expected = defect == gen::Defect::Crossing ? InputErrorKind::Crossing
                                        : defect == gen::Defect::Touch  ? InputErrorKind::VertexOnEdge
                                                                        : InputErrorKind::Overlap;
        RC_ASSERT(std::string(to_string(e.kind())) == to_string(expected));
    }
}

RC_GTEST_PROP(Crossings, prop_validate_names_the_planted_defect, ()) {
    const GraphCase c = *graphs();
    const gen::Defect defect = *rc::gen::element(gen::Defect::Crossing, gen::Defect::Touch, gen::Defect::Overlap);
    const std::optional<PlanarGraph> bad = gen::plant(c.graph, defect, *rc::gen::arbitrary<std::uint64_t>());
    RC_PRE(bad.has_value());
    RC_ASSERT(!embedding_refusal(c.graph).has_value());
    const std::optional<InvalidInput> e = embedding_refusal(*bad);
    if (!e) RC_FAIL("validate's embedding check passed a graph with a planted defect: " + io::write_graph(*bad));
    check_named_defect(*e, find_defects(*bad));
    const InputErrorKind expected = defect == gen::Defect::Crossing ? InputErrorKind::Crossing
                                    : defect == gen::Defect::Touch  ? InputErrorKind::VertexOnEdge
                                                                    : InputErrorKind::Overlap;
    RC_ASSERT(std::string(to_string(e->kind())) == to_string(expected));
}

// Unchecked segments between random points of a small grid: every kind of
// contact, duplicate points and duplicate edges are common.
struct RawGraph {
    PlanarGraph graph;
};
void showValue(const RawGraph& r, std::ostream& os) { os << io::write_graph(r.graph); }

rc::Gen<RawGraph> raw_graphs() {
    return rc::gen::mapcat(rc::gen::pair(rc::gen::inRange(2, 7), rc::gen::inRange(2, 14)), [](std::pair<int, int> sn) {
        const auto [side, n] = sn;
        const auto coordinate = rc::gen::map(rc::gen::inRange(0, side), [](int v) { return static_cast<double>(v); });
        const auto points = rc::gen::container<std::vector<Point>>(static_cast<std::size_t>(n), rc::gen::apply(
                                                                                                    [](double x, double y) {
                                                                                                        return Point{x, y};
                                                                                                    },
                                                                                                    coordinate, coordinate));
        const auto edge = rc::gen::map(
            rc::gen::suchThat(rc::gen::pair(rc::gen::inRange(0, n), rc::gen::inRange(0, n)),
                              [](std::pair<int, int> e) { return e.first != e.second; }),
            [](std::pair<int, int> e) {
                return GraphEdge{VertexId(static_cast<Index>(e.first)), VertexId(static_cast<Index>(e.second))};
            });
        return rc::gen::apply(
            [](std::vector<Point> p, std::vector<GraphEdge> e) {
                return RawGraph{{std::move(p), std::move(e)}};
            },
            points, rc::gen::resize(n, rc::gen::container<std::vector<GraphEdge>>(edge)));
    });
}

RC_GTEST_PROP(Crossings, prop_build_rejects_raw_segments_exactly_when_brute_force_finds_a_defect, ()) {
    const RawGraph r = *raw_graphs();
    const Defects found = find_defects(r.graph);
    RC_CLASSIFY(found.empty(), "valid");
    try {
        (void)build(r.graph);
        RC_ASSERT(found.empty());
    } catch (const InvalidInput& e) {
        RC_ASSERT(!found.empty());
        check_named_defect(e, found);
    }
}

RC_GTEST_PROP(Crossings, prop_validate_flags_raw_segments_exactly_when_brute_force_finds_a_defect, ()) {
    const RawGraph r = *raw_graphs();
    const Defects found = find_defects(r.graph);
    RC_CLASSIFY(found.empty(), "valid");
    const std::optional<InvalidInput> e = embedding_refusal(r.graph);
    RC_ASSERT(e.has_value() == !found.empty());
    if (e) check_named_defect(*e, found);
}

}  // namespace
}  // namespace dcel::props
