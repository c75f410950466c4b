// build() against a brute-force oracle that shares none of its machinery
// (no lex order, rank graph, sweep or union-find): on random small graphs,
// the oracle finds next() by looking at every half-edge at a vertex, walks
// the cycles, tells bounded faces from holes by exact signed area, and puts
// each component in the innermost positive cycle that winds around it
// (exact winding numbers). Invalid graphs: build() must throw exactly when
// a pairwise check finds two edges meeting badly, and name a real culprit.
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <random>
#include <set>
#include <vector>

#include "dcel/build.hpp"
#include "dcel/error.hpp"
#include "dcel/geometry/area.hpp"
#include "dcel/geometry/predicates.hpp"
#include "dcel/geometry/segments.hpp"
#include "support/face_shapes.hpp"

namespace dcel {
namespace {

using testing::Cycle;
using testing::FaceShape;
using testing::sorted_shapes;

Point at(const PlanarGraph& g, Index v) { return g.vertices[v]; }
Index origin_of(const PlanarGraph& g, Index h) {
    return (h & 1U) == 0 ? g.edges[h / 2].u.index() : g.edges[h / 2].v.index();
}
Index target_of(const PlanarGraph& g, Index h) { return origin_of(g, h ^ 1U); }

// next(u->v): of the half-edges leaving v, the first one met turning
// clockwise from v->u. By brute force over all of them: O(d) per half-edge.
std::vector<Index> oracle_next(const PlanarGraph& g) {
    const auto hs = static_cast<Index>(2 * g.edges.size());
    std::vector<Index> next(hs);
    for (Index h = 0; h < hs; ++h) {
        const Index back = h ^ 1U;  // v->u
        const Index v = origin_of(g, back);
        const Point c = at(g, v);
        const Point ref = at(g, target_of(g, back));
        // Clockwise from ref: the largest angle below ref's, else the largest of all.
        std::optional<Index> best_below;
        std::optional<Index> best_any;
        for (Index x = 0; x < hs; ++x) {
            if (origin_of(g, x) != v || x == back) continue;
            const Point p = at(g, target_of(g, x));
            auto later = [&](std::optional<Index> cur) {
                return !cur || compare_angle(c, at(g, target_of(g, *cur)), p) == Sign::Negative;
            };
            if (compare_angle(c, p, ref) == Sign::Negative && later(best_below)) best_below = x;
            if (later(best_any)) best_any = x;
        }
        next[h] = best_below ? *best_below : (best_any ? *best_any : back);
    }
    return next;
}

// Winding number of the closed walk `cycle` (origin vertices) around p,
// which is on none of its edges. Exact: coordinate comparisons and orient2d.
int winding(const PlanarGraph& g, const Cycle& cycle, Point p) {
    int w = 0;
    for (std::size_t i = 0; i < cycle.size(); ++i) {
        const Point a = at(g, cycle[i]);
        const Point b = at(g, cycle[(i + 1) % cycle.size()]);
        if (a.y <= p.y && p.y < b.y && orient2d(a, b, p) == Sign::Positive) ++w;
        if (b.y <= p.y && p.y < a.y && orient2d(a, b, p) == Sign::Negative) --w;
    }
    return w;
}

Sign cycle_area_sign(const PlanarGraph& g, const Cycle& cycle) {
    return polygon_area_sign([&](auto&& f) {
        for (std::size_t i = 0; i < cycle.size(); ++i) f(at(g, cycle[i]), at(g, cycle[(i + 1) % cycle.size()]));
    });
}

double cycle_twice_area(const PlanarGraph& g, const Cycle& cycle) {
    return polygon_twice_area([&](auto&& f) {
        for (std::size_t i = 0; i < cycle.size(); ++i) f(at(g, cycle[i]), at(g, cycle[(i + 1) % cycle.size()]));
    });
}

std::vector<FaceShape> oracle_faces(const PlanarGraph& g) {
    const auto n = static_cast<Index>(g.vertices.size());
    const std::vector<Index> next = oracle_next(g);
    // Components by repeated relaxation (slow and obviously right).
    std::vector<Index> comp(n);
    for (Index v = 0; v < n; ++v) comp[v] = v;
    for (bool changed = true; changed;) {
        changed = false;
        for (const GraphEdge& e : g.edges) {
            const Index m = std::min(comp[e.u.index()], comp[e.v.index()]);
            for (const VertexId x : {e.u, e.v}) {
                if (comp[x.index()] != m) comp[x.index()] = m, changed = true;
            }
        }
    }
    std::vector<Cycle> cycles;
    std::vector<Index> cycle_comp;
    std::vector<char> seen(next.size(), 0);
    for (Index h = 0; h < next.size(); ++h) {
        if (seen[h] != 0) continue;
        Cycle c;
        for (Index x = h; seen[x] == 0; x = next[x]) {
            seen[x] = 1;
            c.push_back(origin_of(g, x));
        }
        cycles.push_back(c);
        cycle_comp.push_back(comp[c[0]]);
    }
    // Positive cycles bound faces; every other cycle is a component's outer boundary.
    std::vector<FaceShape> faces(1);  // faces[0]: unbounded
    std::vector<std::size_t> face_of_cycle(cycles.size(), 0);
    for (std::size_t i = 0; i < cycles.size(); ++i) {
        if (cycle_area_sign(g, cycles[i]) == Sign::Positive) {
            face_of_cycle[i] = faces.size();
            faces.push_back({cycles[i], {}, {}});
        }
    }
    // Each component (a hole or an isolated vertex) goes in the innermost
    // positive cycle of another component that winds around it; nested
    // faces around one point are nested regions, so the smallest area wins.
    auto container = [&](Index component) {
        std::size_t best = 0;
        double best_area = 0;
        for (std::size_t i = 0; i < cycles.size(); ++i) {
            if (face_of_cycle[i] == 0 || cycle_comp[i] == component) continue;
            if (winding(g, cycles[i], at(g, component)) == 0) continue;
            const double area = cycle_twice_area(g, cycles[i]);  // exact here: small integers
            if (best == 0 || area < best_area) best = face_of_cycle[i], best_area = area;
        }
        return best;
    };
    for (std::size_t i = 0; i < cycles.size(); ++i) {
        if (face_of_cycle[i] == 0) faces[container(cycle_comp[i])].holes.push_back(cycles[i]);
    }
    std::vector<char> has_edge(n, 0);
    for (const GraphEdge& e : g.edges) has_edge[e.u.index()] = has_edge[e.v.index()] = 1;
    for (Index v = 0; v < n; ++v) {
        if (has_edge[v] == 0) faces[container(v)].isolated.push_back(v);
    }
    return sorted_shapes(faces);
}

// Whether edges a and b (input indexes) meet other than at a shared endpoint.
bool edges_conflict(const PlanarGraph& g, Index a, Index b) {
    const GraphEdge& e = g.edges[a];
    const GraphEdge& f = g.edges[b];
    const std::set<Index> ends{e.u.index(), e.v.index(), f.u.index(), f.v.index()};
    if (ends.size() == 2) return true;  // a duplicate edge
    const Contact c = segment_contact(at(g, e.u.index()), at(g, e.v.index()), at(g, f.u.index()), at(g, f.v.index()));
    return c != Contact::None && c != Contact::SharedEndpoint;
}

bool vertex_on_edge(const PlanarGraph& g, Index v, Index k) {
    const GraphEdge& e = g.edges[k];
    return strictly_inside_segment(at(g, e.u.index()), at(g, e.v.index()), at(g, v));
}

bool valid(const PlanarGraph& g) {
    for (Index a = 0; a < g.edges.size(); ++a) {
        for (Index b = a + 1; b < g.edges.size(); ++b) {
            if (edges_conflict(g, a, b)) return false;
        }
        for (Index v = 0; v < g.vertices.size(); ++v) {
            if (vertex_on_edge(g, v, a)) return false;
        }
    }
    return true;
}

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
        const std::vector<FaceShape> expected = oracle_faces(g);
        ASSERT_EQ(testing::face_shapes(build(g)), expected) << "round " << round;
        ASSERT_EQ(testing::face_shapes(build(g, {.check_crossings = false})), expected) << "round " << round;
    }
}

TEST(BuildOracle, TreesAmongFramesMatchBruteForce) {
    // The unchecked build skips the sweep for forests and sweeps only the
    // components with cycles otherwise: trees must still land in the right
    // frame.
    std::mt19937_64 rng(2028);
    for (int round = 0; round < 300; ++round) {
        const PlanarGraph g = random_graph(rng, true, true);
        const std::vector<FaceShape> expected = oracle_faces(g);
        ASSERT_EQ(testing::face_shapes(build(g)), expected) << "round " << round;
        ASSERT_EQ(testing::face_shapes(build(g, {.check_crossings = false})), expected) << "round " << round;
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
            switch (e.kind()) {
                case InputErrorKind::Crossing:
                case InputErrorKind::DuplicateEdge:
                    ASSERT_EQ(es.size(), 2U) << e.what();
                    EXPECT_TRUE(edges_conflict(g, es[0].index(), es[1].index())) << e.what();
                    break;
                case InputErrorKind::Overlap:
                    ASSERT_EQ(es.size(), 2U) << e.what();
                    EXPECT_TRUE(edges_conflict(g, es[0].index(), es[1].index())) << e.what();
                    break;
                case InputErrorKind::VertexOnEdge:
                    ASSERT_EQ(es.size(), 1U) << e.what();
                    ASSERT_EQ(vs.size(), 1U) << e.what();
                    EXPECT_TRUE(vertex_on_edge(g, vs[0].index(), es[0].index())) << e.what();
                    break;
                default: ADD_FAILURE() << "unexpected kind: " << e.what();
            }
        }
    }
    EXPECT_GT(rejected, 100);  // the generator does make invalid graphs
}

}  // namespace
}  // namespace dcel
