// The validator must pass every built DCEL and fail on each planted bug:
// every checker is shown to fire, naming the ids involved.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <limits>
#include <string>

#include "dcel/build.hpp"
#include "dcel/error.hpp"
#include "dcel/validate.hpp"
#include "support/check_helpers.hpp"

namespace dcel {
namespace {

// Square 0-3 (with a dangling edge 3-8 inside, so vertex 3 has degree 3)
// holding triangle 4-6 as a hole and isolated vertex 7; isolated 10 inside
// the triangle; isolated 9 outside.
PlanarGraph rich_graph() {
    PlanarGraph g;
    g.vertices = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {2, 2}, {5, 2}, {2, 5}, {8, 8}, {1, 9}, {20, 20}, {3, 3}};
    for (const auto& [u, v] :
         std::vector<std::pair<Index, Index>>{{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 4}, {3, 8}}) {
        g.edges.push_back({VertexId(u), VertexId(v)});
    }
    return g;
}

DcelDump rich_dump() { return to_dump(build(rich_graph())); }

FaceId face_with_isolated(const DcelDump& d, Index v) {
    for (Index f = 0; f < d.faces.size(); ++f) {
        const auto& iso = d.faces[f].isolated;
        if (std::find(iso.begin(), iso.end(), VertexId(v)) != iso.end()) return FaceId(f);
    }
    return {};
}

// The half-edge u->v of the dump.
HalfEdgeId half_edge(const DcelDump& d, Index u, Index v) {
    for (Index h = 0; h < d.half_edges.size(); ++h) {
        if (d.half_edges[h].origin == VertexId(u) && d.half_edges[d.half_edges[h].twin.index()].origin == VertexId(v)) {
            return HalfEdgeId(h);
        }
    }
    return {};
}

void expect_violation(const DcelDump& d, Invariant expected, const std::string& text) {
    const CheckResult v = validate(d);
    ASSERT_TRUE(v.has_value()) << "no violation found; expected " << to_string(expected);
    EXPECT_EQ(v->invariant, expected) << v->message;
    EXPECT_NE(v->message.find(text), std::string::npos) << v->message;
    std::cerr << "  [" << to_string(v->invariant) << "] " << v->message << "\n";
    EXPECT_EQ(v->message.find('\n'), std::string::npos);
}

TEST(Validate, AcceptsBuiltDcels) {
    EXPECT_FALSE(validate(rich_dump()).has_value());
    EXPECT_FALSE(validate(build(PlanarGraph{})).has_value());
    EXPECT_TRUE(validate_all(rich_dump()).empty());
}

TEST(Validate, References) {
    DcelDump d = rich_dump();
    d.half_edges[3].next = HalfEdgeId(999);
    expect_violation(d, Invariant::References, "next(h3) = h999 is out of range");
    d = rich_dump();
    d.faces[1].inner.push_back(HalfEdgeId(77));
    expect_violation(d, Invariant::References, "an inner cycle of f1 names h77");
    d = rich_dump();
    d.vertex_out.pop_back();
    expect_violation(d, Invariant::References, "vertex_out has 10 entries for 11 vertices");
    d = rich_dump();
    d.half_edges[0].face = FaceId(50);
    expect_violation(d, Invariant::References, "face(h0) = f50");
    d = rich_dump();
    d.faces.clear();
    expect_violation(d, Invariant::References, "no faces");
    d = rich_dump();
    d.vertex_out[2] = HalfEdgeId(500);
    expect_violation(d, Invariant::References, "out(v2) = h500 is out of range");
    d = rich_dump();
    d.faces[1].outer = HalfEdgeId(600);
    expect_violation(d, Invariant::References, "the outer cycle of f1 names h600, out of range");
}

TEST(Validate, Twin) {
    DcelDump d = rich_dump();
    d.half_edges[0].twin = HalfEdgeId(2);
    expect_violation(d, Invariant::Twin, "twin(h0) = h2 but twin(h2) = h3");
    d = rich_dump();
    d.half_edges[4].twin = HalfEdgeId(4);
    expect_violation(d, Invariant::Twin, "twin(h4) = h4");
}

TEST(Validate, NextPrev) {
    DcelDump d = rich_dump();
    std::swap(d.half_edges[0].next, d.half_edges[1].next);  // prev left alone
    expect_violation(d, Invariant::NextPrev, "next(h0) = ");
}

TEST(Validate, NextOrigin) {
    // The seed solver's bug: next(h) = twin of the clockwise neighbour, so
    // next arrives at the target instead of leaving it. Recreate it on one
    // pair while keeping next and prev inverse.
    DcelDump d = rich_dump();
    const HalfEdgeId a(0), b(2);
    const HalfEdgeId na = d.half_edges[a.index()].next, nb = d.half_edges[b.index()].next;
    d.half_edges[a.index()].next = nb;
    d.half_edges[b.index()].next = na;
    d.half_edges[nb.index()].prev = a;
    d.half_edges[na.index()].prev = b;
    expect_violation(d, Invariant::NextOrigin, "h0 ends at v1 but next(h0) = ");
}

TEST(Validate, FaceOnCycle) {
    DcelDump d = rich_dump();
    d.half_edges[6].face = FaceId((d.half_edges[6].face.index() + 1) % d.faces.size());
    expect_violation(d, Invariant::FaceOnCycle, "h6");
}

TEST(Validate, VertexOut) {
    DcelDump d = rich_dump();
    d.vertex_out[3] = half_edge(d, 0, 1);
    expect_violation(d, Invariant::VertexOut, "out(v3) = h0 but h0 leaves v0");
    d = rich_dump();
    d.vertex_out[2] = HalfEdgeId();
    expect_violation(d, Invariant::VertexOut, "out(v2) is null but 2 half-edges leave it");
}

TEST(Validate, FaceRecords) {
    DcelDump d = rich_dump();
    d.faces.push_back({});  // a second face without an outer cycle
    expect_violation(d, Invariant::FaceRecords, "2 faces have no outer cycle");
    d = rich_dump();
    d.faces[0].inner.clear();  // the square's outer boundary is named by nobody
    expect_violation(d, Invariant::FaceRecords, "is not listed by any face");
    d = rich_dump();
    d.faces[0].inner.push_back(d.faces[0].inner.front());
    expect_violation(d, Invariant::FaceRecords, "is listed more than once");
    d = rich_dump();
    std::swap(d.faces[1].outer, d.faces[2].outer);
    expect_violation(d, Invariant::FaceRecords, "as its outer cycle, but face(");
}

TEST(Validate, IsolatedVertices) {
    DcelDump d = rich_dump();
    const FaceId f = face_with_isolated(d, 7);
    d.faces[f.index()].isolated.clear();
    expect_violation(d, Invariant::IsolatedVertices, "isolated vertex v7 is not listed in any face");
    d = rich_dump();
    d.faces[0].isolated.push_back(VertexId(4));
    expect_violation(d, Invariant::IsolatedVertices, "lists v4 as isolated, but 2 half-edges leave it");
    d = rich_dump();
    d.faces[0].isolated.push_back(VertexId(9));
    expect_violation(d, Invariant::IsolatedVertices, "v9 is listed more than once");
}

TEST(Validate, Embedding) {
    DcelDump d = rich_dump();
    d.vertices[8] = {11, 9};  // the dangling edge 3-8 now crosses the square's side 1-2
    expect_violation(d, Invariant::Embedding, "cross");
    d = rich_dump();
    d.vertices[7] = d.vertices[9];
    expect_violation(d, Invariant::Embedding, "vertices 7 and 9 are at the same point");
    d = rich_dump();
    d.vertices[7] = {5, 0};  // isolated vertex on the square's bottom side
    expect_violation(d, Invariant::Embedding, "vertex 7 (5, 0) lies inside");
}

using test_support::edges_only_dump;

PlanarGraph graph_of(std::vector<Point> points, const std::vector<std::pair<Index, Index>>& edges) {
    PlanarGraph g;
    g.vertices = std::move(points);
    for (const auto& [u, v] : edges) g.edges.push_back({VertexId(u), VertexId(v)});
    return g;
}

// validate()'s embedding check is its own code (validate/embedding.cpp and
// segment_sweep.cpp), not build()'s; on each kind of problem it must still
// refuse what build() refuses, with build()'s words and elements.
TEST(Validate, EmbeddingRefusesEachProblemAsBuildDoes) {
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<std::pair<const char*, PlanarGraph>> cases = {
        {"non-finite", graph_of({{0, 0}, {inf, 1}}, {{0, 1}})},
        {"self-loop", graph_of({{0, 0}, {1, 0}}, {{0, 1}, {1, 1}})},
        {"same point", graph_of({{0, 0}, {1, 0}, {0, 0}}, {{0, 1}})},
        {"duplicate edge", graph_of({{0, 0}, {1, 0}, {0, 1}}, {{0, 1}, {0, 2}, {1, 0}})},
        {"same direction", graph_of({{0, 0}, {2, 0}, {1, 0}}, {{0, 1}, {0, 2}})},
        {"collinear stretch", graph_of({{0, 0}, {2, 0}, {1, 0}, {3, 0}}, {{0, 1}, {2, 3}})},
        {"crossing", graph_of({{0, 0}, {2, 2}, {0, 2}, {2, 0}}, {{0, 1}, {2, 3}})},
        {"vertical crossing", graph_of({{0, -1}, {0, 1}, {-1, 0}, {1, 0}}, {{0, 1}, {2, 3}})},
        {"right end inside", graph_of({{0, 0}, {4, 0}, {1, 2}, {2, 0}}, {{0, 1}, {2, 3}})},
        {"left end inside", graph_of({{0, 0}, {4, 4}, {2, 2}, {3, 0}}, {{0, 1}, {2, 3}})},
        {"lone vertex inside a vertical edge", graph_of({{0, 0}, {0, 2}, {0, 1}}, {{0, 1}})},
        {"vertical edges overlapping", graph_of({{0, 0}, {0, 2}, {0, 1}, {0, 3}}, {{0, 1}, {2, 3}})},
    };
    for (const auto& [name, g] : cases) {
        SCOPED_TRACE(name);
        std::string refusal;
        std::vector<VertexId> vertices;
        std::vector<EdgeId> edges;
        try {
            (void)build(g);
            FAIL() << "build() accepted it";
        } catch (const InvalidInput& e) {
            refusal = e.what();
            vertices = e.vertices();
            edges = e.edges();
        }
        const CheckResult v = check_embedding(edges_only_dump(g));
        ASSERT_TRUE(v.has_value());
        EXPECT_EQ(v->invariant, Invariant::Embedding);
        EXPECT_EQ(v->message.rfind(refusal, 0), 0U) << v->message << "\nbuild(): " << refusal;
        EXPECT_EQ(v->vertices, vertices);
        std::vector<EdgeId> named;
        for (const HalfEdgeId h : v->half_edges) named.push_back(edge_of(h));
        EXPECT_EQ(named, edges);
    }
    // And it passes what build() accepts, vertical edges and shared x included.
    const PlanarGraph fine = graph_of({{0, 0}, {0, 2}, {1, 1}, {0, 3}, {1, 3}, {2, 0}},
                                      {{0, 1}, {0, 2}, {1, 2}, {1, 3}, {3, 4}, {2, 5}, {0, 5}});
    EXPECT_NO_THROW((void)build(fine));
    EXPECT_FALSE(check_embedding(edges_only_dump(fine)).has_value());
}

TEST(Validate, Rotation) {
    // Mirroring the points keeps the drawing planar but turns every rotation
    // around: at v3 (degree 3) next(twin(h)) now runs counterclockwise.
    DcelDump d = rich_dump();
    for (Point& p : d.vertices) p.x = -p.x;
    expect_violation(d, Invariant::Rotation, "around v3");
    // A vertex orbit that splits: exchange next of two half-edges into v3
    // (and fix prev), so next(twin(h)) around v3 misses an edge.
    d = rich_dump();
    const HalfEdgeId a = half_edge(d, 2, 3), b = half_edge(d, 8, 3);
    const HalfEdgeId na = d.half_edges[a.index()].next, nb = d.half_edges[b.index()].next;
    d.half_edges[a.index()].next = nb;
    d.half_edges[b.index()].next = na;
    d.half_edges[nb.index()].prev = a;
    d.half_edges[na.index()].prev = b;
    // Faces now disagree along the new cycles; give each cycle one face and
    // skip straight to the rotation check.
    EXPECT_TRUE(check_rotation(d).has_value());
    EXPECT_NE(check_rotation(d)->message.find("around v3"), std::string::npos) << check_rotation(d)->message;
}

TEST(Validate, Orientation) {
    // A lone triangle mirrored: every vertex has degree 2, so rotations are
    // fine, but the cycles turn the other way. Faces are checked in id order,
    // so the unbounded face's hole, now counterclockwise, is reported first.
    PlanarGraph g;
    g.vertices = {{0, 0}, {1, 0}, {0, 1}};
    g.edges = {{VertexId(0), VertexId(1)}, {VertexId(1), VertexId(2)}, {VertexId(2), VertexId(0)}};
    DcelDump d = to_dump(build(g));
    for (Point& p : d.vertices) p.x = -p.x;
    expect_violation(d, Invariant::Orientation, "the inner cycle of f0 through h1 is counterclockwise");
    // Without the hole, the bounded face's outer cycle is the one reported.
    d.faces[0].inner.clear();
    EXPECT_NE(check_orientation(d)->message.find("the outer cycle of f1 (through h0) is not counterclockwise"),
              std::string::npos);
    // The two cycles' roles swapped: the clockwise cycle as a bounded face's outer.
    d = to_dump(build(g));
    std::swap(d.faces[0].inner[0], d.faces[1].outer);
    for (HalfEdgeRecord& r : d.half_edges) r.face = FaceId(1 - r.face.index());
    expect_violation(d, Invariant::Orientation, "the inner cycle of f0 through h0 is counterclockwise");
    d.faces[0].inner.clear();
    EXPECT_NE(check_orientation(d)->message.find("the outer cycle of f1 (through h1) is not counterclockwise"),
              std::string::npos);
}

TEST(Validate, HolePlacement) {
    // Move the triangle's outer boundary from the square's face to the
    // unbounded face, consistently: every other invariant still holds.
    DcelDump d = rich_dump();
    const HalfEdgeId tri_out = half_edge(d, 4, 6);  // on the triangle's clockwise outer boundary
    const FaceId square = d.half_edges[tri_out.index()].face;
    ASSERT_NE(square, FaceId(0));
    auto& inner = d.faces[square.index()].inner;
    const auto it = std::find_if(inner.begin(), inner.end(), [&](HalfEdgeId h) {
        for (HalfEdgeId x = h;;) {
            if (x == tri_out) return true;
            x = d.half_edges[x.index()].next;
            if (x == h) return false;
        }
    });
    ASSERT_NE(it, inner.end());
    d.faces[0].inner.push_back(*it);
    inner.erase(it);
    for (HalfEdgeId x = tri_out;;) {
        d.half_edges[x.index()].face = FaceId(0);
        x = d.half_edges[x.index()].next;
        if (x == tri_out) break;
    }
    expect_violation(d, Invariant::HolePlacement, "is placed in f0 but lies in " + square.str());

    // An isolated vertex listed in the wrong face.
    d = rich_dump();
    const FaceId f7 = face_with_isolated(d, 7);
    const FaceId f10 = face_with_isolated(d, 10);
    d.faces[f7.index()].isolated.clear();
    d.faces[f10.index()].isolated.push_back(VertexId(7));
    expect_violation(d, Invariant::HolePlacement, "isolated vertex v7 is placed in " + f10.str());
}

TEST(Validate, ValidateAllReportsEachBrokenInvariant) {
    DcelDump d = rich_dump();
    d.half_edges[6].face = FaceId((d.half_edges[6].face.index() + 1) % d.faces.size());
    d.vertex_out[2] = HalfEdgeId();
    d.faces[face_with_isolated(d, 7).index()].isolated.clear();
    const auto all = validate_all(d);
    std::vector<Invariant> kinds;
    for (const Violation& v : all) kinds.push_back(v.invariant);
    EXPECT_NE(std::find(kinds.begin(), kinds.end(), Invariant::FaceOnCycle), kinds.end());
    EXPECT_NE(std::find(kinds.begin(), kinds.end(), Invariant::VertexOut), kinds.end());
    EXPECT_NE(std::find(kinds.begin(), kinds.end(), Invariant::IsolatedVertices), kinds.end());
}

}  // namespace
}  // namespace dcel
