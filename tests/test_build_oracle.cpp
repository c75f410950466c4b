// build() against the reference DCEL (oracles/reference_dcel.hpp), which
// shares none of its machinery (no lex order, rank graph, sweep or filtered
// predicate): on random small graphs, the reference sorts each vertex's
// half-edges by exact angle, walks the cycles, tells bounded faces from
// holes by exact signed area, and puts each component in the innermost
// positive cycle that winds around it. Invalid graphs: build() must throw
// exactly when brute force (oracles/brute_force.hpp) finds a defect, and
// name one it found.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <vector>

#include "dcel/build.hpp"
#include "dcel/error.hpp"
#include "oracles/brute_force.hpp"
#include "oracles/reference_dcel.hpp"
#include "support/face_shapes.hpp"

namespace dcel {
namespace {

using oracle::Defects;
using oracle::find_defects;
using oracle::Meeting;
using test_support::FaceShape;

bool valid(const PlanarGraph& g) { return find_defects(g).empty(); }

// Whether u and v are already joined by a path in g (by search).
bool connected(const PlanarGraph& g, Index u, Index v) {
    std::vector<char> seen(g.vertices.size(), 0);
    std::vector<Index> stack{u};
    seen[u] = 1;
    while (!stack.empty()) {
        const Index x = stack.back();
        stack.pop_back();
        if (x == v) return true;
        for (const GraphEdge& e : g.edges) {
            for (const auto& [a, b] : {std::pair{e.u, e.v}, std::pair{e.v, e.u}}) {
                if (a.index() == x && seen[b.index()] == 0) seen[b.index()] = 1, stack.push_back(b.index());
            }
        }
    }
    return false;
}

// Distinct points on a small grid (many collinear triples), random edges kept
// when the graph stays valid, and sometimes nested frames around the lot so
// that holes have holes. With trees_only, an edge is also dropped when it
// would close a cycle, so the only cycles are the frames: trees among and
// inside cycles, or a whole forest when there are no frames.
PlanarGraph random_graph(std::mt19937_64& rng, bool keep_valid, bool trees_only = false) {
    PlanarGraph g;
    const int side = std::uniform_int_distribution<int>(3, 9)(rng);
    const int points = std::uniform_int_distribution<int>(1, side * side / 2 + 1)(rng);
    std::set<std::pair<int, int>> used;
    while (static_cast<int>(g.vertices.size()) < points) {
        const int x = std::uniform_int_distribution<int>(0, side)(rng);
        const int y = std::uniform_int_distribution<int>(0, side)(rng);
        if (used.insert({x, y}).second) g.vertices.push_back({static_cast<double>(x), static_cast<double>(y)});
    }
    const int frames = std::uniform_int_distribution<int>(0, 2)(rng);
    for (int f = 1; f <= frames; ++f) {
        const auto b = static_cast<Index>(g.vertices.size());
        const double lo = -2.0 * f;
        const double hi = side + 2.0 * f;
        g.vertices.insert(g.vertices.end(), {{lo, lo}, {hi, lo}, {hi, hi}, {lo, hi}});
        for (Index k = 0; k < 4; ++k) g.edges.push_back({VertexId(b + k), VertexId(b + (k + 1) % 4)});
    }
    const auto n = static_cast<Index>(g.vertices.size());
    const int attempts = std::uniform_int_distribution<int>(0, 3 * points)(rng);
    for (int i = 0; i < attempts; ++i) {
        const Index u = std::uniform_int_distribution<Index>(0, n - 1)(rng);
        const Index v = std::uniform_int_distribution<Index>(0, n - 1)(rng);
        if (u == v || (trees_only && connected(g, u, v))) continue;
        g.edges.push_back({VertexId(u), VertexId(v)});
        if (keep_valid && !valid(g)) g.edges.pop_back();
    }
    std::shuffle(g.edges.begin(), g.edges.end(), rng);
    return g;
}

TEST(BuildOracle, FacesHolesAndIsolatedVerticesMatchBruteForce) {
    std::mt19937_64 rng(2026);
    for (int round = 0; round < 400; ++round) {
        const PlanarGraph g = random_graph(rng, true);
        ASSERT_TRUE(valid(g));
        const std::vector<FaceShape> expected = oracle::reference_faces(g);
        ASSERT_EQ(test_support::face_shapes(build(g)), expected) << "round " << round;
        ASSERT_EQ(test_support::face_shapes(build(g, {.check_crossings = false})), expected) << "round " << round;
    }
}

TEST(BuildOracle, TreesAmongFramesMatchBruteForce) {
    // The unchecked build skips the sweep for forests and sweeps only the
    // components with cycles otherwise: trees must still land in the right
    // frame.
    std::mt19937_64 rng(2028);
    for (int round = 0; round < 300; ++round) {
        const PlanarGraph g = random_graph(rng, true, true);
        const std::vector<FaceShape> expected = oracle::reference_faces(g);
        ASSERT_EQ(test_support::face_shapes(build(g)), expected) << "round " << round;
        ASSERT_EQ(test_support::face_shapes(build(g, {.check_crossings = false})), expected) << "round " << round;
    }
}

TEST(BuildOracle, RejectsExactlyTheInvalidGraphsAndNamesARealCulprit) {
    std::mt19937_64 rng(2027);
    int rejected = 0;
    for (int round = 0; round < 600; ++round) {
        const PlanarGraph g = random_graph(rng, round % 3 == 0);
        const bool ok = valid(g);
        // Unchecked mode promises only memory safety and termination on
        // crossing input (checked under the sanitizers); on valid input it
        // must agree with the checked build (first test).
        try {
            EXPECT_EQ(build(g, {.check_crossings = false}).num_edges(), g.edges.size());
        } catch (const InvalidInput& e) {
            EXPECT_FALSE(ok) << e.what();  // duplicate edges and same-direction edges are still rejected
        }
        try {
            (void)build(g);
            EXPECT_TRUE(ok) << "round " << round << ": accepted an invalid graph";
        } catch (const InvalidInput& e) {
            ++rejected;
            EXPECT_FALSE(ok) << "round " << round << ": " << e.what();
            const auto& es = e.edges();
            const auto& vs = e.vertices();
            const Defects found = find_defects(g);
            auto pair_found = [&](std::initializer_list<Meeting> how) {
                const Index lo = std::min(es[0].index(), es[1].index()), hi = std::max(es[0].index(), es[1].index());
                return std::any_of(found.edge_pairs.begin(), found.edge_pairs.end(), [&](const Defects::EdgePair& p) {
                    return p.e1 == lo && p.e2 == hi && std::find(how.begin(), how.end(), p.how) != how.end();
                });
            };
            switch (e.kind()) {
                case InputErrorKind::Crossing:
                    ASSERT_EQ(es.size(), 2U) << e.what();
                    EXPECT_TRUE(pair_found({Meeting::Crossing})) << e.what();
                    break;
                case InputErrorKind::DuplicateEdge: {
                    ASSERT_EQ(es.size(), 2U) << e.what();
                    // A real duplicate: the two edges join the same two vertices.
                    auto ends = [&](EdgeId k) {
                        const GraphEdge& x = g.edges[k.index()];
                        return std::pair{std::min(x.u, x.v), std::max(x.u, x.v)};
                    };
                    EXPECT_NE(es[0], es[1]) << e.what();
                    EXPECT_EQ(ends(es[0]), ends(es[1])) << e.what();
                    break;
                }
                case InputErrorKind::Overlap:
                    ASSERT_EQ(es.size(), 2U) << e.what();
                    EXPECT_TRUE(pair_found({Meeting::Overlap, Meeting::Same})) << e.what();
                    break;
                case InputErrorKind::VertexOnEdge: {
                    ASSERT_EQ(es.size(), 1U) << e.what();
                    ASSERT_EQ(vs.size(), 1U) << e.what();
                    const std::pair<Index, Index> named{vs[0].index(), es[0].index()};
                    EXPECT_EQ(std::count(found.vertex_in_edge.begin(), found.vertex_in_edge.end(), named), 1) << e.what();
                    break;
                }
                default: ADD_FAILURE() << "unexpected kind: " << e.what();
            }
        }
    }
    EXPECT_GT(rejected, 100);  // the generator does make invalid graphs
}

}  // namespace
}  // namespace dcel
