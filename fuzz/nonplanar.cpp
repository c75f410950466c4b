// nonplanar: arbitrary segments, where crossings, touches and overlaps are
// likely, through build().
//
// Compares build()'s verdict with a brute-force exact check of every pair of
// elements (support/brute_force.hpp): build() rejects exactly when brute
// force finds a defect, and the kind it reports is one brute force found.
// Compares an accepted graph's DCEL with an independent reference
// (support/reference_dcel.hpp), and requires validate() to pass it. Compares
// with Boost's Boyer-Myrvold test: a graph Boost calls non-planar must be
// rejected. build() without the crossing check must terminate without
// memory errors on any input, and equal the checked build on a valid one.
// The generators' own guard (gen::find_problem, which keeps every generated
// graph valid) must find a problem exactly when brute force does.
//
// Input: readable text, see support/text_graph.hpp, e.g.
//   points 0 0, 4 4, 0 4, 4 0  edges 0 1, 2 3
// The custom mutator (support/graph_mutator.hpp) moves vertices onto or
// within ulps of lines and other vertices, adds and removes edges and
// vertices, and plants crossings, touches, overlaps and duplicates.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "dcel/build.hpp"
#include "dcel/dump.hpp"
#include "dcel/error.hpp"
#include "dcel/gen/brute_force.hpp"
#include "dcel/validate.hpp"
#include "oracles/boost_oracle.hpp"
#include "oracles/brute_force.hpp"
#include "oracles/dump_judge.hpp"
#include "support/fuzz_check.hpp"
#include "support/graph_fuzzer.hpp"
#include "support/text_graph.hpp"

namespace dcel::fuzz {
namespace {

// The brute force compares all pairs (O(V E + E^2) exact orientations) and
// the reference DCEL sorts and walks; these caps keep a run near a
// millisecond under the sanitizers. Enough for K5 and K3,3 (Boost) and for
// every local configuration of a few edges.
constexpr std::size_t kMaxInput = 16 * 1024;
constexpr GraphCaps kCaps{48, 96};

using oracle::Defect;
using oracle::describe;

void check_graph(const PlanarGraph& g) {
    const oracle::DefectKinds defects = oracle::find_defects(g, oracle::PairSearch::AllPairs).kinds();
    const std::optional<std::string> problem = gen::find_problem(g);
    FUZZ_CHECK(problem.has_value() == defects.any(),
               "the generators' guard says " << problem.value_or("valid") << ", brute force finds " << describe(defects));
    const bool planar = oracle::boyer_myrvold(g).planar;
    // The oracles check each other: a graph that is not planar at all has
    // no drawing without a geometric defect among its edges.
    if (!planar) {
        FUZZ_CHECK(has(defects, Defect::Crossing) || has(defects, Defect::Touch) || has(defects, Defect::Overlap) ||
                       has(defects, Defect::DuplicatePoint) || has(defects, Defect::BadCoordinate),
                   "Boost calls the graph non-planar, brute force finds only " << describe(defects));
    }
    Dcel d;
    try {
        d = build(g);
    } catch (const InvalidInput& e) {
        const Defect k = oracle::defect_of(e.kind());
        FUZZ_CHECK(defects.any(), "build rejects a graph brute force finds valid: " << e.what());
        FUZZ_CHECK(k != Defect::Count && has(defects, k), "build reports " << to_string(e.kind())
                                                                           << " but brute force finds " << describe(defects)
                                                                           << ": " << e.what());
        return;
    }
    FUZZ_CHECK(defects.none(), "build accepts a graph with " << describe(defects));
    FUZZ_CHECK(planar, "build accepts a graph Boost calls non-planar");
    const CheckResult v = validate(d);
    FUZZ_CHECK(!v, "validate rejects a built DCEL: [" << to_string(v->invariant) << "] " << v->message);
    const DcelDump dump = to_dump(d);
    const oracle::Judgement j = oracle::judge_dump(dump);
    FUZZ_CHECK(j.valid, "the reference disagrees with build: " << j.reason);

    const DcelDump unchecked = to_dump(build(g, BuildOptions{.check_crossings = false}));
    FUZZ_CHECK(
        unchecked.half_edges == dump.half_edges && unchecked.faces == dump.faces && unchecked.vertex_out == dump.vertex_out,
        "build without the crossing check differs on a valid graph");
}

// On input that breaks its promise, build() without the crossing check may
// return anything or refuse, but must terminate cleanly.
void check_unchecked_build(const PlanarGraph& g) {
    try {
        const Dcel d = build(g, BuildOptions{.check_crossings = false});
        FUZZ_CHECK(d.num_half_edges() == 2 * g.edges.size(), "unchecked build lost half-edges");
    } catch (const InvalidInput&) {
    }
}

std::optional<PlanarGraph> any_graph(std::string_view text) {
    TokenReader in(text);
    return decode_graph(in, kCaps);
}

constexpr GraphFuzzing kFuzzing{any_graph, Validity::Break, {kCaps.vertices, kCaps.edges}};

}  // namespace
}  // namespace dcel::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > dcel::fuzz::kMaxInput) return -1;
    dcel::fuzz::TokenReader in(std::string_view(reinterpret_cast<const char*>(data), size));
    const dcel::PlanarGraph g = dcel::fuzz::decode_graph(in, dcel::fuzz::kCaps);
    dcel::fuzz::check_graph(g);
    dcel::fuzz::check_unchecked_build(g);
    return 0;
}

DCEL_GRAPH_FUZZER_HOOKS(dcel::fuzz::kFuzzing)
