// The pieces build() is made of, each against a plain reference: the lex
// order against std::sort with lex_less, the ring sort against the angular
// order of the exact oracle (oracles/exact.hpp, no rounding), the skip-list
// status against a std::vector.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <random>
#include <vector>

#include "dcel/build/huge_pages.hpp"
#include "dcel/build/lex_order.hpp"
#include "dcel/build/ring_sort.hpp"
#include "dcel/build/status_list.hpp"
#include "dcel/error.hpp"
#include "oracles/exact.hpp"

namespace dcel {

// From the internals of the core (dcel::detail).
using detail::advise_huge_pages;
using detail::first_same_direction;
using detail::lex_order_checked;
using detail::LexOrder;
using detail::reserve_huge;
using detail::RingEntry;
using detail::sort_ring;
using detail::StatusList;
namespace {

// Doubles that stress exact code: small integers, near-equal large values,
// subnormals, signed zeros, values near the double limit.
double nasty_double(std::mt19937_64& rng) {
    std::uniform_int_distribution<int> kind(0, 7);
    std::uniform_int_distribution<int> small(-4, 4);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    switch (kind(rng)) {
        case 0: return small(rng);
        case 1: return 1e15 + small(rng);
        case 2: return small(rng) * 0x1p-1074;
        case 3: return unit(rng) < 0 ? -0.0 : 0.0;
        case 4: return std::ldexp(unit(rng), 1023);
        case 5: return std::ldexp(unit(rng), std::uniform_int_distribution<int>(-1074, 1023)(rng));
        case 6: return unit(rng);
        default: return small(rng) * (DBL_MAX / 4);
    }
}

// ---- Lex order

std::vector<VertexId> reference_order(const std::vector<Point>& pts) {
    std::vector<VertexId> order;
    for (Index v = 0; v < pts.size(); ++v) order.emplace_back(v);
    std::sort(order.begin(), order.end(), [&](VertexId a, VertexId b) {
        if (lex_less(pts[a.index()], pts[b.index()])) return true;
        if (lex_less(pts[b.index()], pts[a.index()])) return false;
        return a < b;
    });
    return order;
}

void expect_lex_order_matches(const std::vector<Point>& pts) {
    const std::vector<VertexId> expected = reference_order(pts);
    std::vector<VertexId> dup;  // the first adjacent pair at one point, if any
    for (std::size_t i = 1; i < expected.size() && dup.empty(); ++i) {
        if (pts[expected[i - 1].index()] == pts[expected[i].index()]) dup = {expected[i - 1], expected[i]};
    }
    try {
        const LexOrder got = lex_order_checked(pts);
        ASSERT_TRUE(dup.empty()) << "accepted a duplicate point";
        ASSERT_EQ(got.vertex_of_rank, expected);
        for (Index r = 0; r < pts.size(); ++r) {
            EXPECT_EQ(got.rank_of_vertex[got.vertex_of_rank[r].index()], r);
            EXPECT_EQ(got.point_of_rank[r], pts[got.vertex_of_rank[r].index()]) << "rank " << r;
        }
    } catch (const InvalidInput& e) {
        ASSERT_FALSE(dup.empty()) << e.what();
        EXPECT_EQ(e.kind(), InputErrorKind::DuplicatePoint);
        EXPECT_EQ(e.vertices(), dup);
    }
}

TEST(LexOrder, MatchesStdSortOnNastyCoordinates) {
    std::mt19937_64 rng(7);
    for (int round = 0; round < 300; ++round) {
        std::vector<Point> pts(std::uniform_int_distribution<int>(0, 200)(rng));
        for (Point& p : pts) p = {nasty_double(rng), nasty_double(rng)};
        expect_lex_order_matches(pts);
    }
}

TEST(LexOrder, MatchesStdSortOnSpreadAndClusteredPoints) {
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int round = 0; round < 50; ++round) {
        std::vector<Point> pts;
        for (int i = 0; i < 3000; ++i) {
            // Most spread out, some in one narrow column, a few far away.
            const int k = i % 10;
            const double x = k < 7 ? unit(rng) * 1000 : (k < 9 ? 500 + unit(rng) * 1e-9 : unit(rng) * 1e300);
            pts.push_back({x, std::floor(unit(rng) * 50)});
        }
        expect_lex_order_matches(pts);
    }
}

TEST(LexOrder, InputAlreadyInOrderAndAlmostInOrder) {
    // Strictly increasing input takes a shortcut (the identity), and so
    // does a large bucket already in order; one step that is not strictly
    // increasing (an equal point, -0.0 next to 0.0, or one pair swapped)
    // must not.
    std::vector<Point> pts;
    for (int i = 0; i < 100; ++i) pts.push_back({static_cast<double>(i / 3), static_cast<double>(i % 3)});
    expect_lex_order_matches(pts);
    for (const std::size_t k : {std::size_t{1}, std::size_t{50}, std::size_t{99}}) {
        std::vector<Point> dup = pts;
        dup[k] = dup[k - 1];
        expect_lex_order_matches(dup);
        std::vector<Point> swapped = pts;
        std::swap(swapped[k], swapped[k - 1]);
        expect_lex_order_matches(swapped);
    }
    // A row-major grid: every column is a bucket of the x pass that is
    // already in order; then one column with an equal point, and one with
    // a swapped pair, and one column written with -0.0 and 0.0 mixed.
    std::vector<Point> grid;
    for (int y = 0; y < 40; ++y) {
        for (int x = 0; x < 40; ++x) grid.push_back({static_cast<double>(x), static_cast<double>(y)});
    }
    expect_lex_order_matches(grid);
    for (const std::size_t k : {std::size_t{40 * 20 + 7}, std::size_t{40 * 39 + 39}}) {
        std::vector<Point> dup = grid;
        dup[k] = dup[k - 40];
        expect_lex_order_matches(dup);
        std::vector<Point> swapped = grid;
        std::swap(swapped[k], swapped[k - 40]);
        expect_lex_order_matches(swapped);
    }
    std::vector<Point> zeros = grid;
    for (std::size_t k = 0; k < zeros.size(); k += 80) zeros[k].x = -0.0;
    expect_lex_order_matches(zeros);
    expect_lex_order_matches({{-1, 0}, {-0.0, 0}, {0.0, 0}, {1, 0}});
    expect_lex_order_matches({{-1, 0}, {0.0, -1}, {-0.0, 0}, {1, 0}});
    expect_lex_order_matches({{5, 5}});
}

TEST(LexOrder, AllOnOneVerticalLineAndSignedZeros) {
    std::vector<Point> pts;
    for (int i = 0; i < 1000; ++i) pts.push_back({0.0, static_cast<double>((i * 7919) % 1000)});
    expect_lex_order_matches(pts);
    expect_lex_order_matches({{-0.0, 1}, {0.0, 0}, {-0.0, -1}});
    expect_lex_order_matches({{-0.0, 1}, {0.0, 1}});  // one point: a duplicate
    expect_lex_order_matches({{-DBL_MAX, 0}, {DBL_MAX, 0}, {0x1p-1074, 0}, {-0x1p-1074, 0}, {0, 0}});
}

// ---- Ring sort

// Angular order from east, counterclockwise, exact; ties by id.
bool oracle_before(Point c, const RingEntry& a, const RingEntry& b) {
    const int order = oracle::angle_order(c, a.target, b.target);
    return order != 0 ? order < 0 : a.half_edge < b.half_edge;
}

void expect_ring_sorted(Point c, std::vector<RingEntry> ring) {
    std::vector<RingEntry> expected = ring;
    std::sort(expected.begin(), expected.end(),
              [&](const RingEntry& a, const RingEntry& b) { return oracle_before(c, a, b); });
    const std::size_t reported = sort_ring(c, ring);
    ASSERT_EQ(ring.size(), expected.size());
    for (std::size_t i = 0; i < ring.size(); ++i) EXPECT_EQ(ring[i].half_edge, expected[i].half_edge) << i;
    std::size_t same = ring.size();
    for (std::size_t i = 0; i + 1 < ring.size() && same == ring.size(); ++i) {
        if (oracle::angle_order(c, ring[i].target, ring[i + 1].target) == 0) same = i;
    }
    EXPECT_EQ(first_same_direction(c, ring), same);
    EXPECT_EQ(reported, same);
}

TEST(RingSort, MatchesRationalAngularOrder) {
    std::mt19937_64 rng(9);
    for (int round = 0; round < 2000; ++round) {
        const Point c{nasty_double(rng), nasty_double(rng)};
        std::vector<RingEntry> ring;
        const int degree = std::uniform_int_distribution<int>(0, round % 10 == 0 ? 60 : 8)(rng);
        for (int i = 0; i < degree; ++i) {
            Point t{nasty_double(rng), nasty_double(rng)};
            if (t == c) continue;
            ring.push_back({t, HalfEdgeId(static_cast<Index>(i)), 0, 0});
        }
        expect_ring_sorted(c, ring);
    }
}

TEST(RingSort, DirectionsAtan2CannotTellApartAndRepeatedDirections) {
    // (1e15, 1e15+1) and (1e15+1, 1e15+2) from the origin differ by ~5e-31 rad.
    const double o = 1e15;
    expect_ring_sorted({0, 0}, {{{o + 1, o + 2}, HalfEdgeId(0), 0, 0},
                                {{o, o + 1}, HalfEdgeId(1), 0, 0},
                                {{-o, -o - 1}, HalfEdgeId(2), 0, 0},
                                {{2 * o, 2 * o + 2}, HalfEdgeId(3), 0, 0},  // same way as h1
                                {{1, 0}, HalfEdgeId(4), 0, 0},
                                {{0, -1}, HalfEdgeId(5), 0, 0}});
    // Every axis direction and the diagonals, twice over, from a subnormal centre.
    std::vector<RingEntry> ring;
    Index id = 0;
    for (int k = 1; k <= 2; ++k) {
        for (int dx = -1; dx <= 1; ++dx) {
            for (int dy = -1; dy <= 1; ++dy) {
                if (dx != 0 || dy != 0) ring.push_back({{dx * k * 0x1p-1070, dy * k * 0x1p-1070}, HalfEdgeId(id++), 0, 0});
            }
        }
    }
    std::shuffle(ring.begin(), ring.end(), std::mt19937_64(3));
    expect_ring_sorted({0x1p-1074, 0}, ring);
    expect_ring_sorted({0, 0}, ring);
}

TEST(RingSort, SmallRingsWhereTheFloatingPointGuessIsWrong) {
    // Directions ~1e-31 rad apart: the guessed angles tie or come out
    // swapped, so the exact check must catch them.
    std::mt19937_64 rng(11);
    const double o = 1e15;
    for (int round = 0; round < 500; ++round) {
        std::vector<RingEntry> ring;
        for (Index i = 0; i < 8; ++i) {
            const double k = std::uniform_int_distribution<int>(0, 3)(rng);
            const double sx = (rng() & 1U) != 0 ? 1 : -1;
            const double sy = (rng() & 1U) != 0 ? 1 : -1;
            ring.push_back({{sx * (o + k), sy * (o + k + 1)}, HalfEdgeId(i), 0, 0});
        }
        expect_ring_sorted({0, 0}, ring);
    }
}

TEST(RingSort, RingsOfTwoInEveryArrangement) {
    // Degree 2 has its own path: both orders of the input, same and
    // different quadrants, the same direction (either id first), opposite
    // directions, and pairs ~1e-31 rad apart, from nasty centres too.
    std::mt19937_64 rng(12);
    const double o = 1e15;
    const std::vector<std::pair<Point, Point>> fixed = {{{1, 0}, {0, 1}},
                                                        {{1, 1}, {2, 2}},
                                                        {{-1, -1}, {-3, -3}},
                                                        {{1, 0}, {-1, 0}},
                                                        {{0, 1}, {0, -1}},
                                                        {{o, o + 1}, {o + 1, o + 2}},
                                                        {{-o, -o - 1}, {-o - 1, -o - 2}},
                                                        {{1, -1}, {2, -1}},
                                                        {{0, -1}, {0, -2}},
                                                        {{-1, 0}, {-2, 0}},
                                                        {{2, 1}, {1, 2}}};
    for (const auto& [a, b] : fixed) {
        for (const bool swap_ids : {false, true}) {
            const HalfEdgeId ia(swap_ids ? 1 : 0);
            const HalfEdgeId ib(swap_ids ? 0 : 1);
            expect_ring_sorted({0, 0}, {{a, ia, 0, 0}, {b, ib, 0, 0}});
            expect_ring_sorted({0, 0}, {{b, ib, 0, 0}, {a, ia, 0, 0}});
        }
    }
    for (int round = 0; round < 3000; ++round) {
        const Point c{nasty_double(rng), nasty_double(rng)};
        const Point a{nasty_double(rng), nasty_double(rng)};
        Point b = round % 3 == 0 ? Point{c.x + 2 * (a.x - c.x), c.y + 2 * (a.y - c.y)}  // often the same way
                                 : Point{nasty_double(rng), nasty_double(rng)};
        if (!std::isfinite(b.x) || !std::isfinite(b.y)) b = Point{nasty_double(rng), nasty_double(rng)};
        if (a == c || b == c) continue;
        expect_ring_sorted(c, {{a, HalfEdgeId(static_cast<Index>(round % 2)), 0, 0},
                               {b, HalfEdgeId(static_cast<Index>(1 - round % 2)), 0, 0}});
    }
}

// ---- Status list

TEST(StatusList, AgreesWithAVectorUnderRandomEdits) {
    std::mt19937_64 rng(10);
    for (const Index capacity : {1U, 7U, 100U, 3000U}) {
        StatusList list(capacity);
        const int phase = 4 * static_cast<int>(capacity) + 50;
        std::vector<Index> ref;  // bottom to top
        std::vector<Index> erased;
        std::size_t most = 0;  // the most nodes in the list at once
        for (int step = 0; step < 20000; ++step) {
            // Grow to the capacity, shrink, grow again: ids must be reused.
            const bool grow = (step / phase) % 2 == 0;
            const bool insert = ref.empty() || (ref.size() < capacity && (rng() % 4 != 0) == grow);
            if (!insert) {
                const std::size_t pos = std::uniform_int_distribution<std::size_t>(0, ref.size() - 1)(rng);
                const Index node = ref[pos];
                ASSERT_TRUE(list.contains(node));
                list.erase(node);
                ASSERT_FALSE(list.contains(node));
                ref.erase(ref.begin() + static_cast<std::ptrdiff_t>(pos));
                erased.push_back(node);
            } else {
                // Above a random member, or at the bottom.
                const std::size_t pos = std::uniform_int_distribution<std::size_t>(0, ref.size())(rng);
                const Index below = pos == 0 ? StatusList::kNone : ref[pos - 1];
                const Index node = list.insert_above(below);
                ASSERT_NE(node, StatusList::kNone);
                ASSERT_EQ(std::find(ref.begin(), ref.end(), node), ref.end()) << "id " << node << " handed out twice";
                if (!erased.empty()) {
                    ASSERT_EQ(node, erased.back()) << "the last erased id is reused first";
                    erased.pop_back();
                }
                ref.insert(ref.begin() + static_cast<std::ptrdiff_t>(pos), node);
                most = std::max(most, ref.size());
            }
            ASSERT_EQ(list.ids_made(), most) << "ids are made only when none is free";
            if (step % 97 != 0) continue;
            // Walk both ways, and search every partition point.
            std::vector<Index> up;
            for (Index x = list.first(); x != StatusList::kNone; x = list.next(x)) up.push_back(x);
            ASSERT_EQ(up, ref);
            std::vector<Index> down;
            for (Index x = list.last(); x != StatusList::kNone; x = list.prev(x)) down.push_back(x);
            std::reverse(down.begin(), down.end());
            ASSERT_EQ(down, ref);
            std::vector<char> is_below(list.ids_made() + std::size_t{1}, 0);
            for (std::size_t k = 0; k <= ref.size(); ++k) {
                if (k > 0) is_below[ref[k - 1]] = 1;  // the first k nodes are below
                const Index found = list.first_not_below([&](Index x) { return is_below[x] != 0; });
                ASSERT_EQ(found, k < ref.size() ? ref[k] : StatusList::kNone);
            }
        }
        EXPECT_EQ(list.ids_made(), capacity) << "the list filled up at least once";
    }
}

}  // namespace
}  // namespace dcel

namespace dcel {
namespace {

// The huge-page hint changes nothing a program can see: contents and sizes
// stay as they are, for arrays smaller than a huge page, spanning several,
// or not allocated at all.
TEST(HugePages, TheHintLeavesArraysAsTheyAre) {
    advise_huge_pages(nullptr, 0);
    for (const std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{1000}, std::size_t{3} << 20U}) {
        std::vector<Index> v;
        reserve_huge(v, n);
        EXPECT_GE(v.capacity(), n);
        EXPECT_TRUE(v.empty());
        v.resize(n);
        for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<Index>(i * 7);
        advise_huge_pages(v.data(), v.size() * sizeof(Index));
        for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(v[i], static_cast<Index>(i * 7)) << i;
    }
}

}  // namespace
}  // namespace dcel
