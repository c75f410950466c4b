// dcel::check::compare_faces and compare_dump: every kind of difference is
// shown on an answer derived from the reference by a known change, so what
// must be reported is known without asking the comparison.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <set>
#include <string>

#include "dcel/build.hpp"
#include "dcel/check/compare.hpp"
#include "dcel/check/report.hpp"
#include "dcel/gen/generate.hpp"
#include "support/check_helpers.hpp"
#include "support/edit_helpers.hpp"

namespace dcel::test_support {
namespace {

using check::compare_dump;
using check::compare_faces;
using check::DifferenceKind;
using check::Report;

// West [0 1 4 5] and East [1 2 3 4] side by side; a triangle 6 7 8 is a hole
// of West; isolated 9 in West, 10 in East, 11 outside; a dangling edge 3-12
// into East; a path 13-14-15 outside (a tree: its one cycle repeats 14).
PlanarGraph rich() {
    return graph(
        {{0, 0},
         {10, 0},
         {20, 0},
         {20, 10},
         {10, 10},
         {0, 10},
         {2, 2},
         {5, 2},
         {2, 5},
         {7, 7},
         {15, 5},
         {30, 30},
         {18, 8},
         {40, 0},
         {41, 0},
         {41, 1}},
        {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 0}, {1, 4}, {6, 7}, {7, 8}, {8, 6}, {3, 12}, {13, 14}, {14, 15}});
}

// Prints the report, so a failing expectation shows what was said.
Report show(Report r) {
    std::cerr << check::report_text(r);
    return r;
}

// The index of the answer cycle equal (as a cycle) to `want`.
std::size_t find_cycle(const FacesAnswer& a, const std::vector<Index>& want) {
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (canonical(a[i]) == canonical(want)) return i;
    }
    ADD_FAILURE() << "no such cycle";
    return 0;
}

TEST(CheckFaces, AgreesWithItselfInAnyOrderAndRotation) {
    const Dcel d = build(rich());
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
        const Report r = compare_faces(d, shuffled(faces_answer(d), seed));
        EXPECT_TRUE(r.agrees()) << check::report_text(r);
    }
    EXPECT_TRUE(compare_faces(build(PlanarGraph{}), {}).agrees());
    EXPECT_TRUE(compare_faces(build(graph({{0, 0}, {1, 1}}, {})), {}).agrees());  // isolated vertices only
}

TEST(CheckFaces, AgreesOnEveryFamily) {
    for (const gen::Family f : gen::all_families()) {
        for (std::uint64_t seed = 0; seed < 8; ++seed) {
            const Dcel d = build(gen::generate({f, seed, 5 + 10 * seed}));
            const Report r = compare_faces(d, shuffled(faces_answer(d), seed));
            EXPECT_TRUE(r.agrees()) << gen::family_name(f) << " " << seed << "\n" << check::report_text(r);
        }
    }
}

TEST(CheckFaces, VertexCountForAnIdBeyondTheGraph) {
    const Dcel d = build(rich());
    FacesAnswer a = faces_answer(d);
    a[0].push_back(16);  // the graph has v0..v15
    const Report r = show(compare_faces(d, a));
    ASSERT_FALSE(r.agrees());
    EXPECT_EQ(r.differences[0].kind, DifferenceKind::VertexCount);
    EXPECT_NE(r.differences[0].message.find("vertex 16, but the graph has 16 vertices"), std::string::npos);
    // The cycle it spoiled is then missing; nothing else.
    EXPECT_EQ(count_kind(r, DifferenceKind::MissingCycle), 1U);
    EXPECT_EQ(r.differences.size(), 2U);

    a = faces_answer(d);
    a.push_back({kNoIndex - 1, 0});
    EXPECT_EQ(show(compare_faces(d, a)).differences.at(0).kind, DifferenceKind::VertexCount);
}

TEST(CheckFaces, NotAnEdge) {
    const Dcel d = build(rich());
    FacesAnswer a = faces_answer(d);
    a.push_back({0, 2, 1});  // 0-2 is not an edge (1 lies between them)
    Report r = show(compare_faces(d, a));
    ASSERT_EQ(r.differences.size(), 1U);
    EXPECT_EQ(r.differences[0].kind, DifferenceKind::NotAnEdge);
    EXPECT_EQ(r.differences[0].vertices, (std::vector<Index>{0, 2}));
    EXPECT_NE(r.differences[0].message.find("steps from v0 to v2"), std::string::npos);

    a = faces_answer(d);
    a.push_back({9});  // an isolated vertex as a cycle of one
    r = show(compare_faces(d, a));
    ASSERT_EQ(r.differences.size(), 1U);
    EXPECT_EQ(r.differences[0].kind, DifferenceKind::NotAnEdge);
    EXPECT_NE(r.differences[0].message.find("single vertex"), std::string::npos);
}

TEST(CheckFaces, MissingCycleForEachDroppedCycle) {
    const Dcel d = build(rich());
    const FacesAnswer full = faces_answer(d);
    for (std::size_t k = 0; k < full.size(); ++k) {
        FacesAnswer a = full;
        a.erase(a.begin() + static_cast<std::ptrdiff_t>(k));
        const Report r = compare_faces(d, shuffled(a, k));
        ASSERT_EQ(r.differences.size(), 1U) << check::report_text(r);
        EXPECT_EQ(r.differences[0].kind, DifferenceKind::MissingCycle);
        EXPECT_EQ(canonical(r.differences[0].vertices), canonical(full[k]));
    }
}

TEST(CheckFaces, ExtraCycleForARepeatAnEmptyCycleAndTwoTurns) {
    const Dcel d = build(rich());
    const FacesAnswer full = faces_answer(d);
    const std::size_t west = find_cycle(full, {0, 1, 4, 5});
    for (std::size_t k = 0; k < full.size(); ++k) {
        FacesAnswer a = full;
        a.push_back(full[k]);
        const Report r = compare_faces(d, shuffled(a, k));
        ASSERT_EQ(r.differences.size(), 1U) << check::report_text(r);
        EXPECT_EQ(r.differences[0].kind, DifferenceKind::ExtraCycle);
        EXPECT_NE(r.differences[0].message.find("the reference has this cycle once"), std::string::npos);
    }
    FacesAnswer a = full;
    a.emplace_back();
    Report r = show(compare_faces(d, a));
    ASSERT_EQ(r.differences.size(), 1U);
    EXPECT_EQ(r.differences[0].kind, DifferenceKind::ExtraCycle);
    EXPECT_NE(r.differences[0].message.find("is empty"), std::string::npos);

    a = full;  // West walked twice in one list: extra, and West itself missing
    a[west].insert(a[west].end(), full[west].begin(), full[west].end());
    r = show(compare_faces(d, a));
    EXPECT_EQ(count_kind(r, DifferenceKind::ExtraCycle), 1U);
    EXPECT_EQ(count_kind(r, DifferenceKind::MissingCycle), 1U);
    ASSERT_NE(find_kind(r, DifferenceKind::ExtraCycle), nullptr);
    EXPECT_NE(find_kind(r, DifferenceKind::ExtraCycle)->message.find("2 times"), std::string::npos);
    EXPECT_EQ(r.differences.size(), 2U);
}

TEST(CheckFaces, ReversedCycle) {
    const Dcel d = build(rich());
    const FacesAnswer full = faces_answer(d);
    const std::size_t west = find_cycle(full, {0, 1, 4, 5});
    FacesAnswer a = full;
    std::reverse(a[west].begin(), a[west].end());
    const Report r = show(compare_faces(d, a));
    ASSERT_EQ(r.differences.size(), 1U);
    EXPECT_EQ(r.differences[0].kind, DifferenceKind::ReversedCycle);
    EXPECT_EQ(canonical(r.differences[0].vertices), canonical({5, 4, 1, 0}));
}

// The mirror image (x -> -x) has every cycle of the original reversed. A
// cycle whose reverse is itself a reference cycle (a triangle's inside and
// outside, a tree's walk) still matches; every other one is reported reversed.
TEST(CheckFaces, MirrorImageReversesEveryCycle) {
    const PlanarGraph g = rich();
    const Dcel d = build(g);
    const Dcel mirrored = build(*gen::apply(g, gen::Transform::Mirror));
    std::set<std::vector<Index>> cycles;
    for (const auto& c : faces_answer(d)) cycles.insert(canonical(c));
    std::size_t expected = 0;
    for (const auto& c : faces_answer(d)) {
        expected += cycles.count(canonical({c.rbegin(), c.rend()})) == 0 ? 1 : 0;
    }
    const Report r = show(compare_faces(d, faces_answer(mirrored)));
    EXPECT_EQ(expected, 3U);  // West, East and the rectangle's outside
    EXPECT_EQ(r.differences.size(), expected);
    EXPECT_EQ(count_kind(r, DifferenceKind::ReversedCycle), expected);
}

// Swapping next(a) and next(b) for two half-edges a, b into the same vertex
// splits or merges their cycles; the answer's walk leaves the reference's
// exactly at a and at b.
TEST(CheckFaces, WrongNextAtTheRewiredHalfEdges) {
    const PlanarGraph g = rich();
    const Dcel d = build(g);
    int cases = 0;
    for (Index e1 = 0; e1 < d.num_half_edges(); ++e1) {
        for (Index e2 = e1 + 1; e2 < d.num_half_edges(); ++e2) {
            const HalfEdgeId a(e1), b(e2);
            if (d.target(a) != d.target(b)) continue;
            std::vector<Index> next = next_array(d);
            std::swap(next[e1], next[e2]);
            const Report r = compare_faces(d, cycles_of_permutation(d, next));
            ASSERT_FALSE(r.agrees());
            EXPECT_EQ(r.differences[0].kind, DifferenceKind::WrongNext) << check::report_text(r);
            EXPECT_EQ(count_kind(r, DifferenceKind::WrongNext), 2U) << check::report_text(r);
            for (const HalfEdgeId h : {a, b}) {
                const HalfEdgeId given(next[h.index()]);
                const std::vector<Index> want{d.origin(h).index(), d.target(h).index(), d.target(given).index(),
                                              d.target(d.next(h)).index()};
                const bool found = std::any_of(r.differences.begin(), r.differences.end(), [&](const auto& x) {
                    return x.kind == DifferenceKind::WrongNext && x.vertices == want;
                });
                EXPECT_TRUE(found) << "no wrong next at " << h << "\n" << check::report_text(r);
            }
            ++cases;
        }
    }
    EXPECT_GT(cases, 10);
}

// The seed solver's rule, next(h) = twin(reference next(h)): on a triangle,
// three 2-cycles, a wrong next at all six half-edges, both faces missing.
TEST(CheckFaces, SeedSolverRule) {
    const Dcel d = build(graph({{0, 0}, {1, 0}, {0, 1}}, {{0, 1}, {1, 2}, {2, 0}}));
    std::vector<Index> next = next_array(d);
    for (Index& n : next) n ^= 1U;
    const Report r = show(compare_faces(d, cycles_of_permutation(d, next)));
    EXPECT_EQ(count_kind(r, DifferenceKind::WrongNext), 6U);
    EXPECT_EQ(count_kind(r, DifferenceKind::MissingCycle), 2U);
    EXPECT_EQ(count_kind(r, DifferenceKind::ExtraCycle), 3U);
    EXPECT_EQ(r.differences[0].kind, DifferenceKind::WrongNext);
    EXPECT_EQ(r.differences[0].message.find('\n'), std::string::npos);
}

TEST(CheckFaces, HostileAnswersAreBoundedAndCapped) {
    const Dcel d = build(rich());
    FacesAnswer a(5000, std::vector<Index>{kNoIndex - 1, kNoIndex - 2});
    a.resize(10000);  // and 5000 empty cycles
    Report r = compare_faces(d, a);
    EXPECT_EQ(r.differences.size() + r.unlisted, 10000U + faces_answer(d).size());
    EXPECT_EQ(count_kind(r, DifferenceKind::VertexCount), check::kMaxListedPerKind);
    EXPECT_EQ(r.differences[0].kind, DifferenceKind::VertexCount);
    EXPECT_NE(check::report_text(r).find("more not listed"), std::string::npos);

    // One cycle walking every half-edge of the graph in turn, 2000 times.
    FacesAnswer walk(1);
    for (int k = 0; k < 2000; ++k) {
        for (const auto& c : faces_answer(d)) walk[0].insert(walk[0].end(), c.begin(), c.end());
    }
    r = compare_faces(d, walk);
    EXPECT_FALSE(r.agrees());
    EXPECT_LE(r.differences.size(), 4 * check::kMaxListedPerKind);
}

// ---- Dumps

DcelDump rich_dump() { return to_dump(build(rich())); }

TEST(CheckDump, AgreesModuloNumbering) {
    const Dcel d = build(rich());
    EXPECT_TRUE(compare_dump(d, to_dump(d)).agrees());
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
        const Report r = compare_dump(d, renumbered(to_dump(d), seed));
        EXPECT_TRUE(r.agrees()) << check::report_text(r);
    }
    DcelDump no_out = renumbered(to_dump(d), 99);
    no_out.vertex_out.clear();  // optional in a foreign dump
    EXPECT_TRUE(compare_dump(d, no_out).agrees());
    for (const gen::Family f : gen::all_families()) {
        const Dcel g = build(gen::generate({f, 3, 40}));
        const Report r = compare_dump(g, renumbered(to_dump(g), 3));
        EXPECT_TRUE(r.agrees()) << gen::family_name(f) << "\n" << check::report_text(r);
    }
}

TEST(CheckDump, VertexCountWhenAPointIsAddedOrMissing) {
    const Dcel d = build(rich());
    DcelDump a = rich_dump();
    a.vertices.push_back({50, 50});
    a.vertex_out.emplace_back();
    a.faces[0].isolated.push_back(VertexId(16));
    Report r = show(compare_dump(d, a));
    ASSERT_FALSE(r.agrees());
    EXPECT_EQ(r.differences[0].kind, DifferenceKind::VertexCount);
    EXPECT_NE(r.differences[0].message.find("17 vertices, the graph 16"), std::string::npos);

    a = rich_dump();  // the last vertex dropped (its half-edges still name it)
    a.vertices.pop_back();
    a.vertex_out.pop_back();
    r = show(compare_dump(d, a));
    ASSERT_FALSE(r.agrees());
    EXPECT_EQ(r.differences[0].kind, DifferenceKind::VertexCount);
}

TEST(CheckDump, WrongPoint) {
    const Dcel d = build(rich());
    DcelDump a = renumbered(rich_dump(), 1);
    a.vertices[9] = {8, 8};  // still inside West, so the dump stays valid
    const Report r = show(compare_dump(d, a));
    ASSERT_EQ(r.differences.size(), 1U);
    EXPECT_EQ(r.differences[0].kind, DifferenceKind::WrongPoint);
    EXPECT_EQ(r.differences[0].vertices, (std::vector<Index>{9}));
    EXPECT_NE(r.differences[0].message.find("(8, 8) in the answer, at (7, 7)"), std::string::npos);
}

TEST(CheckDump, BrokenInvariantNamesTheChecker) {
    const Dcel d = build(rich());
    DcelDump a = renumbered(rich_dump(), 2);
    a.half_edges[0].next = a.half_edges[1].next;  // next is no longer a permutation
    Report r = show(compare_dump(d, a));
    ASSERT_FALSE(r.agrees());
    EXPECT_EQ(r.differences[0].kind, DifferenceKind::BrokenInvariant);
    EXPECT_EQ(r.differences[0].message.rfind("[next-prev] ", 0), 0U);

    a = rich_dump();
    a.half_edges[3].twin = HalfEdgeId(1000);
    r = show(compare_dump(d, a));
    ASSERT_EQ(r.differences.size(), 1U);
    EXPECT_EQ(r.differences[0].message.rfind("[references] ", 0), 0U);
}

// Moves West's triangle hole into East (its half-edges' faces too, so the
// records stay consistent): a wrong hole, which hole-placement also sees.
TEST(CheckDump, WrongHole) {
    const Dcel d = build(rich());
    DcelDump a = rich_dump();
    const HalfEdgeId west_edge = dump_half_edge(a, 0, 1);
    const HalfEdgeId east_edge = dump_half_edge(a, 1, 2);
    const FaceId west = a.half_edges[west_edge.index()].face;
    const FaceId east = a.half_edges[east_edge.index()].face;
    ASSERT_EQ(a.faces[west.index()].inner.size(), 1U);
    const HalfEdgeId hole = a.faces[west.index()].inner[0];
    a.faces[west.index()].inner.clear();
    a.faces[east.index()].inner.push_back(hole);
    HalfEdgeId h = hole;
    do {
        a.half_edges[h.index()].face = east;
        h = a.half_edges[h.index()].next;
    } while (h != hole);
    const Report r = show(compare_dump(d, renumbered(a, 4)));
    ASSERT_EQ(count_kind(r, DifferenceKind::WrongHole), 1U);
    const check::Difference* wrong = find_kind(r, DifferenceKind::WrongHole);
    ASSERT_NE(wrong, nullptr);
    EXPECT_EQ(canonical(wrong->vertices), canonical({6, 8, 7}));
    EXPECT_NE(wrong->message.find("is a hole of the face bounded by [0, 1, 4, 5]"), std::string::npos);
    EXPECT_NE(wrong->message.find("but the answer puts it in answer face"), std::string::npos);
    EXPECT_NE(wrong->message.find("(the face bounded by [1, 2, 3, 12, 3, 4])"), std::string::npos);
    EXPECT_EQ(r.differences[0].kind, DifferenceKind::BrokenInvariant);
    EXPECT_EQ(r.differences[0].message.rfind("[hole-placement]", 0), 0U);
    // No cycle changed.
    EXPECT_EQ(count_kind(r, DifferenceKind::MissingCycle) + count_kind(r, DifferenceKind::WrongNext), 0U);
}

TEST(CheckDump, WrongOuterBoundaryWhenOuterAndHoleSwap) {
    const Dcel d = build(rich());
    DcelDump a = rich_dump();
    const FaceId west = a.half_edges[dump_half_edge(a, 0, 1).index()].face;
    FaceDump& f = a.faces[west.index()];
    std::swap(f.outer, f.inner[0]);
    const Report r = show(compare_dump(d, renumbered(a, 5)));
    EXPECT_EQ(count_kind(r, DifferenceKind::WrongOuterBoundary), 2U);  // West's boundary and the triangle
    EXPECT_EQ(count_kind(r, DifferenceKind::BrokenInvariant), 1U);     // orientation
    EXPECT_EQ(count_kind(r, DifferenceKind::MissingCycle), 0U);

    a = rich_dump();  // the unbounded face given an outer boundary
    a.faces[0].outer = a.faces[0].inner[0];
    const Report r2 = show(compare_dump(d, a));
    EXPECT_GE(count_kind(r2, DifferenceKind::WrongOuterBoundary), 1U);

    a = rich_dump();  // West's outer boundary listed as a hole: two faces without one
    FaceDump& w = a.faces[west.index()];
    w.inner.push_back(w.outer);
    w.outer = HalfEdgeId();
    const Report r3 = show(compare_dump(d, a));
    const std::string two = "answer faces f0 f" + std::to_string(west.index()) +
                            " (2) have no outer boundary; only the unbounded face lacks one";
    EXPECT_TRUE(std::any_of(r3.differences.begin(), r3.differences.end(), [&](const check::Difference& x) {
        return x.kind == DifferenceKind::WrongOuterBoundary && x.message == two;
    })) << report_text(r3);
}

TEST(CheckDump, WrongIsolatedVertex) {
    const Dcel d = build(rich());
    DcelDump a = rich_dump();
    const FaceId west = a.half_edges[dump_half_edge(a, 0, 1).index()].face;
    const FaceId east = a.half_edges[dump_half_edge(a, 1, 2).index()].face;
    auto& west_iso = a.faces[west.index()].isolated;
    ASSERT_EQ(west_iso, (std::vector<VertexId>{VertexId(9)}));
    west_iso.clear();
    a.faces[east.index()].isolated.push_back(VertexId(9));  // v9 moved to East
    Report r = show(compare_dump(d, renumbered(a, 6)));
    ASSERT_EQ(count_kind(r, DifferenceKind::WrongIsolatedVertex), 1U);
    ASSERT_NE(find_kind(r, DifferenceKind::WrongIsolatedVertex), nullptr);
    EXPECT_EQ(find_kind(r, DifferenceKind::WrongIsolatedVertex)->vertices, (std::vector<Index>{9}));
    EXPECT_NE(find_kind(r, DifferenceKind::WrongIsolatedVertex)
                  ->message.find("isolated vertex v9 lies in the face bounded by [0, 1, 4, 5]"),
              std::string::npos);

    a = rich_dump();
    a.faces[0].isolated.clear();                 // v11 in no face
    a.faces[0].isolated.push_back(VertexId(0));  // and v0, which has edges, listed
    r = show(compare_dump(d, a));
    EXPECT_EQ(count_kind(r, DifferenceKind::WrongIsolatedVertex), 2U);
}

// A dump whose next is rewired at one vertex (prev kept the inverse): still
// walkable, so the comparison names the place.
TEST(CheckDump, WrongNextInARewiredDump) {
    const Dcel d = build(rich());
    DcelDump a = rich_dump();
    const HalfEdgeId x = dump_half_edge(a, 0, 1);  // both into v1
    const HalfEdgeId y = dump_half_edge(a, 4, 1);
    auto& rx = a.half_edges[x.index()];
    auto& ry = a.half_edges[y.index()];
    std::swap(rx.next, ry.next);
    a.half_edges[rx.next.index()].prev = x;
    a.half_edges[ry.next.index()].prev = y;
    const Report r = show(compare_dump(d, renumbered(a, 7)));
    EXPECT_EQ(count_kind(r, DifferenceKind::WrongNext), 2U);
    const std::string text = check::report_text(r);
    EXPECT_NE(text.find("wrong-next: at v0->v1 the answer continues to v1->v2 ("), std::string::npos);
    EXPECT_NE(text.find("), the reference to v1->v4\n"), std::string::npos);
    EXPECT_NE(text.find("wrong-next: at v4->v1 the answer continues to v1->v4 ("), std::string::npos);
}

TEST(CheckReport, TextAndJson) {
    const Dcel d = build(graph({{0, 0}, {1, 0}, {0, 1}}, {{0, 1}, {1, 2}, {2, 0}}));
    EXPECT_EQ(check::report_text(compare_faces(d, faces_answer(d))), "agrees\n");
    EXPECT_EQ(check::report_json(compare_faces(d, faces_answer(d))),
              "{\"agrees\": true, \"count\": 0, \"unlisted\": 0, \"differences\": [], \"notes\": []}\n");
    const FacesAnswer full = faces_answer(d);
    ASSERT_EQ(full.size(), 2U);
    std::string cycle;  // the first cycle, as the text writes it
    for (const Index v : full[0]) cycle += (cycle.empty() ? "" : ", ") + std::to_string(v);
    const Report r = compare_faces(d, {full[1]});
    EXPECT_EQ(check::report_text(r),
              "1 difference\nmissing-cycle: the reference cycle [" + cycle + "] is missing from the answer\n");
    EXPECT_EQ(check::report_json(r),
              "{\"agrees\": false, \"count\": 1, \"unlisted\": 0, \"differences\": [\n"
              "  {\"kind\": \"missing-cycle\", \"message\": \"the reference cycle [" +
                  cycle + "] is missing from the answer\", \"vertices\": [" + cycle + "]}\n], \"notes\": []}\n");
    for (const auto k : {DifferenceKind::VertexCount, DifferenceKind::WrongIsolatedVertex, DifferenceKind::WrongPoint}) {
        EXPECT_NE(check::kind_name(k), "unknown");
    }
}

}  // namespace
}  // namespace dcel::test_support
