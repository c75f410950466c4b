// dcel::check::read_answer and compare for every answer kind (faces, dump,
// polygons, rings) and convention (1-based ids, faces on the right, closed
// rings, unoriented rings). Each answer is written out by hand for a small
// graph drawn below, so what must be reported is known without asking the
// comparison: which polygons a polygonizer gives, which rings a face finder
// gives, and what each changed answer lacks.
#include <gtest/gtest.h>
#include <algorithm>

#include <iostream>
#include <string>

#include "dcel/build.hpp"
#include "dcel/check/answer.hpp"
#include "dcel/check/report.hpp"
#include "dcel/error.hpp"
#include "dcel/io/graph_json.hpp"

namespace dcel {
namespace {

using check::AnswerKind;
using check::Conventions;
using check::DifferenceKind;
using check::Report;

Dcel reference(std::string_view graph_json) { return build(io::read_graph(graph_json)); }

Report check_text(const Dcel& ref, std::string_view answer, std::optional<AnswerKind> kind = std::nullopt,
                  Conventions c = {}) {
    Report r = check::compare(ref, check::read_answer(answer, kind), c);
    std::cerr << check::report_text(r);
    return r;
}

bool has(const Report& r, DifferenceKind k) {
    for (const check::Difference& d : r.differences) {
        if (d.kind == k) return true;
    }
    return false;
}

bool noted(const Report& r, std::string_view text) {
    for (const std::string& n : r.notes) {
        if (n.find(text) != std::string::npos) return true;
    }
    return false;
}

// A square 0-1-2-3 (0..4 on each side) with a triangle 4-5-6 inside, joined
// to the square's corner 0 by the bridge 0-4, and vertex 7 alone outside:
//
//   3 +-----------+ 2        bounded faces: f1, between the square and the
//     |  6        |            triangle (the bridge has f1 on both sides);
//     |  |\       |            f2, the triangle
//     |  4-5      |
//     | /         |        as polygons: f1 = shell 0 1 2 3, hole 4 6 5
//   0 +-----------+ 1                   f2 = shell 4 5 6
//                          as rings:    f1 = 0 1 2 3 (the triangle filled in)
//                     7 .               f2 = 4 5 6
constexpr std::string_view kBridged = R"({"vertices": [[0,0],[4,0],[4,4],[0,4],[1,1],[2,1],[1,2],[5,5]],)"
                                      R"( "edges": [[0,1],[1,2],[2,3],[3,0],[4,5],[5,6],[6,4],[0,4]]})";

TEST(CheckPolygons, AgreeInEverySpelling) {
    const Dcel d = reference(kBridged);
    // Vertex-id rings, open and closed, as arrays and as shell/holes objects
    // (holes given before the shell), and the bare form.
    for (const char* answer : {
             R"({"polygons": [[[0,1,2,3],[4,6,5]], [[4,5,6]]]})",
             R"({"polygons": [[[0,1,2,3,0],[4,6,5,4]], [[5,6,4,5]]]})",
             R"({"polygons": [{"holes": [[6,5,4]], "shell": [1,2,3,0]}, {"shell": [6,4,5], "holes": []}]})",
             R"([[[0,1,2,3],[4,6,5]], [[4,5,6]]])",
         }) {
        const Report r = check_text(d, answer);
        EXPECT_TRUE(r.agrees()) << answer;
    }
}

TEST(CheckPolygons, AgreeAsGeoJson) {
    const Dcel d = reference(kBridged);
    for (const char* answer : {
             // A MultiPolygon, shells counterclockwise (RFC 7946), positions with an altitude.
             R"({"type": "MultiPolygon", "coordinates": [[[[0,0,9],[4,0,9],[4,4,9],[0,4,9],[0,0,9]],)"
             R"( [[1,1],[1,2],[2,1],[1,1]]], [[[1,1],[2,1],[1,2],[1,1]]]]})",
             // A FeatureCollection with "type" after "geometry", a Feature without geometry, -0.
             R"({"features": [{"geometry": {"coordinates": [[[0,0],[4,0],[4,4],[0,4],[-0.0,0]],)"
             R"( [[1,1],[1,2],[2,1],[1,1]]], "type": "Polygon"}, "type": "Feature", "properties": {"a": [1]}},)"
             R"( {"type": "Feature", "geometry": null, "properties": null},)"
             R"( {"type": "Feature", "geometry": {"type": "Polygon", "coordinates": [[[1,1],[2,1],[1,2],[1,1]]]}}],)"
             R"( "type": "FeatureCollection"})",
             // A GeometryCollection of a Polygon and a MultiPolygon.
             R"({"type": "GeometryCollection", "geometries": [{"type": "Polygon", "coordinates": )"
             R"([[[0,0],[4,0],[4,4],[0,4],[0,0]], [[1,1],[1,2],[2,1],[1,1]]]}, {"type": "MultiPolygon", )"
             R"("coordinates": [[[[1,1],[2,1],[1,2],[1,1]]]]}]})",
         }) {
        const Report r = check_text(d, answer);
        EXPECT_TRUE(r.agrees()) << answer;
        EXPECT_TRUE(noted(r, "detected from a GeoJSON object"));
    }
}

TEST(CheckPolygons, EachKindOfDifference) {
    const Dcel d = reference(kBridged);
    // The hole left out: f1 without its triangle.
    Report r = check_text(d, R"({"polygons": [[[0,1,2,3]], [[4,5,6]]]})");
    ASSERT_EQ(r.differences.size(), 1U);
    EXPECT_EQ(r.differences[0].kind, DifferenceKind::WrongHole);
    EXPECT_NE(r.differences[0].message.find("v4->v6"), std::string::npos);
    // The triangle's polygon missing.
    r = check_text(d, R"({"polygons": [[[0,1,2,3],[4,6,5]]]})");
    ASSERT_EQ(r.differences.size(), 1U);
    EXPECT_EQ(r.differences[0].kind, DifferenceKind::MissingFace);
    // An extra polygon: the whole square, which is no face.
    r = check_text(d, R"({"polygons": [[[0,1,2,3],[4,6,5]], [[4,5,6]], [[0,1,2,3]]]})");
    ASSERT_EQ(r.differences.size(), 1U);
    EXPECT_EQ(r.differences[0].kind, DifferenceKind::WrongHole);  // all its edges lie on f1: f1 without its hole
    r = check_text(d, R"({"polygons": [[[0,1,2,3],[4,6,5]], [[4,5,6]], [[4,5,6]]]})");
    ASSERT_EQ(r.differences.size(), 1U);
    EXPECT_EQ(r.differences[0].kind, DifferenceKind::ExtraPolygon);
    EXPECT_NE(r.differences[0].message.find("repeats polygon 1"), std::string::npos);
    // A shell walked clockwise.
    r = check_text(d, R"({"polygons": [[[0,3,2,1],[4,6,5]], [[4,5,6]]]})");
    ASSERT_EQ(r.differences.size(), 1U);
    EXPECT_EQ(r.differences[0].kind, DifferenceKind::WrongOrientation);
    // A point that is no vertex, a step that is no edge, an id out of range.
    r = check_text(d, R"({"polygons": [[[[0,0],[4,0],[4,4],[0,4.5]]]]})");
    EXPECT_TRUE(has(r, DifferenceKind::NotAVertex));
    r = check_text(d, R"({"polygons": [[[0,1,7]]]})");
    EXPECT_TRUE(has(r, DifferenceKind::NotAnEdge));
    r = check_text(d, R"({"polygons": [[[0,1,8]]]})");
    EXPECT_TRUE(has(r, DifferenceKind::VertexCount));
    // A ring of two vertices.
    r = check_text(d, R"({"polygons": [[[0,1]]]})");
    EXPECT_TRUE(has(r, DifferenceKind::ExtraPolygon));
}

TEST(CheckPolygons, Conventions) {
    const Dcel d = reference(kBridged);
    // GEOS's orientation: shells clockwise, holes counterclockwise.
    const char* geos = R"({"polygons": [[[0,3,2,1],[4,5,6]], [[4,6,5]]]})";
    Report r = check_text(d, geos);
    EXPECT_EQ(r.differences.size(), 3U);
    EXPECT_TRUE(noted(r, "agrees with --face-on right"));
    EXPECT_TRUE(check_text(d, geos, AnswerKind::Polygons, {.face_on_right = true}).agrees());
    EXPECT_TRUE(check_text(d, geos, AnswerKind::Polygons, {.unoriented = true}).agrees());
    // Mixed orientations: only --unoriented helps.
    const char* mixed = R"({"polygons": [[[0,3,2,1],[4,6,5]], [[4,5,6]]]})";
    r = check_text(d, mixed);
    EXPECT_TRUE(noted(r, "agrees with --unoriented"));
    EXPECT_FALSE(check_text(d, mixed, AnswerKind::Polygons, {.face_on_right = true}).agrees());
    // 1-based ids.
    const char* one_based = R"({"polygons": [[[1,2,3,4],[5,7,6]], [[5,6,7]]]})";
    r = check_text(d, one_based);
    EXPECT_FALSE(r.agrees());
    EXPECT_TRUE(noted(r, "agrees with --one-based"));
    EXPECT_TRUE(check_text(d, one_based, AnswerKind::Polygons, {.one_based = true}).agrees());
}

// A hole that touches its shell: the triangle 4-5-6 inside the square, its
// corner 4 on the square's corner 0 (no bridge). f1's outer cycle walks the
// square and the triangle, pinched at 0; a polygonizer gives the square with
// a hole touching it, or one self-touching shell. Both are f1.
constexpr std::string_view kPinched = R"({"vertices": [[0,0],[4,0],[4,4],[0,4],[9,9],[2,1],[1,2]],)"
                                      R"( "edges": [[0,1],[1,2],[2,3],[3,0],[0,5],[5,6],[6,0]]})";

TEST(CheckPolygons, PinchedBoundariesMeanTheirPointSets) {
    const Dcel d = reference(kPinched);
    EXPECT_TRUE(check_text(d, R"({"polygons": [[[0,1,2,3],[0,6,5]], [[0,5,6]]]})").agrees());
    EXPECT_TRUE(check_text(d, R"({"polygons": [[[0,1,2,3,0,6,5]], [[0,5,6]]]})").agrees());
    // As rings, f1 is the square: the triangle it encloses is filled in.
    EXPECT_TRUE(check_text(d, R"({"rings": [[0,1,2,3], [0,5,6]]})").agrees());
    Report r = check_text(d, R"({"rings": [[0,1,2,3,0,6,5], [0,5,6]]})");
    EXPECT_TRUE(has(r, DifferenceKind::ExtraPolygon));
    EXPECT_TRUE(has(r, DifferenceKind::MissingFace));
}

TEST(CheckRings, OneRingPerBoundedFaceInEitherDirection) {
    const Dcel d = reference(kBridged);
    EXPECT_TRUE(check_text(d, R"({"rings": [[0,1,2,3], [4,5,6]]})").agrees());
    EXPECT_TRUE(check_text(d, R"({"rings": [[3,2,1,0,3], [6,5,4]]})").agrees());
    EXPECT_TRUE(check_text(d, R"([[[0,0],[0,4],[4,4],[4,0]], [[1,1],[2,1],[1,2]]])").agrees());
    // A bare list of id lists is read as faces unless told.
    Report r = check_text(d, R"([[0,1,2,3], [4,5,6]])");
    EXPECT_FALSE(r.agrees());
    EXPECT_TRUE(noted(r, "--answer rings"));
    EXPECT_TRUE(check_text(d, R"([[0,1,2,3], [4,5,6]])", AnswerKind::Rings).agrees());
    // Missing and extra rings.
    r = check_text(d, R"({"rings": [[0,1,2,3]]})");
    ASSERT_EQ(r.differences.size(), 1U);
    EXPECT_EQ(r.differences[0].kind, DifferenceKind::MissingFace);
    r = check_text(d, R"({"rings": [[0,1,2,3], [4,5,6], [0,1,2]]})");
    EXPECT_TRUE(has(r, DifferenceKind::NotAnEdge));
}

// Nested squares: the rings are both squares whole; the polygons are the
// outer square with the inner one as its hole, and the inner square.
TEST(CheckRings, HolesAreFilledPolygonsKeepThem) {
    const Dcel d = reference(R"({"vertices": [[0,0],[9,0],[9,9],[0,9],[3,3],[6,3],[6,6],[3,6]],)"
                             R"( "edges": [[0,1],[1,2],[2,3],[3,0],[4,5],[5,6],[6,7],[7,4]]})");
    EXPECT_TRUE(check_text(d, R"({"rings": [[0,1,2,3], [4,5,6,7]]})").agrees());
    EXPECT_TRUE(check_text(d, R"({"polygons": [[[0,1,2,3],[4,7,6,5]], [[4,5,6,7]]]})").agrees());
    EXPECT_TRUE(has(check_text(d, R"({"polygons": [[[0,1,2,3]], [[4,5,6,7]]]})"), DifferenceKind::WrongHole));
}

// A dangling edge 1-4 into the triangle: polygons and rings leave it out.
TEST(CheckRegions, DanglingEdgesBoundNothing) {
    const Dcel d = reference(R"({"vertices": [[0,0],[6,0],[0,6],[9,9],[2,1]], "edges": [[0,1],[1,2],[2,0],[1,4]]})");
    EXPECT_TRUE(check_text(d, R"({"polygons": [[[0,1,2]]]})").agrees());
    EXPECT_TRUE(check_text(d, R"({"rings": [[0,1,2]]})").agrees());
    // A polygonizer that keeps the dangle in its ring (there and back) agrees too.
    EXPECT_TRUE(check_text(d, R"({"polygons": [[[0,1,4,1,2]]]})").agrees());
}

// A degenerate ring [u, v] walks a lone edge there and back: it cancels, as
// [u, v, u, v] and a there-and-back path do; a ring of one point walks
// nothing. The same answer spelled either way gets the same verdict.
TEST(CheckRegions, DegenerateRingsCancelLikeTheirLongSpellings) {
    // examples/check/graph.json, with a lone edge 8-9 inside the triangle.
    const Dcel d = reference(R"({"vertices": [[0,0],[4,0],[4,4],[0,4],[1,1],[2,1],[1,2],[5,5],[1.2,1.2],[1.4,1.2]],
        "edges": [[0,1],[1,2],[2,3],[3,0],[4,5],[5,6],[6,4],[0,4],[8,9]]})");
    for (const char* spelling :
         {R"({"polygons": [[[0,1,2,3],[5,4,6]],[[4,5,6],[8,9]]]})",
          R"({"polygons": [[[0,1,2,3],[5,4,6]],[[4,5,6],[8,9,8,9]]]})",
          R"({"polygons": [[[0,1,2,3],[5,4,6]],[[4,5,6],[9,8,9]]]})", R"({"polygons": [[[0,1,2,3],[5,4,6]],[[4,5,6],[7]]]})",
          R"({"polygons": [[[0,1,2,3],[5,4,6]],[[4,5,6],[]]]})", R"({"polygons": [[[0,1,2,3],[5,4,6]],[[4,5,6]]]})"}) {
        EXPECT_TRUE(check_text(d, spelling).agrees()) << spelling;
    }
}

// A ring of zero area has no direction to read off its area, so it means
// the walk as written, in the answer's convention: with faces on the right,
// backwards. A square with a bowtie inside: triangles 4-5-6 and 4-7-8 of
// equal area (4) touching at 4. Face f1, the square around the bowtie, is
// also the sum of the square, the figure eight [4, 5, 6, 4, 8, 7] (the
// first triangle counterclockwise, the second clockwise: no area) and the
// first triangle clockwise twice. The same answer written with faces on the
// right, every ring reversed, is f1 too.
TEST(CheckRegions, ARingWithoutAreaIsReadInTheAnswersConvention) {
    const Dcel d = reference(R"({"vertices": [[0,0],[8,0],[8,8],[0,8],[4,4],[2,6],[2,2],[6,2],[6,6]],
        "edges": [[0,1],[1,2],[2,3],[3,0],[4,5],[5,6],[6,4],[4,7],[7,8],[8,4]]})");
    const char* left = R"({"polygons": [[[0,1,2,3],[4,5,6,4,8,7],[4,6,5],[4,6,5]], [[4,5,6]], [[4,7,8]]]})";
    const char* right = R"({"polygons": [[[3,2,1,0],[7,8,4,6,5,4],[5,6,4],[5,6,4]], [[6,5,4]], [[8,7,4]]]})";
    for (const bool unoriented : {false, true}) {
        EXPECT_TRUE(check_text(d, left, AnswerKind::Polygons, {.unoriented = unoriented}).agrees());
        EXPECT_TRUE(check_text(d, right, AnswerKind::Polygons, {.face_on_right = true, .unoriented = unoriented}).agrees());
        // Read in the other convention, the figure eight runs the other way.
        EXPECT_FALSE(check_text(d, left, AnswerKind::Polygons, {.face_on_right = true, .unoriented = true}).agrees());
        EXPECT_FALSE(check_text(d, right, AnswerKind::Polygons, {.unoriented = true}).agrees());
    }
}

// A polygon that walks a half-edge twice (its hole listed twice) is no face:
// a difference, not a crash in the part that explains what a face lacks.
TEST(CheckRegions, ARingListedTwiceIsADifference) {
    const Dcel d = reference(R"({"vertices": [[0,0],[4,0],[4,4],[0,4],[1,1],[2,1],[1,2],[5,5]],
        "edges": [[0,1],[1,2],[2,3],[3,0],[4,5],[5,6],[6,4],[0,4]]})");
    const Report r = check_text(d, R"({"polygons": [[[0,1,2,3],[5,4,6],[5,4,6]],[[4,5,6]]]})");
    ASSERT_FALSE(r.agrees());
    EXPECT_TRUE(std::any_of(r.differences.begin(), r.differences.end(), [](const check::Difference& x) {
        return x.kind == check::DifferenceKind::ExtraPolygon && x.message.find("more than once") != std::string::npos;
    }));
    // Shells that overlap a face twice, and a shell listed twice in one polygon.
    EXPECT_FALSE(check_text(d, R"({"polygons": [[[0,1,2,3],[0,1,2,3]],[[4,5,6]]]})").agrees());
    EXPECT_FALSE(check_text(d, R"({"rings": [[0,1,2,3],[4,5,6],[4,5,6]]})").agrees());
}

// faces: closed cycles, 1-based ids and faces on the right.
TEST(CheckFaces, Conventions) {
    const Dcel d = reference(R"({"vertices": [[0,0],[1,0],[0,1]], "edges": [[0,1],[1,2],[2,0]]})");
    // The triangle's cycles: [0, 1, 2] inside, [1, 0, 2] outside.
    EXPECT_TRUE(check_text(d, R"({"faces": [[2,0,1], [0,2,1]]})").agrees());
    Report r = check_text(d, R"({"faces": [[0,1,2,0], [1,0,2,1]]})");
    EXPECT_TRUE(r.agrees());
    EXPECT_TRUE(noted(r, "2 cycles repeat their first vertex"));
    r = check_text(d, R"({"faces": [[1,2,3], [2,1,3]]})");
    EXPECT_TRUE(has(r, DifferenceKind::VertexCount));
    EXPECT_TRUE(noted(r, "agrees with --one-based"));
    EXPECT_TRUE(check_text(d, R"({"faces": [[1,2,3], [2,1,3]]})", AnswerKind::Faces, {.one_based = true}).agrees());
    // With a dangling edge 0-3 into the triangle the two cycles are no longer
    // each other's reversal: [0, 1, 2, 0, 3] and [1, 0, 2], walked backwards.
    const Dcel dangle = reference(R"({"vertices": [[0,0],[4,0],[0,4],[1,1]], "edges": [[0,1],[1,2],[2,0],[0,3]]})");
    const char* backwards = R"({"faces": [[0,3,0,2,1], [1,2,0]]})";
    r = check_text(dangle, backwards);
    EXPECT_TRUE(has(r, DifferenceKind::ReversedCycle));
    EXPECT_TRUE(noted(r, "agrees with --face-on right"));
    EXPECT_TRUE(check_text(dangle, backwards, AnswerKind::Faces, {.face_on_right = true}).agrees());
    // A 0 under --one-based names no vertex.
    r = check_text(d, R"({"faces": [[0,1,2]]})", AnswerKind::Faces, {.one_based = true});
    EXPECT_TRUE(has(r, DifferenceKind::VertexCount));
}

// A dump with faces on the right, written out by hand for the triangle: the
// counterclockwise cycle 0->1->2 has the unbounded face on its right, the
// clockwise one 0->2->1 the triangle.
TEST(CheckDump, FacesOnTheRightAndOneBased) {
    const Dcel d = reference(R"({"vertices": [[0,0],[1,0],[0,1]], "edges": [[0,1],[1,2],[2,0]]})");
    const std::string right = R"({"vertices": [[0,0],[1,0],[0,1]], "vertex_out": [0, 2, 4], "half_edges": [)"
                              R"({"origin": 0, "twin": 1, "next": 2, "prev": 4, "face": 0},)"
                              R"({"origin": 1, "twin": 0, "next": 5, "prev": 3, "face": 1},)"
                              R"({"origin": 1, "twin": 3, "next": 4, "prev": 0, "face": 0},)"
                              R"({"origin": 2, "twin": 2, "next": 1, "prev": 5, "face": 1},)"
                              R"({"origin": 2, "twin": 5, "next": 0, "prev": 2, "face": 0},)"
                              R"({"origin": 0, "twin": 4, "next": 3, "prev": 1, "face": 1}],)"
                              R"( "faces": [{"outer": null, "inner": [0], "isolated": []},)"
                              R"( {"outer": 1, "inner": [], "isolated": []}]})";
    Report r = check_text(d, right);
    EXPECT_FALSE(r.agrees());
    EXPECT_TRUE(noted(r, "agrees with --face-on right"));
    EXPECT_TRUE(check_text(d, right, std::nullopt, {.face_on_right = true}).agrees());
    // The same dump with every id one higher (0 is the null of 1-based code).
    const std::string one_based = R"({"vertices": [[0,0],[1,0],[0,1]], "vertex_out": [1, 3, 5], "half_edges": [)"
                                  R"({"origin": 1, "twin": 2, "next": 3, "prev": 5, "face": 1},)"
                                  R"({"origin": 2, "twin": 1, "next": 6, "prev": 4, "face": 2},)"
                                  R"({"origin": 2, "twin": 4, "next": 5, "prev": 1, "face": 1},)"
                                  R"({"origin": 3, "twin": 3, "next": 2, "prev": 6, "face": 2},)"
                                  R"({"origin": 3, "twin": 6, "next": 1, "prev": 3, "face": 1},)"
                                  R"({"origin": 1, "twin": 5, "next": 4, "prev": 2, "face": 2}],)"
                                  R"( "faces": [{"outer": 0, "inner": [1], "isolated": []},)"
                                  R"( {"outer": 2, "inner": [], "isolated": []}]})";
    EXPECT_TRUE(check_text(d, one_based, std::nullopt, {.face_on_right = true, .one_based = true}).agrees());
}

TEST(ReadAnswer, DetectsTheKindFromTheShape) {
    struct Case {
        const char* text;
        AnswerKind kind;
    };
    for (const Case& c : {
             Case{R"({"faces": []})", AnswerKind::Faces},
             Case{R"([])", AnswerKind::Faces},
             Case{R"([[0, 1]])", AnswerKind::Faces},
             Case{R"({"vertices": [], "half_edges": [], "faces": [{"outer": null}]})", AnswerKind::Dump},
             Case{R"({"polygons": []})", AnswerKind::Polygons},
             Case{R"({"type": "Polygon", "coordinates": []})", AnswerKind::Polygons},
             Case{R"([[[0, 1, 2]]])", AnswerKind::Polygons},
             Case{R"([[[[0, 0], [1, 0], [0, 1]]]])", AnswerKind::Polygons},
             Case{R"({"rings": []})", AnswerKind::Rings},
             Case{R"([[[0, 0], [1, 0], [0, 1]]])", AnswerKind::Rings},
         }) {
        const check::Answer a = check::read_answer(c.text);
        EXPECT_EQ(a.kind, c.kind) << c.text;
        EXPECT_FALSE(a.detected_from.empty()) << c.text;
    }
}

TEST(ReadAnswer, RefusesWhatFitsNoKindWithThePath) {
    auto message = [](const char* text, std::optional<AnswerKind> kind = std::nullopt) {
        try {
            (void)check::read_answer(text, kind);
        } catch (const InvalidInput& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(message(R"({"answer": 1})").find("needs a \"faces\""), std::string::npos);
    EXPECT_NE(message(R"({"type": "LineString", "coordinates": [[0, 0], [1, 1]]})")
                  .find(R"(of type "LineString" is not a polygon)"),
              std::string::npos);
    // The answer's own text is quoted and escaped, never echoed raw.
    // (Ordinary literals: in a raw literal, gcc reads \u as a universal character name.)
    EXPECT_NE(message("{\"type\": \"Poly\\u001b[31m\\ngon\\u202e\"}").find("of type \"Poly\\u001B[31m\\ngon\\u202E\""),
              std::string::npos);
    // Two answer keys: refused, not judged by one of them.
    EXPECT_NE(message(R"({"faces": [[0, 1, 2]], "rings": [[0, 1, 2]]})").find(R"(keys "faces" and "rings")"),
              std::string::npos);
    EXPECT_NE(message(R"({"faces": [], "polygons": []})", AnswerKind::Faces).find("give one of them"), std::string::npos);
    // Duplicate keys are refused in objects whose members are ignored too.
    EXPECT_NE(message(R"({"faces": [], "extra": {"a": 1, "a": 2}})").find(R"(duplicate key "a")"), std::string::npos);
    EXPECT_NE(message(R"({"polygons": [[[0, [1, 2]]]]})").find("both as vertex ids and as coordinates"), std::string::npos);
    EXPECT_NE(message(R"({"polygons": [[[[0, 0, 0, 0]]]]})").find("polygons[0][0][0]"), std::string::npos);
    EXPECT_NE(message(R"({"polygons": [{"holes": []}]})").find("missing key \"shell\""), std::string::npos);
    EXPECT_NE(message(R"([[[[[0]]]]])").find("fit no answer kind"), std::string::npos);
    EXPECT_NE(message("[[0, 1]]", AnswerKind::Polygons).find("expected"), std::string::npos);
}

}  // namespace
}  // namespace dcel
