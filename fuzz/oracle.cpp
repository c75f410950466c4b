// oracle: valid graphs of every generator family through build(), compared
// with Boost and with exact rational arithmetic.
//
// Compares the DCEL's boundary cycles with the faces of Boost's
// planar_face_traversal over a rotation system sorted by the oracles' own
// exact comparator (tests/support/boost_oracle.hpp: it never uses
// src/dcel/geometry). Boost skips isolated vertices and reports each
// component's outer walk as a face of its own, which is exactly a hole
// cycle, so cycles are compared, not faces. Also: Boyer-Myrvold calls the
// graph planar and its embedding has as many faces as the DCEL has cycles;
// V - E + F = 1 + C with C by union-find; validate() passes; the generated
// graph is valid by brute force (exact, all pairs). The queries are checked
// against the same oracles: boundary_cycles(), count_components(),
// faces_around() against the exact angular order, neighbours() against a
// scan of all half-edges, cycle_area() signs and face_area() values against
// rational areas (face_area promises the exact area rounded once).
//
// Input: readable text, see support/generated_graph.hpp, e.g.
//   triangulation seed 7 vertices 30 mirror scale -3 drop 4
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "dcel/build.hpp"
#include "dcel/error.hpp"
#include "dcel/queries.hpp"
#include "dcel/validate.hpp"
#include "oracles/boost_oracle.hpp"
#include "oracles/brute_force.hpp"
#include "oracles/exact.hpp"
#include "oracles/union_find.hpp"
#include "support/dcel_views.hpp"
#include "support/fuzz_check.hpp"
#include "support/generated_graph.hpp"

namespace dcel::fuzz {
namespace {

// Boost, the rational angle sort and the all-pairs check are superlinear;
// 40 vertices (a family may add a few) keep a run to a few milliseconds
// while leaving room for holes in holes, stars and long chains. The text
// cap bounds the number of transforms and deletions the same way.
constexpr std::size_t kMaxInput = 1024;
constexpr std::size_t kMaxVertices = 40;
constexpr std::size_t kMaxSteps = 32;

std::string describe(const GeneratedGraph& c) {
    return std::string(gen::family_name(c.params.family)) + " seed " + std::to_string(c.params.seed) + " vertices " +
           std::to_string(c.params.vertices) + " (" + std::to_string(c.graph.vertices.size()) + " vertices, " +
           std::to_string(c.graph.edges.size()) + " edges after " + std::to_string(c.transforms) + " transforms)";
}

void check_cycles(const Dcel& d, const PlanarGraph& g) {
    const std::vector<oracle::Cycle> ours = testing::dcel_cycles(d);
    const std::vector<oracle::Cycle> boost = oracle::boost_face_cycles(g);
    FUZZ_CHECK(ours == boost,
               "the DCEL has " << ours.size() << " boundary cycles, Boost's traversal " << boost.size() << "; they differ");
    std::vector<oracle::Cycle> queried;
    for (const std::vector<VertexId>& c : boundary_cycles(d)) {
        oracle::Cycle ids;
        for (const VertexId v : c) ids.push_back(v.index());
        queried.push_back(oracle::canonical(ids));
    }
    std::sort(queried.begin(), queried.end());
    FUZZ_CHECK(queried == ours, "boundary_cycles() differs from the cycles walked by next");

    const oracle::BoyerMyrvoldAnswer bm = oracle::boyer_myrvold(g);
    FUZZ_CHECK(bm.planar, "Boyer-Myrvold calls a valid straight-line graph non-planar");
    FUZZ_CHECK(bm.faces == ours.size(),
               "Boyer-Myrvold's embedding has " << bm.faces << " faces, the DCEL " << ours.size() << " cycles");
}

void check_euler(const Dcel& d, const PlanarGraph& g) {
    const std::size_t c = oracle::count_components(g);
    const std::size_t v = d.num_vertices(), e = d.num_edges(), f = d.num_faces();
    FUZZ_CHECK(v + f == e + 1 + c, "V - E + F = " << v << " - " << e << " + " << f << ", but 1 + C = " << 1 + c);
    FUZZ_CHECK(count_components(d) == c, "count_components() " << count_components(d) << ", union-find " << c);
}

// faces_around(v): the faces of v's outgoing half-edges in counterclockwise
// order (the exact oracle's), starting with out(v).
void check_faces_around(const Dcel& d) {
    std::vector<std::vector<HalfEdgeId>> outgoing(d.num_vertices());
    for (Index i = 0; i < d.num_half_edges(); ++i) outgoing[d.origin(HalfEdgeId(i)).index()].push_back(HalfEdgeId(i));
    for (Index i = 0; i < d.num_vertices(); ++i) {
        const VertexId v(i);
        const std::vector<FaceId> got = faces_around(d, v);
        std::vector<HalfEdgeId>& ring = outgoing[i];
        if (ring.empty()) {
            FUZZ_CHECK(got.size() == 1, "isolated " << v.str() << " lies in " << got.size() << " faces");
            const std::vector<VertexId>& listed = d.isolated(got[0]);
            FUZZ_CHECK(std::find(listed.begin(), listed.end(), v) != listed.end(),
                       "faces_around(" << v.str() << ") names a face that does not list it");
            continue;
        }
        const Point centre = d.point(v);
        std::sort(ring.begin(), ring.end(), [&](HalfEdgeId a, HalfEdgeId b) {
            return oracle::angle_order(centre, d.point(d.target(a)), d.point(d.target(b))) < 0;
        });
        const auto start = std::find(ring.begin(), ring.end(), d.out(v));
        FUZZ_CHECK(start != ring.end(), "out(" << v.str() << ") does not leave it");
        std::rotate(ring.begin(), start, ring.end());
        std::vector<FaceId> expected;
        for (const HalfEdgeId h : ring) expected.push_back(d.face(h));
        FUZZ_CHECK(got == expected, "faces_around(" << v.str() << ") disagrees with the exact angular order");
    }
}

void check_neighbours(const Dcel& d) {
    std::vector<std::vector<FaceId>> expected(d.num_faces());
    for (Index i = 0; i < d.num_half_edges(); ++i) {
        const HalfEdgeId h(i);
        const FaceId across = d.face(Dcel::twin(h));
        if (across != d.face(h)) expected[d.face(h).index()].push_back(across);
    }
    for (Index i = 0; i < d.num_faces(); ++i) {
        std::vector<FaceId>& e = expected[i];
        std::sort(e.begin(), e.end());
        e.erase(std::unique(e.begin(), e.end()), e.end());
        FUZZ_CHECK(neighbours(d, FaceId(i)) == e, "neighbours(f" << i << ") differs from a scan of all half-edges");
    }
}

int sign_of(const oracle::Rational& r) { return r.sign(); }
int sign_of(Sign s) { return s == Sign::Positive ? 1 : (s == Sign::Negative ? -1 : 0); }

void check_areas(const Dcel& d) {
    for (Index i = 0; i < d.num_faces(); ++i) {
        const FaceId f(i);
        if (d.is_unbounded(f)) continue;
        oracle::Rational twice = oracle::twice_area(testing::cycle_points(d, d.outer(f)));
        FUZZ_CHECK(sign_of(cycle_area(d, d.outer(f)).sign) == sign_of(twice),
                   "cycle_area sign of f" << i << "'s outer cycle");
        for (const HalfEdgeId h : d.inner(f)) {
            const oracle::Rational hole = oracle::twice_area(testing::cycle_points(d, h));
            FUZZ_CHECK(sign_of(cycle_area(d, h).sign) == sign_of(hole), "cycle_area sign of a hole of f" << i);
            twice += hole;
        }
        const oracle::Rational exact = twice / 2;
        const Area got = face_area(d, f);
        FUZZ_CHECK(exact > 0 && got.sign == Sign::Positive,
                   "f" << i << " has area of sign " << sign_of(exact) << ", face_area says " << sign_of(got.sign));
        FUZZ_CHECK(oracle::is_nearest_double(got.value, exact), "face_area(f" << i << ") = " << got.value
                                                                              << " is not the exact area " << exact.str()
                                                                              << " rounded to the nearest double");
    }
}

void check(const GeneratedGraph& c) {
    const PlanarGraph& g = c.graph;
    const oracle::Defects defects = oracle::find_defects(g, oracle::PairSearch::AllPairs);
    FUZZ_CHECK(defects.empty(), "the generator made an invalid graph: " << describe(c));
    Dcel d;
    try {
        d = build(g);
    } catch (const InvalidInput& e) {
        FUZZ_CHECK(false, "build rejects a valid generated graph, " << describe(c) << ": " << e.what());
    }
    const CheckResult v = validate(d);
    FUZZ_CHECK(!v, "validate rejects a built DCEL: [" << to_string(v->invariant) << "] " << v->message);
    check_cycles(d, g);
    check_euler(d, g);
    check_faces_around(d);
    check_neighbours(d);
    check_areas(d);
}

}  // namespace
}  // namespace dcel::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > dcel::fuzz::kMaxInput) return -1;
    dcel::fuzz::TokenReader in(std::string_view(reinterpret_cast<const char*>(data), size));
    dcel::fuzz::check(dcel::fuzz::decode_generated_graph(in, dcel::fuzz::kMaxVertices, dcel::fuzz::kMaxSteps));
    return 0;
}
