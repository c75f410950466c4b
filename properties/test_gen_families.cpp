// Unit tests of dcel::gen's families and GraphBuilder: every family gives
// exactly the vertices asked for at every size (the size rule in
// src/dcel/gen/families.hpp), valid graphs (build() accepts them, and the
// brute-force checks agree where they are affordable), graphs of the
// family's own character at sizes 100 to 10000, the same graph for the same
// parameters, and 1e5 vertices without quadratic work. GraphBuilder's grid
// makes the same decisions as brute force.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <deque>
#include <string>

#include "dcel/build.hpp"
#include "dcel/error.hpp"
#include "dcel/gen/brute_force.hpp"
#include "dcel/gen/generate.hpp"
#include "dcel/gen/graph_builder.hpp"
#include "dcel/gen/rng.hpp"
#include "dcel/queries.hpp"
#include "oracles/brute_force.hpp"
#include "oracles/exact.hpp"
#include "oracles/union_find.hpp"

namespace dcel::gen {
namespace {

std::string label(Family f, std::size_t n, std::uint64_t seed) {
    return std::string(family_name(f)) + " n=" + std::to_string(n) + " seed=" + std::to_string(seed);
}

// What a graph looks like, from build() and from the graph itself.
struct Shape {
    std::size_t edges = 0, components = 0, max_degree = 0, leaves = 0;
    std::size_t bounded_faces = 0, triangles = 0, other_bounded_faces = 0, faces_with_holes = 0;
    std::size_t isolated_in_bounded = 0;  // isolated vertices inside bounded faces
    std::size_t longest_cycle = 0;        // half-edges in the longest boundary cycle
    std::size_t depth = 0;                // faces nested in holes of faces, counted from the unbounded one
    std::size_t most_collinear = 0;       // most vertices on the line of one of the first 16 edges (if asked)
};

std::size_t cycle_length(const Dcel& d, HalfEdgeId start) {
    std::size_t n = 0;
    HalfEdgeId h = start;
    do {
        ++n;
        h = d.next(h);
    } while (h != start);
    return n;
}

Shape shape_of(const PlanarGraph& g, bool collinear = false) {
    const Dcel d = build(g);
    Shape s;
    s.edges = g.edges.size();
    s.components = oracle::count_components(g);
    std::vector<std::size_t> degree(g.vertices.size(), 0);
    for (const GraphEdge& e : g.edges) ++degree[e.u.index()], ++degree[e.v.index()];
    for (const std::size_t k : degree) {
        s.max_degree = std::max(s.max_degree, k);
        s.leaves += k == 1;
    }
    for (const std::vector<VertexId>& c : boundary_cycles(d)) s.longest_cycle = std::max(s.longest_cycle, c.size());
    // Depth by a 0-1 breadth-first search over faces: crossing a face's
    // outer cycle keeps the depth, crossing into a hole adds one.
    std::vector<std::size_t> depth(d.num_faces(), SIZE_MAX);
    std::deque<Index> queue;
    for (Index f = 0; f < d.num_faces(); ++f) {
        if (d.outer(FaceId(f)).is_null()) {
            depth[f] = 0;
            queue.push_back(f);
        }
    }
    while (!queue.empty()) {
        const Index f = queue.front();
        queue.pop_front();
        auto cross = [&](HalfEdgeId start, std::size_t step) {
            HalfEdgeId h = start;
            do {
                const Index other = d.face(twin(h)).index();
                if (depth[f] + step < depth[other]) {
                    depth[other] = depth[f] + step;
                    if (step == 0) queue.push_front(other);
                    else queue.push_back(other);
                }
                h = d.next(h);
            } while (h != start);
        };
        if (!d.outer(FaceId(f)).is_null()) cross(d.outer(FaceId(f)), 0);
        for (const HalfEdgeId h : d.inner(FaceId(f))) cross(h, 1);
    }
    for (Index f = 0; f < d.num_faces(); ++f) {
        s.depth = std::max(s.depth, depth[f]);
        if (d.outer(FaceId(f)).is_null()) continue;
        ++s.bounded_faces;
        s.faces_with_holes += !d.inner(FaceId(f)).empty();
        s.isolated_in_bounded += d.isolated(FaceId(f)).size();
        if (d.inner(FaceId(f)).empty() && cycle_length(d, d.outer(FaceId(f))) == 3) ++s.triangles;
        else ++s.other_bounded_faces;
    }
    for (std::size_t k = 0; collinear && k < std::min<std::size_t>(16, g.edges.size()); ++k) {
        const Point a = g.vertices[g.edges[k].u.index()], b = g.vertices[g.edges[k].v.index()];
        std::size_t on_line = 0;
        for (const Point& p : g.vertices) on_line += oracle::orientation(a, b, p) == 0;
        s.most_collinear = std::max(s.most_collinear, on_line);
    }
    return s;
}

bool same_bits(const PlanarGraph& a, const PlanarGraph& b) {
    return a.vertices.size() == b.vertices.size() && a.edges == b.edges &&
           std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(Point)) == 0;
}

// The size rule, and validity three ways: build(), GraphBuilder's own
// brute-force check, and the properties' exact oracle (the last two are
// quadratic, so only where they stay fast).
TEST(Families, ExactlyTheVerticesAskedAndValidAtEverySize) {
    for (const Family f : all_families()) {
        for (const std::size_t n : {0, 1, 2, 3, 5, 10, 100, 1000, 10000}) {
            const std::uint64_t seeds = n <= 100 ? 40 : n <= 1000 ? 6 : 3;
            for (std::uint64_t seed = 0; seed < seeds; ++seed) {
                SCOPED_TRACE(label(f, n, seed));
                const PlanarGraph g = generate({f, seed, n});
                EXPECT_EQ(g.vertices.size(), n);
                EXPECT_NO_THROW((void)build(g));
                if (n <= 100 || (n == 1000 && seed < 2)) {
                    EXPECT_EQ(find_problem(g), std::nullopt);
                }
                if (n <= 100) {
                    EXPECT_TRUE(oracle::find_defects(g).empty());
                }
            }
        }
    }
}

TEST(Families, SameParametersSameGraph) {
    for (const Family f : all_families()) {
        for (const std::size_t n : {7, 1000}) {
            for (const std::uint64_t seed : {0ULL, 12345ULL, ~0ULL}) {
                EXPECT_TRUE(same_bits(generate({f, seed, n}), generate({f, seed, n}))) << label(f, n, seed);
            }
        }
    }
    EXPECT_FALSE(same_bits(generate({Family::Tree, 1, 100}), generate({Family::Tree, 2, 100})));
}

// Each family's character at sizes 100, 1000 and 10000: what every graph
// has, and what some seed among a few has. The 10000-vertex graphs are the
// big cases `dcel diff` draws on: a vertex of degree 9999, boundary cycles
// of thousands of half-edges, a full triangulation of 10000 points.
TEST(Families, KeepTheirCharacterAtLargeSizes) {
    for (const std::size_t n : {100, 1000, 10000}) {
        const std::uint64_t seeds = n <= 1000 ? 12 : 6;
        for (const Family f : all_families()) {
            bool some = false, other = false, third = false;
            for (std::uint64_t seed = 0; seed < seeds; ++seed) {
                SCOPED_TRACE(label(f, n, seed));
                const Shape s = shape_of(generate({f, seed, n}), f == Family::CollinearChain);
                switch (f) {
                    case Family::RandomSegments:
                        EXPECT_GE(s.edges, n / 2);
                        some = some || s.longest_cycle >= n;  // one simple polygon through every point
                        other = other || (s.components > 1 && s.bounded_faces > 1);
                        break;
                    case Family::Triangulation:
                        EXPECT_GE(s.edges, n / 2);
                        some = some || (s.other_bounded_faces == 0 && s.triangles >= n - 2);  // all edges kept
                        other = other || s.components > n / 10;                               // a sparse subset
                        break;
                    case Family::GridWithHoles:
                        EXPECT_GE(s.bounded_faces, n / 10);
                        EXPECT_LE(s.max_degree, 8u);
                        some = some || s.faces_with_holes > 0;  // an island in a hole
                        break;
                    case Family::NestedPolygons:
                        EXPECT_LE(s.max_degree, 2u);
                        EXPECT_GE(s.bounded_faces, 1u);
                        some = some || s.depth >= 3;
                        other = other || s.longest_cycle >= n / 2;
                        third = third || s.isolated_in_bounded > 0;
                        break;
                    case Family::Tree:
                        EXPECT_EQ(s.bounded_faces, 0u);
                        EXPECT_EQ(s.edges + s.components, n);  // a forest
                        EXPECT_GE(s.leaves, n / 10);
                        some = some || s.longest_cycle == 2 * (n - 1);  // a spanning tree
                        other = other || s.components > 1;
                        break;
                    case Family::Comb:
                        EXPECT_EQ(s.edges, n - 1);
                        EXPECT_EQ(s.components, 1u);
                        EXPECT_EQ(s.longest_cycle, 2 * (n - 1));
                        EXPECT_LE(s.max_degree, 4u);
                        EXPECT_GE(s.leaves, n / 10);
                        some = other = third = true;
                        break;
                    case Family::Star:
                        EXPECT_EQ(s.max_degree, n - 1);
                        some = some || s.bounded_faces > 0;  // a rim
                        other = other || s.bounded_faces == 0;
                        break;
                    case Family::CollinearChain:
                        EXPECT_GE(s.most_collinear, 2 * n / 3);
                        some = some || s.longest_cycle >= n;  // no gaps: the line and its branches in one piece
                        other = other || s.components > 1;    // gaps
                        break;
                    case Family::Components:
                        EXPECT_GE(s.components, n / 5);
                        EXPECT_LE(s.max_degree, 2u);
                        some = some || s.isolated_in_bounded > 0;
                        other = other || s.triangles > 0;
                        break;
                    case Family::NearDegenerate:
                        some = some || s.max_degree >= n / 2;  // a thin fan (or a star)
                        break;
                }
            }
            const bool needs_other = f == Family::RandomSegments || f == Family::Triangulation ||
                                     f == Family::NestedPolygons || f == Family::Tree || f == Family::Star ||
                                     f == Family::CollinearChain || f == Family::Components;
            EXPECT_TRUE(some) << family_name(f) << " n=" << n;
            if (needs_other) {
                EXPECT_TRUE(other) << family_name(f) << " n=" << n;
            }
            if (f == Family::NestedPolygons) {
                EXPECT_TRUE(third) << family_name(f) << " n=" << n;
            }
        }
    }
}

TEST(Families, NearDegenerateCoordinates) {
    std::size_t fractional = 0, negative_zero = 0, big_offsets = 0, subnormal = 0;
    for (const std::size_t n : {10, 100, 1000}) {
        for (std::uint64_t seed = 0; seed < 20; ++seed) {
            for (const Point& p : generate({Family::NearDegenerate, seed, n}).vertices) {
                for (const double v : {p.x, p.y}) {
                    fractional += std::trunc(v) != v;
                    negative_zero += v == 0 && std::signbit(v);
                    big_offsets += std::fabs(v) >= 1e15;
                    subnormal += v != 0 && std::fabs(v) < DBL_MIN;
                }
            }
        }
    }
    EXPECT_GT(fractional, 0u);
    EXPECT_GT(negative_zero, 0u);
    EXPECT_GT(big_offsets, 0u);
    EXPECT_GT(subnormal, 0u);
}

// 1e5 vertices per family: exact size and build() accepts. A family that
// went quadratic again would take hours here and hit the ctest timeout.
TEST(Families, HundredThousandVertices) {
    for (const Family f : all_families()) {
        const PlanarGraph g = generate({f, 1, 100000});
        EXPECT_EQ(g.vertices.size(), 100000u) << family_name(f);
        EXPECT_NO_THROW((void)build(g)) << family_name(f);
    }
}

// GraphBuilder's grid against brute force: every point and edge it is
// offered, accepted exactly when the graph with it added is valid. Small
// lattices make collinear runs, touches and overlaps common; cell sides from
// 1 (edges spanning many cells) to 1000 (one cell); half-integer points are
// not filed and take the brute-force path.
TEST(GraphBuilder, DecidesAsBruteForce) {
    Rng rng(7);
    for (const std::int64_t cell : {1, 2, 3, 8, 1000}) {
        for (int round = 0; round < 6; ++round) {
            GraphBuilder b(cell);
            const std::int64_t side = rng.between(4, 24);
            std::size_t accepted = 0, refused = 0;
            for (int step = 0; step < 300; ++step) {
                PlanarGraph with = b.graph();
                if (rng.chance(1, 3) || b.num_vertices() < 2) {
                    Point p{static_cast<double>(rng.between(-side, side)), static_cast<double>(rng.between(-side, side))};
                    if (rng.chance(1, 10)) p.x += 0.5;
                    with.vertices.push_back(p);
                    const bool valid = !find_problem(with).has_value();
                    EXPECT_EQ(b.add_point(p).has_value(), valid) << "point (" << p.x << ", " << p.y << ")";
                    (valid ? accepted : refused) += 1;
                } else {
                    const VertexId u(static_cast<Index>(rng.below(b.num_vertices())));
                    const VertexId v(static_cast<Index>(rng.below(b.num_vertices())));
                    with.edges.push_back({u, v});
                    const bool valid = !find_problem(with).has_value();
                    EXPECT_EQ(b.add_edge(u, v), valid) << "edge " << u.str() << "-" << v.str();
                    (valid ? accepted : refused) += 1;
                }
            }
            EXPECT_EQ(find_problem(b.graph()), std::nullopt);
            EXPECT_GT(accepted, 20u);
            EXPECT_GT(refused, 20u);
        }
    }
}

TEST(GraphBuilder, RefusedSegmentLeavesNoVertexBehind) {
    GraphBuilder b(2);
    ASSERT_TRUE(b.add_segment({0, 0}, {10, 0}));
    EXPECT_FALSE(b.add_segment({5, -5}, {5, 5}));  // crosses: neither end stays
    EXPECT_EQ(b.num_vertices(), 2u);
    EXPECT_FALSE(b.find({5, -5}).has_value());
    EXPECT_TRUE(b.add_segment({5, -5}, {5, -1}));   // the freed points are usable again
    EXPECT_FALSE(b.add_segment({0, 0}, {10, 0}));   // the same segment twice
    EXPECT_FALSE(b.add_point({4, 0}).has_value());  // on an edge
    EXPECT_EQ(b.find({-0.0, 0}), VertexId(0));      // -0.0 is 0.0
    EXPECT_EQ(find_problem(b.graph()), std::nullopt);
}

}  // namespace
}  // namespace dcel::gen
