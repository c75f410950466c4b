// oracle: valid graphs through build(), compared with Boost, the reference
// DCEL and the exact oracles (tests/oracles/, none of which uses
// src/dcel/geometry).
//
// Compares the DCEL's faces with the reference DCEL's (every cycle, every
// hole and isolated vertex in its face), and its boundary cycles with the
// faces of Boost's planar_face_traversal over a rotation system sorted by
// the oracles' own exact comparator, once per input for both and for
// faces_around (oracles/rotations.hpp). (Boost skips isolated vertices and
// reports each component's outer walk as a face of its own, which is
// exactly a hole cycle, so cycles are compared, not faces). Also: on small
// graphs, Boyer-Myrvold calls the graph planar and its embedding has as
// many faces as the DCEL has cycles; V - E + F = 1 + C with C by
// union-find; validate() passes; the graph is valid by brute force (exact;
// pairs found by bounding boxes, and on small graphs all pairs, which must
// agree). The
// queries are checked against the same oracles: boundary_cycles(),
// count_components(), faces_around() against the exact angular order,
// neighbours() against a scan of all half-edges, cycle_area() signs and
// face_area() values against exact areas (face_area promises the exact
// area rounded once); and at a few points and segments built from the
// graph's own points (vertices, rounded edge midpoints, rounded centroids),
// PointLocator and locate_by_scan against exact point location, and
// stab_segment and stab_line against the exact stabbing checks
// (tests/oracles/stab_walk.hpp).
//
// Input: readable text (support/graph_input.hpp): a recipe naming a
// generated graph, e.g.
//   triangulation seed 7 vertices 30 mirror scale -3 drop 4
// or a graph point by point, which is what the custom mutator writes
// (support/graph_mutator.hpp: near-degenerate moves, edges added and
// removed, components copied into faces, exact transforms), e.g.
//   points 0 0, 4 0, 0 4, 1 1  edges 0 1, 1 2, 2 0
// A graph given point by point that is not valid is skipped.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dcel/build.hpp"
#include "dcel/error.hpp"
#include "dcel/locate.hpp"
#include "dcel/queries.hpp"
#include "dcel/stab.hpp"
#include "dcel/validate.hpp"
#include "oracles/boost_oracle.hpp"
#include "oracles/brute_force.hpp"
#include "oracles/exact.hpp"
#include "oracles/reference_dcel.hpp"
#include "oracles/rotations.hpp"
#include "oracles/stab_walk.hpp"
#include "oracles/union_find.hpp"
#include "support/dcel_views.hpp"
#include "support/face_shapes.hpp"
#include "support/fuzz_check.hpp"
#include "support/graph_fuzzer.hpp"
#include "support/graph_input.hpp"

namespace dcel::fuzz {
namespace {

// A few hundred vertices: the oracles are near E log E (the brute force's
// pairs of overlapping boxes, the angle sorts, the traversal), so a run
// stays within milliseconds under the sanitizers; a graph of that size
// takes some 10 KB of text. The quadratic all-pairs brute force and
// Boyer-Myrvold, which on large graphs cost more than everything else,
// check small graphs only.
constexpr std::size_t kMaxInput = 32 * 1024;
constexpr GraphLimits kLimits{300, 900};
constexpr std::size_t kSmallEdges = 24;

void check_validity(const GraphInput& in, const oracle::Defects& defects) {
    const PlanarGraph& g = in.graph;
    if (g.edges.size() <= kSmallEdges) {
        FUZZ_CHECK(oracle::find_defects(g, oracle::PairSearch::AllPairs) == defects,
                   "the brute force's bounding-box pairs and all pairs disagree on " << describe(in));
    }
    FUZZ_CHECK(defects.empty(),
               "the generator made an invalid graph: " << describe(in) << ": " << oracle::describe(defects.kinds()));
}

// The graph's exact rotation system, sorted once for every check that needs it.
struct Embedded {
    oracle::HalfEdgeGraph half_edges;
    oracle::Rotations rotations;
    explicit Embedded(const PlanarGraph& g)
        : half_edges(oracle::half_edges_of(g)), rotations(oracle::rotation_system(half_edges)) {}
};

void check_faces(const Dcel& d, const Embedded& e) {
    const std::vector<oracle::FaceShape> ours = test_support::face_shapes(d);
    const std::vector<oracle::FaceShape> reference = oracle::face_shapes(e.half_edges,
                                                                         oracle::reference_dcel(e.half_edges, e.rotations));
    FUZZ_CHECK(ours == reference,
               "the DCEL has " << ours.size() << " faces, the reference DCEL " << reference.size() << "; they differ");
}

void check_cycles(const Dcel& d, const PlanarGraph& g, const Embedded& e) {
    const std::vector<oracle::Cycle> ours = test_support::dcel_cycles(d);
    const std::vector<oracle::Cycle> boost = oracle::boost_face_cycles(g, e.rotations);
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

    if (g.edges.size() > kSmallEdges) return;
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
// order (the exact rotation system's), starting with out(v). The rotation
// system numbers half-edges as the DCEL does (input edge k owns 2k, u->v,
// and 2k+1), so its rings name the DCEL's half-edges directly.
void check_faces_around(const Dcel& d, const Embedded& e) {
    for (Index i = 0; i < d.num_vertices(); ++i) {
        const VertexId v(i);
        const std::vector<FaceId> got = faces_around(d, v);
        const std::vector<Index>& ring = e.rotations.ring[i];
        if (ring.empty()) {
            FUZZ_CHECK(got.size() == 1, "isolated " << v.str() << " lies in " << got.size() << " faces");
            const std::vector<VertexId>& listed = d.isolated(got[0]);
            FUZZ_CHECK(std::find(listed.begin(), listed.end(), v) != listed.end(),
                       "faces_around(" << v.str() << ") names a face that does not list it");
            continue;
        }
        std::vector<HalfEdgeId> ordered;
        for (const Index h : ring) {
            FUZZ_CHECK(d.origin(HalfEdgeId(h)) == v, "h" << h << " of the input's numbering does not leave " << v.str());
            ordered.emplace_back(h);
        }
        const auto start = std::find(ordered.begin(), ordered.end(), d.out(v));
        FUZZ_CHECK(start != ordered.end(), "out(" << v.str() << ") does not leave it");
        std::rotate(ordered.begin(), start, ordered.end());
        std::vector<FaceId> expected;
        for (const HalfEdgeId h : ordered) expected.push_back(d.face(h));
        FUZZ_CHECK(got == expected, "faces_around(" << v.str() << ") disagrees with the exact angular order");
    }
}

// cycle_reversed(h) is cycle(h) walked backwards from h; the link arrays
// handed out whole (for the Python module's views) are prev(), face() and
// out() id by id.
void check_orbits(const Dcel& d) {
    for (Index i = 0; i < d.num_half_edges(); ++i) {
        const HalfEdgeId h(i);
        FUZZ_CHECK(d.prev_links()[i] == d.prev(h) && d.left_faces()[i] == d.face(h),
                   "prev_links() or left_faces() differs from prev() or face() at h" << i);
    }
    for (Index i = 0; i < d.num_vertices(); ++i) {
        FUZZ_CHECK(d.out_links()[i] == d.out(VertexId(i)), "out_links() differs from out() at v" << i);
    }
    std::vector<char> seen(d.num_half_edges(), 0);
    for (Index i = 0; i < d.num_half_edges(); ++i) {
        if (seen[i] != 0) continue;
        std::vector<HalfEdgeId> forward, backward;
        for (const HalfEdgeId h : d.cycle(HalfEdgeId(i))) {
            forward.push_back(h);
            seen[h.index()] = 1;
        }
        // The iterator's post-increment, which range-for never uses.
        for (auto it = d.cycle_reversed(HalfEdgeId(i)).begin(); it != std::default_sentinel; it++) backward.push_back(*it);
        std::reverse(backward.begin() + 1, backward.end());
        FUZZ_CHECK(backward == forward, "cycle_reversed(h" << i << ") is not cycle(h" << i << ") backwards");
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
        oracle::Rational twice = oracle::twice_area(test_support::cycle_points(d, d.outer(f)));
        FUZZ_CHECK(sign_of(cycle_area(d, d.outer(f)).sign) == sign_of(twice),
                   "cycle_area sign of f" << i << "'s outer cycle");
        for (const HalfEdgeId h : d.inner(f)) {
            const oracle::Rational hole = oracle::twice_area(test_support::cycle_points(d, h));
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

// Probe points from the graph's own geometry, where location is hardest: a
// vertex, the rounded midpoint of an edge (on it or within rounding), and
// the rounded centroid of three vertices (often inside a face).
std::vector<Point> probes(const PlanarGraph& g) {
    std::vector<Point> out;
    const std::size_t n = g.vertices.size(), m = g.edges.size();
    if (n == 0) return out;
    for (std::size_t k = 1; k <= 2; ++k) {
        const Point a = g.vertices[(k * 7919) % n], b = g.vertices[(k * 104729 + 1) % n], c = g.vertices[(k * 13 + 2) % n];
        out.push_back(a);
        if (m > 0) {
            const GraphEdge& e = g.edges[(k * 31) % m];
            const Point u = g.vertices[e.u.index()], w = g.vertices[e.v.index()];
            out.push_back({(u.x + w.x) / 2, (u.y + w.y) / 2});
        }
        out.push_back({(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3});
    }
    return out;
}

// stab_line through a and b against the exact line checks; started from a
// half-edge whose edge the line meets it walks the same, and from one whose
// edge lies strictly on one side it refuses with TopologyError.
void check_line(const Dcel& d, const oracle::ExactLocator& exact, Point a, Point b) {
    const std::vector<StabPiece> line = stab_line(d, a, b);
    const std::string problem = oracle::check_line_walk(d, exact, a, b, line);
    FUZZ_CHECK(problem.empty(),
               "stab_line through (" << a.x << ", " << a.y << ") and (" << b.x << ", " << b.y << "): " << problem);
    std::vector<FaceId> faces;
    for (const StabPiece& p : line) {
        if (p.kind == StabPiece::Kind::Face) faces.push_back(p.face);
    }
    FUZZ_CHECK(faces_in_order(line) == faces, "faces_in_order() is not the line's face pieces");
    for (const StabPiece& p : line) {
        if (p.kind != StabPiece::Kind::Edge) continue;
        FUZZ_CHECK(stab_line(d, a, b, half_edge_of(p.edge, 1)) == line,
                   "stab_line started on e" << p.edge.index() << " walks another way");
        break;
    }
    for (Index e = 0; e < d.num_edges(); ++e) {
        const HalfEdgeId h = half_edge_of(EdgeId(e), 0);
        if (oracle::orientation(a, b, d.point(d.origin(h))) * oracle::orientation(a, b, d.point(d.target(h))) <= 0) continue;
        bool refused = false;
        try {
            (void)stab_line(d, a, b, h);
        } catch (const TopologyError&) {
            refused = true;
        }
        FUZZ_CHECK(refused, "stab_line started on e" << e << ", which the line misses, does not refuse");
        break;
    }
}

// The walks refuse what they cannot follow, each with InvalidInput of the
// kind its contract names: a point with a coordinate that is not finite,
// a "line" through one point, a start half-edge the DCEL does not have.
template <class Walk>
void check_refused(Walk walk, InputErrorKind kind, const char* what) {
    bool refused = false;
    try {
        (void)walk();
    } catch (const InvalidInput& e) {
        const std::string_view message = e.what();
        FUZZ_CHECK(e.kind() == kind && message.find('\n') == std::string_view::npos,
                   what << " is refused with " << to_string(e.kind()) << ": " << message);
        refused = true;
    }
    FUZZ_CHECK(refused, what << " is not refused");
}

void check_refusals(const Dcel& d, Point finite, Point not_finite) {
    check_refused([&] { return stab_segment(d, finite, not_finite); }, InputErrorKind::BadCoordinate,
                  "stab_segment to a point that is not finite");
    check_refused([&] { return stab_line(d, not_finite, finite); }, InputErrorKind::BadCoordinate,
                  "stab_line through a point that is not finite");
    check_refused([&] { return stab_line(d, finite, finite); }, InputErrorKind::BadCoordinate,
                  "stab_line through one point twice");
    check_refused([&] { return stab_line(d, finite, finite, HalfEdgeId(0)); }, InputErrorKind::BadCoordinate,
                  "stab_line from a half-edge through one point twice");
    const Point other{finite.x == 0 ? 1.0 : 0.0, finite.y};
    check_refused([&] { return stab_line(d, finite, other, HalfEdgeId(d.num_half_edges())); }, InputErrorKind::BadIndex,
                  "stab_line from a half-edge past the last");
}

void check_location_and_stabbing(const Dcel& d, const PlanarGraph& g) {
    const std::vector<Point> points = probes(g);
    if (points.empty()) return;
    const oracle::ExactLocator exact(d);
    const PointLocator locator(d);
    for (const Point p : points) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;  // a centroid of huge coordinates overflows
        const Location want = exact.locate(p);
        FUZZ_CHECK(locator.locate(p) == want,
                   "PointLocator puts (" << p.x << ", " << p.y << ") " << locator.locate(p) << ", exact location " << want);
        FUZZ_CHECK(locate_by_scan(d, p) == want, "locate_by_scan puts (" << p.x << ", " << p.y << ") "
                                                                         << locate_by_scan(d, p) << ", exact location "
                                                                         << want);
    }
    auto finite = [](Point p) { return std::isfinite(p.x) && std::isfinite(p.y); };
    const auto good = std::find_if(points.begin(), points.end(), finite);
    const auto bad = std::find_if_not(points.begin(), points.end(), finite);
    if (good != points.end()) {
        check_refusals(d, *good, bad != points.end() ? *bad : Point{std::numeric_limits<double>::quiet_NaN(), good->y});
    }
    for (std::size_t i = 0; i + 1 < points.size(); i += 2) {
        const Point a = points[i], b = points[i + 1];
        if (!finite(a) || !finite(b)) continue;
        const std::string problem = oracle::check_walk(d, exact, a, b, stab_segment(d, a, b));
        FUZZ_CHECK(problem.empty(),
                   "stab_segment from (" << a.x << ", " << a.y << ") to (" << b.x << ", " << b.y << "): " << problem);
        if (a != b) check_line(d, exact, a, b);
    }
}

// Skips (false) a graph given point by point that is not valid; a
// generated one must be.
bool check(const GraphInput& in) {
    const PlanarGraph& g = in.graph;
    const oracle::Defects defects = oracle::find_defects(g);
    if (!in.generated && !defects.empty()) return false;
    check_validity(in, defects);
    Dcel d;
    try {
        d = build(g);
    } catch (const InvalidInput& e) {
        FUZZ_CHECK(false, "build rejects a valid graph, " << describe(in) << ": " << e.what());
    }
    const CheckResult v = validate(d);
    FUZZ_CHECK(!v, "validate rejects a built DCEL: [" << to_string(v->invariant) << "] " << v->message);
    const Embedded embedded(g);
    check_faces(d, embedded);
    check_cycles(d, g, embedded);
    check_euler(d, g);
    check_faces_around(d, embedded);
    check_neighbours(d);
    check_orbits(d);
    check_areas(d);
    check_location_and_stabbing(d, g);
    return true;
}

constexpr GraphInputCaps kCaps{kLimits.vertices, 32, {kLimits.vertices, kLimits.edges}};

// The mutator's view of an input: a valid graph, or nothing.
std::optional<PlanarGraph> valid_graph(std::string_view text) {
    GraphInput in = decode_graph_input(text, kCaps);
    if (!is_valid(in.graph)) return std::nullopt;
    return std::move(in.graph);
}

constexpr GraphFuzzing kFuzzing{valid_graph, Validity::Keep, kLimits};

}  // namespace
}  // namespace dcel::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace dcel::fuzz;
    if (size > kMaxInput) return -1;
    return check(decode_graph_input(as_text(data, size), kCaps)) ? 0 : -1;  // -1: not added to the corpus
}

DCEL_GRAPH_FUZZER_HOOKS(dcel::fuzz::kFuzzing)
