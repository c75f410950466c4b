// The oracles themselves (tests/oracles/), against answers derived by hand
// and against a second route to the same answer: the 128-bit fast path of
// the exact arithmetic against its GMP path, the bounding-box pair search of
// the brute force against all pairs, the reference DCEL against faces worked
// out on paper.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <random>
#include <vector>

#include "dcel/build.hpp"
#include "dcel/dump.hpp"
#include "oracles/brute_force.hpp"
#include "oracles/dump_judge.hpp"
#include "oracles/exact.hpp"
#include "oracles/reference_dcel.hpp"
#include "oracles/shapes.hpp"

namespace dcel::oracle {
namespace {

// The cross product straight from the definition, in rationals.
int rational_cross(Point p1, Point q1, Point p2, Point q2) {
    const Rational d = (exact(q1.x) - exact(p1.x)) * (exact(q2.y) - exact(p2.y)) -
                       (exact(q1.y) - exact(p1.y)) * (exact(q2.x) - exact(p2.x));
    return d.sign();
}

// Small integers, one-ulp steps at 1e15, and values whose exponents lie far
// apart (subnormals, DBL_MAX), so both paths of the exact arithmetic run.
double spread_double(std::mt19937_64& rng, int kind) {
    const double small = static_cast<double>(static_cast<int>(rng() % 9) - 4);
    switch (kind) {
        case 0: return small;
        case 1: return 1e15 + small * 0.125;
        case 2: return small * 0x1p-1074;
        case 3: return small * (DBL_MAX / 4);
        case 4: return std::ldexp(small + 0.5, static_cast<int>(rng() % 200) - 100);
        case 5: return (rng() & 1U) != 0 ? -0.0 : 0.0;
        case 6: return small * 0x1p60;  // beside the next kind: spreads of about 90 bits
        default: return 0.5 + small * 0x1p-30;
    }
}

TEST(ExactOracle, CrossSignAgreesWithRationalsOnBothPaths) {
    std::mt19937_64 rng(41);
    int zeros = 0;
    for (int i = 0; i < 20000; ++i) {
        // Half the cases draw every coordinate from one kind (mostly the
        // 64-bit path), half mix kinds (the 128-bit and GMP paths).
        const int shared = static_cast<int>(rng() % 8);
        auto draw = [&] { return spread_double(rng, i % 2 == 0 ? shared : static_cast<int>(rng() % 8)); };
        Point p[4];
        for (Point& x : p) x = {draw(), draw()};
        const int want = rational_cross(p[0], p[1], p[2], p[3]);
        zeros += want == 0;
        ASSERT_EQ(cross_sign(p[0], p[1], p[2], p[3]), want) << i;
    }
    EXPECT_GT(zeros, 500);
}

TEST(ExactOracle, PointSetsAgreeWithPointByPoint) {
    // Point sets of one kind (stored as integers) and of mixed kinds (the
    // per-call route): orientation, angle order and meeting by index must be
    // the free functions' answers.
    std::mt19937_64 rng(43);
    for (int round = 0; round < 400; ++round) {
        const int kind = static_cast<int>(rng() % 8);
        std::vector<Point> pts(8);
        for (Point& p : pts) {
            const int k = round % 2 == 0 ? kind : static_cast<int>(rng() % 8);
            p = {spread_double(rng, k), spread_double(rng, k)};
        }
        const ExactPoints set(pts);
        for (int t = 0; t < 50; ++t) {
            const auto a = static_cast<Index>(rng() % 8), b = static_cast<Index>(rng() % 8);
            const auto c = static_cast<Index>(rng() % 8), d = static_cast<Index>(rng() % 8);
            ASSERT_EQ(set.orientation(a, b, c), orientation(pts[a], pts[b], pts[c])) << round;
            ASSERT_EQ(set.strictly_on_segment(a, b, c), strictly_on_segment(pts[a], pts[b], pts[c])) << round;
            if (!(pts[a] == pts[b]) && !(pts[a] == pts[c])) {
                ASSERT_EQ(set.angle_order(a, b, c), angle_order(pts[a], pts[b], pts[c])) << round;
            }
            if (!(pts[a] == pts[b]) && !(pts[c] == pts[d])) {
                ASSERT_EQ(set.meeting(a, b, c, d), meeting(pts[a], pts[b], pts[c], pts[d])) << round;
            }
        }
    }
}

TEST(ExactOracle, HandCheckedSigns) {
    EXPECT_EQ(orientation({0, 0}, {1, 0}, {0, 1}), 1);
    EXPECT_EQ(orientation({0, 0}, {0, 1}, {1, 0}), -1);
    EXPECT_EQ(orientation({1e15, 1e15}, {1e15 + 1, 1e15 + 1}, {1e15 + 2, 1e15 + 2}), 0);
    EXPECT_EQ(orientation({1e15, 1e15}, {1e15 + 1, 1e15 + 1}, {1e15 + 2, 1e15 + 3}), 1);
    // 2^-1074 against 2^1000: 2074 bits apart, the GMP path.
    EXPECT_EQ(orientation({0, 0}, {0x1p-1074, 0}, {0x1p1000, 0x1p-1074}), 1);
    EXPECT_EQ(orientation({-DBL_MAX, -DBL_MAX}, {DBL_MAX, DBL_MAX}, {0, 0x1p-1074}), 1);
    // At the edges of the paths: 62 bits (differences of 63) and one more,
    // 125 bits (differences of 126) and one more.
    for (const double big : {0x1.fffffffffffffp61, 0x1.fffffffffffffp62, 0x1.fffffffffffffp124, 0x1.fffffffffffffp125}) {
        // (2 big, 0) x (0, 1): positive, though 2 big wraps to a negative
        // 64-bit integer past the edge.
        EXPECT_EQ(cross_sign({-big, 0}, {big, 0}, {0, 0}, {0, 1}), 1) << big;
        EXPECT_EQ(cross_sign({0, 0}, {0, 1}, {-big, 0}, {big, 0}), -1) << big;
    }
    // Angular order: east, north, west, south, and just below east last.
    const std::vector<Point> ccw = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
    for (std::size_t i = 0; i < ccw.size(); ++i) {
        for (std::size_t j = 0; j < ccw.size(); ++j) {
            EXPECT_EQ(angle_order({0, 0}, ccw[i], ccw[j]), i < j ? -1 : (i > j ? 1 : 0)) << i << " " << j;
        }
    }
    EXPECT_EQ(angle_order({0, 0}, {-0.0, 1}, {0.0, 2}), 0);
}

TEST(ExactOracle, AreasOnBothPathsAndNearestDoubles) {
    // A unit square at the origin, and the same square far away and tiny.
    EXPECT_EQ(twice_area({{0, 0}, {1, 0}, {1, 1}, {0, 1}}), 2);
    EXPECT_EQ(twice_area({{0, 0}, {0, 1}, {1, 1}, {1, 0}}), -2);
    const double o = 0x1p52, e = 0x1p-60;  // 53 bits, and 112 bits apart: the GMP path
    EXPECT_EQ(twice_area({{o, o}, {o + 1, o}, {o + 1, o + 1}, {o, o + 1}}), 2);
    EXPECT_EQ(twice_area({{0, 0}, {e, 0}, {e, e}, {0, e}}), 2 * exact(e) * exact(e));
    EXPECT_EQ(twice_area({{0, 0}, {o, 0}, {o, e}, {0, e}}), 2 * exact(o) * exact(e));
    // Many large terms of one sign: a square of half-diagonal X just below
    // 2^60 walked round 100 times, and the point (1, 1), so that the
    // coordinates span 60 bits. The terms are about X^2 and their sum is
    // above 2^128: on the 128-bit path it would overflow.
    const double x = 0x1.fffffffffffffp59;
    std::vector<Point> wound;
    for (int i = 0; i < 100; ++i) wound.insert(wound.end(), {{x, 0}, {0, x}, {-x, 0}, {0, -x}});
    wound.push_back({1, 1});
    Rational shoelace = 0;
    for (std::size_t i = 0; i < wound.size(); ++i) {
        const Point a = wound[i], b = wound[(i + 1) % wound.size()];
        shoelace += exact(a.x) * exact(b.y) - exact(a.y) * exact(b.x);
    }
    EXPECT_GT(shoelace, Rational(BigInt(1) << 128U));
    EXPECT_EQ(twice_area(wound), shoelace);
    EXPECT_TRUE(is_nearest_double(0.1, Rational(1, 10)));
    EXPECT_FALSE(is_nearest_double(std::nextafter(0.1, 1.0), Rational(1, 10)));
    const Rational half_least = exact(0x1p-1074) / 2;
    EXPECT_TRUE(is_nearest_double(0x1p-1074, half_least + exact(0x1p-1074) * exact(0x1p-30)));  // above half: up
    EXPECT_TRUE(is_nearest_double(0.0, half_least));                                            // a tie: to even, 0
    EXPECT_FALSE(is_nearest_double(0x1p-1074, half_least));
    EXPECT_TRUE(is_nearest_double(INFINITY, exact(DBL_MAX) * 2));
}

TEST(ExactOracle, SegmentsMeetingAndWinding) {
    EXPECT_EQ(meeting({0, 0}, {2, 2}, {0, 2}, {2, 0}), Meeting::Crossing);
    EXPECT_EQ(meeting({0, 0}, {2, 0}, {1, 0}, {1, 5}), Meeting::Touch);
    EXPECT_EQ(meeting({0, 0}, {2, 0}, {1, 0}, {3, 0}), Meeting::Overlap);
    EXPECT_EQ(meeting({0, 0}, {2, 0}, {2, 0}, {3, 0}), Meeting::SharedEndpoint);
    EXPECT_EQ(meeting({0, 0}, {2, 0}, {2, 0}, {0, 0}), Meeting::Same);
    EXPECT_EQ(meeting({0, 0}, {2, 0}, {3, 0}, {4, 0}), Meeting::None);
    const std::vector<Point> square = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
    EXPECT_EQ(winding_number({1, 1}, square), 1);
    EXPECT_EQ(winding_number({5, 1}, square), 0);
    EXPECT_EQ(winding_number({1, 1}, {{0, 0}, {0, 4}, {4, 4}, {4, 0}}), -1);
    // A square with a dangling edge walked out and back.
    EXPECT_EQ(winding_number({1, 1}, {{0, 0}, {4, 0}, {6, 2}, {4, 0}, {4, 4}, {0, 4}}), 1);
    EXPECT_EQ(parameter_of_point({0, 0}, {4, 0}, {1, 0}), Rational(1, 4));
    EXPECT_EQ(parameter_of_crossing({0, 0}, {4, 0}, {3, -1}, {3, 1}), Rational(3, 4));
}

// Random segments on a tiny grid, with duplicate points, duplicate edges,
// self-loops, bad indexes and non-finite coordinates mixed in.
PlanarGraph raw_graph(std::mt19937_64& rng) {
    PlanarGraph g;
    const int side = 2 + static_cast<int>(rng() % 5);
    const int n = 2 + static_cast<int>(rng() % 14);
    for (int i = 0; i < n; ++i) {
        g.vertices.push_back({static_cast<double>(rng() % side), static_cast<double>(rng() % side)});
        if (rng() % 40 == 0) g.vertices.back().x = NAN;
    }
    const int m = static_cast<int>(rng() % 16);
    for (int k = 0; k < m; ++k) {
        const auto u = static_cast<Index>(rng() % (n + (rng() % 30 == 0 ? 2 : 0)));
        const auto v = static_cast<Index>(rng() % n);
        g.edges.push_back({VertexId(u), VertexId(v)});
    }
    return g;
}

TEST(BruteForceOracle, BoundingBoxSearchFindsWhatAllPairsFind) {
    std::mt19937_64 rng(42);
    DefectKinds all;
    for (int i = 0; i < 5000; ++i) {
        const PlanarGraph g = raw_graph(rng);
        const Defects every = find_defects(g, PairSearch::AllPairs);
        ASSERT_EQ(find_defects(g, PairSearch::BoundingBoxes), every) << i;
        all |= every.kinds();
    }
    EXPECT_EQ(all.count(), static_cast<std::size_t>(Defect::Count));  // every kind occurred
}

TEST(BruteForceOracle, HandCheckedDefects) {
    const PlanarGraph g{{{0, 0}, {4, 4}, {0, 4}, {4, 0}, {2, 0}, {0, 0}},
                        {{VertexId(0), VertexId(1)},
                         {VertexId(2), VertexId(3)},
                         {VertexId(0), VertexId(3)},
                         {VertexId(1), VertexId(0)},
                         {VertexId(4), VertexId(4)}}};
    const Defects d = find_defects(g);
    EXPECT_EQ(d.duplicate_points, (std::vector<std::pair<Index, Index>>{{0, 5}}));
    EXPECT_EQ(d.duplicate_edges, (std::vector<std::pair<Index, Index>>{{0, 3}}));
    EXPECT_EQ(d.self_loops, std::vector<Index>{4});
    EXPECT_EQ(d.vertex_in_edge, (std::vector<std::pair<Index, Index>>{{4, 2}}));
    // 0-1 crosses 2-3 at (2, 2); 0-1 and 1-0 are the same segment.
    EXPECT_EQ(d.edge_pairs,
              (std::vector<Defects::EdgePair>{{0, 1, Meeting::Crossing}, {0, 3, Meeting::Same}, {1, 3, Meeting::Crossing}}));
    EXPECT_EQ(describe(d.kinds()), "duplicate-point self-loop duplicate-edge crossing touch overlap");
}

PlanarGraph graph(std::vector<Point> points, std::vector<std::pair<Index, Index>> edges) {
    PlanarGraph g;
    g.vertices = std::move(points);
    for (const auto& [u, v] : edges) g.edges.push_back({VertexId(u), VertexId(v)});
    return g;
}

TEST(ReferenceDcel, FacesWorkedOutByHand) {
    // A square 0-3 with a triangle 4-6 inside it, an isolated vertex 7 inside
    // the square, and an isolated vertex 8 outside. By hand: the square's
    // inside (0 1 2 3 counterclockwise) holds the triangle's outside (4 6 5,
    // clockwise) and vertex 7; the triangle's inside is a face of its own;
    // the unbounded face holds the square's outside and vertex 8.
    const PlanarGraph g = graph({{0, 0}, {10, 0}, {10, 10}, {0, 10}, {2, 2}, {4, 2}, {2, 4}, {8, 8}, {20, 20}},
                                {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 4}});
    const std::vector<FaceShape> want = sorted_shapes({
        {{}, {{0, 3, 2, 1}}, {8}},
        {{0, 1, 2, 3}, {{4, 6, 5}}, {7}},
        {{4, 5, 6}, {}, {}},
    });
    EXPECT_EQ(reference_faces(g), want);
    // A square with the diagonal 0-2 (degree 3 at both ends): two
    // counterclockwise triangles inside, the clockwise square outside.
    EXPECT_EQ(reference_faces(graph({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}})),
              sorted_shapes({{{}, {{0, 3, 2, 1}}, {}}, {{0, 1, 2}, {}, {}}, {{0, 2, 3}, {}, {}}}));
    // A path 0-1-2 is one cycle walked there and back: 0 1 2 1.
    EXPECT_EQ(reference_faces(graph({{0, 0}, {1, 0}, {2, 1}}, {{0, 1}, {1, 2}})), sorted_shapes({{{}, {{0, 1, 2, 1}}, {}}}));
}

TEST(ReferenceDcel, AgreesWithBuildOnNestedSquares) {
    // Squares of side 2k around the origin, each a hole in the next.
    PlanarGraph g;
    for (Index k = 1; k <= 4; ++k) {
        const auto s = static_cast<double>(k);
        const auto b = static_cast<Index>(g.vertices.size());
        g.vertices.insert(g.vertices.end(), {{-s, -s}, {s, -s}, {s, s}, {-s, s}});
        for (Index i = 0; i < 4; ++i) g.edges.push_back({VertexId(b + i), VertexId(b + (i + 1) % 4)});
    }
    const ReferenceDcel r = reference_dcel(g);
    EXPECT_EQ(r.outer_cycle.size(), 5U);  // four squares' insides and the unbounded face
    for (Index f = 1; f < r.outer_cycle.size(); ++f) EXPECT_LE(r.inner[f].size(), 1U);
    EXPECT_TRUE(judge_dump(to_dump(build(g))).valid);
}

TEST(DumpJudge, RejectsASwappedNext) {
    const PlanarGraph g = graph({{0, 0}, {4, 0}, {0, 4}}, {{0, 1}, {1, 2}, {2, 0}});
    DcelDump d = to_dump(build(g));
    ASSERT_TRUE(judge_dump(d).valid);
    std::swap(d.half_edges[0].next, d.half_edges[2].next);
    EXPECT_FALSE(judge_dump(d).valid);
}

TEST(Shapes, CanonicalRotationStartsAtTheBestVisitOfTheSmallestVertex) {
    EXPECT_EQ(canonical({3, 1, 2}), (Cycle{1, 2, 3}));
    EXPECT_EQ(canonical({1, 5, 1, 2}), (Cycle{1, 2, 1, 5}));
    EXPECT_EQ(canonical({}), Cycle{});
}

}  // namespace
}  // namespace dcel::oracle
