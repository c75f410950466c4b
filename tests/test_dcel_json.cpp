// write_dump / read_dump, write_faces / read_faces_answer and read_answer:
// exact text in both dump styles, round trips, optional keys, every shape and
// id error with its JSON path. Every expected value is worked out by hand.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <string_view>
#include <variant>

#include "dcel/build.hpp"
#include "dcel/error.hpp"
#include "dcel/io/dcel_json.hpp"
#include "dcel/io/limited_readers.hpp"
#include "dcel/queries.hpp"

namespace dcel::io {
namespace {

template <class Body>
void expect_input_error(Body&& body, InputErrorKind kind, std::string_view part) {
    try {
        body();
        ADD_FAILURE() << "no error; expected " << to_string(kind) << " containing: " << part;
    } catch (const InvalidInput& e) {
        const std::string message = e.what();
        EXPECT_EQ(e.kind(), kind) << message;
        EXPECT_NE(message.find(part), std::string::npos) << "message: " << message << "\nexpected part: " << part;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
    }
}

void expect_dump_error(std::string_view text, InputErrorKind kind, std::string_view part) {
    SCOPED_TRACE(std::string(text.substr(0, 120)));
    expect_input_error([&] { static_cast<void>(read_dump(text)); }, kind, part);
}

void expect_faces_error(std::string_view text, InputErrorKind kind, std::string_view part) {
    SCOPED_TRACE(std::string(text.substr(0, 120)));
    expect_input_error([&] { static_cast<void>(read_faces_answer(text)); }, kind, part);
}

bool same_double(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

void expect_same_dump(const DcelDump& a, const DcelDump& b) {
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    for (std::size_t i = 0; i < a.vertices.size(); ++i) {
        EXPECT_TRUE(same_double(a.vertices[i].x, b.vertices[i].x)) << "vertex " << i;
        EXPECT_TRUE(same_double(a.vertices[i].y, b.vertices[i].y)) << "vertex " << i;
    }
    EXPECT_EQ(a.vertex_out, b.vertex_out);
    EXPECT_EQ(a.half_edges, b.half_edges);
    EXPECT_EQ(a.faces, b.faces);
}

std::string read_file(const std::string& path) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (f == nullptr) return {};
    std::string text;
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) text.append(buf, n);
    std::fclose(f);
    return text;
}

HalfEdgeRecord he(Index origin, Index twin, Index next, Index prev, Index face) {
    return {VertexId(origin), HalfEdgeId(twin), HalfEdgeId(next), HalfEdgeId(prev), FaceId(face)};
}

// One edge from (0, 0) to (1, 0) and an isolated vertex (0.5, 2): two
// half-edges forming one cycle, both in the unbounded face.
DcelDump segment_dump() {
    DcelDump d;
    d.vertices = {{0, 0}, {1, 0}, {0.5, 2}};
    d.vertex_out = {HalfEdgeId(0), HalfEdgeId(1), HalfEdgeId()};
    d.half_edges = {he(0, 1, 1, 1, 0), he(1, 0, 0, 0, 0)};
    d.faces = {{HalfEdgeId(), {HalfEdgeId(0)}, {VertexId(2)}}};
    return d;
}

constexpr std::string_view kSegmentLines = R"({
  "vertices": [
    [0, 0],
    [1, 0],
    [0.5, 2]
  ],
  "vertex_out": [
    0,
    1,
    null
  ],
  "half_edges": [
    {"origin": 0, "twin": 1, "next": 1, "prev": 1, "face": 0},
    {"origin": 1, "twin": 0, "next": 0, "prev": 0, "face": 0}
  ],
  "faces": [
    {"outer": null, "inner": [0], "isolated": [2]}
  ]
}
)";

constexpr std::string_view kSegmentCompact =
    R"({"vertices": [[0, 0], [1, 0], [0.5, 2]], "vertex_out": [0, 1, null], "half_edges": [{"origin": 0, "twin": 1, "next": 1, "prev": 1, "face": 0}, {"origin": 1, "twin": 0, "next": 0, "prev": 0, "face": 0}], "faces": [{"outer": null, "inner": [0], "isolated": [2]}]})"
    "\n";

// A document with `n` well-formed half-edges, then the text `last` as one more.
std::string dump_with_half_edges(int n, std::string_view last) {
    std::string text = R"({"vertices": [], "half_edges": [)";
    for (int i = 0; i < n; ++i) text += R"({"origin": 0, "twin": 0, "next": 0, "prev": 0, "face": 0}, )";
    text += last;
    text += R"(], "faces": []})";
    return text;
}

std::string dump_with_face(std::string_view face) {
    return R"({"vertices": [], "half_edges": [], "faces": [{"outer": null}, )" + std::string(face) + "]}";
}

// ------------------------------------------------------------------ writing

TEST(WriteDump, LinesStyleExactText) { EXPECT_EQ(write_dump(segment_dump()), kSegmentLines); }

TEST(WriteDump, CompactStyleExactText) { EXPECT_EQ(write_dump(segment_dump(), DumpStyle::Compact), kSegmentCompact); }

TEST(WriteDump, EmptyDump) {
    EXPECT_EQ(write_dump(DcelDump{}),
              "{\n  \"vertices\": [],\n  \"vertex_out\": [],\n  \"half_edges\": [],\n  \"faces\": []\n}\n");
    EXPECT_EQ(write_dump(DcelDump{}, DumpStyle::Compact),
              "{\"vertices\": [], \"vertex_out\": [], \"half_edges\": [], \"faces\": []}\n");
}

TEST(WriteDump, NonFiniteCoordinateIsRefused) {
    DcelDump d = segment_dump();
    d.vertices[2].y = std::numeric_limits<double>::infinity();
    expect_input_error([&] { static_cast<void>(write_dump(d)); }, InputErrorKind::BadCoordinate,
                       "vertices[2][1]: Infinity cannot be written as JSON");
}

TEST(WriteFaces, ExactText) {
    const std::vector<std::vector<VertexId>> cycles{{VertexId(0), VertexId(1), VertexId(2)},
                                                    {VertexId(0), VertexId(2), VertexId(1)}};
    EXPECT_EQ(write_faces(cycles), "{\"faces\": [[0, 1, 2], [0, 2, 1]]}\n");
    EXPECT_EQ(write_faces({}), "{\"faces\": []}\n");
    EXPECT_EQ(write_faces({{}, {VertexId(3)}, {VertexId()}}), "{\"faces\": [[], [3], [null]]}\n");
}

TEST(WriteFaces, StraightFromTheDcelMatchesTheListedCycles) {
    // A square with a diagonal, a hole segment and an isolated vertex.
    PlanarGraph g;
    g.vertices = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 2}, {2, 3}, {3, 1}};
    for (const auto& [u, v] : std::vector<std::pair<Index, Index>>{{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}, {4, 5}}) {
        g.edges.push_back({VertexId(u), VertexId(v)});
    }
    const Dcel d = build(g);
    EXPECT_EQ(write_faces_of(d), write_faces(boundary_cycles(d)));
    EXPECT_EQ(write_faces_of(build(PlanarGraph{})), "{\"faces\": []}\n");
}

// ------------------------------------------------------------- round trips

TEST(ReadDump, ReadsBothStyles) {
    expect_same_dump(read_dump(kSegmentLines), segment_dump());
    expect_same_dump(read_dump(kSegmentCompact), segment_dump());
}

TEST(ReadDump, RoundTripsSpecialNumbersAndLargeIds) {
    DcelDump d;
    d.vertices = {{-0.0, 5e-324}, {std::numeric_limits<double>::max(), 0.1}, {-1e-300, 1.0 / 3.0}};
    d.vertex_out = {HalfEdgeId(4294967294U), HalfEdgeId(), HalfEdgeId(7)};
    d.half_edges = {he(4294967294U, 1, 2, 3, 4294967294U), he(0, 0, 0, 0, 0)};
    d.faces = {{HalfEdgeId(), {}, {}},
               {HalfEdgeId(9), {HalfEdgeId(1), HalfEdgeId(2)}, {VertexId(0), VertexId(4294967294U)}}};
    for (const DumpStyle style : {DumpStyle::Lines, DumpStyle::Compact}) {
        const std::string text = write_dump(d, style);
        expect_same_dump(read_dump(text), d);
        // Writing what was read gives the same text again.
        EXPECT_EQ(write_dump(read_dump(text), style), text);
    }
}

TEST(ReadDump, DataFile) {
    const std::string text = read_file(std::string(DCEL_TEST_DATA_DIR) + "/json/square_dump.json");
    ASSERT_FALSE(text.empty());
    const DcelDump d = read_dump(text);
    ASSERT_EQ(d.vertices.size(), 4U);
    EXPECT_EQ(d.vertices[2], (Point{1, 1}));
    EXPECT_EQ(d.vertex_out, (std::vector<HalfEdgeId>{HalfEdgeId(0), HalfEdgeId(1), HalfEdgeId(3), HalfEdgeId(5)}));
    ASSERT_EQ(d.half_edges.size(), 8U);
    EXPECT_EQ(d.half_edges[0], he(0, 1, 2, 6, 1));
    EXPECT_EQ(d.half_edges[7], he(0, 6, 5, 1, 0));
    ASSERT_EQ(d.faces.size(), 2U);
    EXPECT_EQ(d.faces[0], (FaceDump{HalfEdgeId(), {HalfEdgeId(1)}, {}}));
    EXPECT_EQ(d.faces[1], (FaceDump{HalfEdgeId(0), {}, {}}));
    // The file is in the Lines style, so writing it back gives the same text.
    EXPECT_EQ(write_dump(d), text);
}

// ------------------------------------------------------- optional and unknown

TEST(ReadDump, OptionalKeysDefaultToEmpty) {
    const DcelDump d = read_dump(
        R"({"faces": [{"outer": 3}, {"outer": null, "isolated": [1]}], "half_edges": [], "vertices": [[1, 2]]})");
    EXPECT_EQ(d.vertices.size(), 1U);
    EXPECT_TRUE(d.vertex_out.empty());
    EXPECT_TRUE(d.half_edges.empty());
    ASSERT_EQ(d.faces.size(), 2U);
    EXPECT_EQ(d.faces[0], (FaceDump{HalfEdgeId(3), {}, {}}));
    EXPECT_EQ(d.faces[1], (FaceDump{HalfEdgeId(), {}, {VertexId(1)}}));
}

TEST(ReadDump, UnknownKeysAreIgnored) {
    const DcelDump d = read_dump(
        R"({"format": "dcel", "vertices": [], "half_edges": [{"face": 5, "origin": 1, "id": "h0", "twin": 2, "next": 3, "prev": 4}], "faces": [{"outer": null, "area": -1.5, "inner": []}], "extra": [[{}]]})");
    ASSERT_EQ(d.half_edges.size(), 1U);
    EXPECT_EQ(d.half_edges[0], he(1, 2, 3, 4, 5));
}

TEST(ReadDump, IdsAreNotRangeChecked) {
    // A validator reports references to missing elements; the reader keeps them.
    const DcelDump d = read_dump(
        R"({"vertices": [], "vertex_out": [99], "half_edges": [{"origin": 7, "twin": 100, "next": 4294967294, "prev": 0, "face": 3}], "faces": []})");
    EXPECT_EQ(d.vertex_out, (std::vector<HalfEdgeId>{HalfEdgeId(99)}));
    EXPECT_EQ(d.half_edges[0], he(7, 100, 4294967294U, 0, 3));
}

// ------------------------------------------------------------------- errors

TEST(ReadDumpErrors, TopLevel) {
    expect_dump_error("[]", InputErrorKind::Shape, R"(top level: expected a DCEL dump {"vertices": [[x, y], ...], )");
    expect_dump_error(
        R"({"vertices": [], "faces": []})", InputErrorKind::Shape,
        R"(missing key "half_edges": expected {"vertices": [[x, y], ...], "vertex_out": [h or null, ...], "half_edges": [{"origin": v, )");
    expect_dump_error(R"({"half_edges": [], "faces": []})", InputErrorKind::Shape, R"(missing key "vertices")");
    expect_dump_error(R"({"vertices": [], "half_edges": []})", InputErrorKind::Shape, R"(missing key "faces")");
    expect_dump_error(R"({"vertices": [], "half_edges": [], "faces": [], "faces": []})", InputErrorKind::Shape,
                      R"(top level: duplicate key "faces" at line 1, column 49)");
    expect_dump_error(R"({"vertices": [], "half_edges": [], "faces": []} {})", InputErrorKind::Syntax,
                      "line 1, column 49: unexpected content after the end of the JSON document");
    expect_dump_error("", InputErrorKind::Syntax, "line 1, column 1: empty input");
}

TEST(ReadDumpErrors, HalfEdges) {
    expect_dump_error(dump_with_half_edges(7, R"({"origin": 0, "twin": 0, "next": -1, "prev": 0, "face": 0})"),
                      InputErrorKind::BadIndex, "half_edges[7].next: half-edge id -1 is negative");
    expect_dump_error(
        dump_with_half_edges(1, R"({"origin": 0, "twin": 0, "prev": 0, "face": 0})"), InputErrorKind::Shape,
        R"(half_edges[1]: missing key "next": expected {"origin": v, "twin": h, "next": h, "prev": h, "face": f})");
    expect_dump_error(dump_with_half_edges(0, R"({"origin": 0, "twin": 0, "twin": 1, "next": 0, "prev": 0, "face": 0})"),
                      InputErrorKind::Shape,
                      R"(half_edges[0]: duplicate key "twin" at line 1, column 58: give each key once)");
    expect_dump_error(dump_with_half_edges(2, R"({"origin": 0.5, "twin": 0, "next": 0, "prev": 0, "face": 0})"),
                      InputErrorKind::BadIndex, "half_edges[2].origin: vertex id 0.5 is not an integer");
    expect_dump_error(dump_with_half_edges(0, R"({"origin": 0, "twin": 0, "next": 0, "prev": 0, "face": 4294967295})"),
                      InputErrorKind::BadIndex, "half_edges[0].face: face id 4294967295 is too large");
    expect_dump_error(dump_with_half_edges(0, R"({"origin": 0, "twin": null, "next": 0, "prev": 0, "face": 0})"),
                      InputErrorKind::Shape,
                      "half_edges[0].twin: expected a half-edge id (a non-negative integer), found null");
    expect_dump_error(dump_with_half_edges(0, R"({"origin": "0", "twin": 0, "next": 0, "prev": 0, "face": 0})"),
                      InputErrorKind::Shape,
                      "half_edges[0].origin: expected a vertex id (a non-negative integer), found a string");
    expect_dump_error(
        dump_with_half_edges(0, "[0, 1, 2, 3, 4]"), InputErrorKind::Shape,
        R"(half_edges[0]: expected a half-edge {"origin": v, "twin": h, "next": h, "prev": h, "face": f}, found an array)");
    expect_dump_error(R"({"vertices": [], "half_edges": {}, "faces": []})", InputErrorKind::Shape,
                      "half_edges: expected an array of half-edges");
}

TEST(ReadDumpErrors, VerticesAndVertexOut) {
    expect_dump_error(R"({"vertices": [[0, 0], [1]], "half_edges": [], "faces": []})", InputErrorKind::Shape,
                      "vertices[1]: expected a point [x, y], found an array of 1 element");
    expect_dump_error(R"({"vertices": [[0, -1e999]], "half_edges": [], "faces": []})", InputErrorKind::BadCoordinate,
                      "vertices[0][1]: -1e999 is beyond the range of a double");
    expect_dump_error(R"({"vertices": [], "vertex_out": [0, 1.5], "half_edges": [], "faces": []})", InputErrorKind::BadIndex,
                      "vertex_out[1]: half-edge id 1.5 is not an integer");
    expect_dump_error(R"({"vertices": [], "vertex_out": [true], "half_edges": [], "faces": []})", InputErrorKind::Shape,
                      "vertex_out[0]: expected a half-edge id (a non-negative integer) or null, found true");
    expect_dump_error(R"({"vertices": [], "vertex_out": null, "half_edges": [], "faces": []})", InputErrorKind::Shape,
                      "vertex_out: expected an array of half-edge ids or null [h, null, ...], found null");
}

TEST(ReadDumpErrors, Faces) {
    expect_dump_error(
        dump_with_face(R"({"inner": [0]})"), InputErrorKind::Shape,
        R"(faces[1]: missing key "outer": expected {"outer": h or null, "inner": [h, ...], "isolated": [v, ...]})");
    expect_dump_error(dump_with_face(R"({"outer": "x"})"), InputErrorKind::Shape,
                      "faces[1].outer: expected a half-edge id (a non-negative integer) or null, found a string");
    expect_dump_error(dump_with_face(R"({"outer": -2})"), InputErrorKind::BadIndex,
                      "faces[1].outer: half-edge id -2 is negative");
    expect_dump_error(dump_with_face(R"({"outer": 1, "inner": [0, 1, 2.5]})"), InputErrorKind::BadIndex,
                      "faces[1].inner[2]: half-edge id 2.5 is not an integer");
    expect_dump_error(dump_with_face(R"({"outer": 1, "inner": [null]})"), InputErrorKind::Shape,
                      "faces[1].inner[0]: expected a half-edge id (a non-negative integer), found null");
    expect_dump_error(dump_with_face(R"({"outer": 1, "isolated": [1e10]})"), InputErrorKind::BadIndex,
                      "faces[1].isolated[0]: vertex id 1e10 is too large");
    expect_dump_error(dump_with_face(R"({"outer": 1, "isolated": 3})"), InputErrorKind::Shape,
                      "faces[1].isolated: expected an array of vertex ids [v, ...], found a number");
    expect_dump_error(dump_with_face(R"({"outer": 1, "outer": 2})"), InputErrorKind::Shape,
                      R"(faces[1]: duplicate key "outer")");
    expect_dump_error(
        dump_with_face("[1]"), InputErrorKind::Shape,
        R"(faces[1]: expected a face {"outer": h or null, "inner": [h, ...], "isolated": [v, ...]}, found an array)");
}

TEST(ReadDumpErrors, TooLarge) {
    CountLimits limits;
    limits.vertices = 1;
    limits.half_edges = 1;
    limits.faces = 1;
    const auto read = [&](std::string_view text) { return detail::read_dump(text, limits); };
    EXPECT_NO_THROW(
        static_cast<void>(read(dump_with_half_edges(0, R"({"origin": 0, "twin": 0, "next": 0, "prev": 0, "face": 0})"))));
    expect_input_error(
        [&] {
            static_cast<void>(read(dump_with_half_edges(1, R"({"origin": 0, "twin": 0, "next": 0, "prev": 0, "face": 0})")));
        },
        InputErrorKind::TooLarge, "half_edges[1]: more than 1 half-edges: ids are 32-bit");
    expect_input_error([&] { static_cast<void>(read(R"({"vertices": [[0, 0], [1, 1]], "half_edges": [], "faces": []})")); },
                       InputErrorKind::TooLarge, "vertices[1]: more than 1 vertices");
    expect_input_error(
        [&] { static_cast<void>(read(R"({"vertices": [], "vertex_out": [0, 1], "half_edges": [], "faces": []})")); },
        InputErrorKind::TooLarge, "vertex_out[1]: more than 1 vertices");
    expect_input_error(
        [&] { static_cast<void>(read(R"({"vertices": [], "half_edges": [], "faces": [{"outer": null}, {"outer": 0}]})")); },
        InputErrorKind::TooLarge, "faces[1]: more than 1 faces");
    expect_input_error([&] { static_cast<void>(detail::read_faces_answer("[[], []]", limits)); }, InputErrorKind::TooLarge,
                       "[1]: more than 1 faces");
}

// ------------------------------------------------------------- faces answers

TEST(ReadFacesAnswer, BothForms) {
    const std::vector<std::vector<Index>> expected{{0, 1, 2}, {}, {2, 1, 0}};
    EXPECT_EQ(read_faces_answer(R"({"faces": [[0, 1, 2], [], [2, 1, 0]]})"), expected);
    EXPECT_EQ(read_faces_answer("[[0, 1, 2], [], [2, 1, 0]]"), expected);
    EXPECT_EQ(read_faces_answer(R"({"note": {"faces": 1}, "faces": [[0, 1, 2], [], [2.0, 1e0, 0]], "x": null})"), expected);
    EXPECT_TRUE(read_faces_answer("[]").empty());
    EXPECT_TRUE(read_faces_answer(R"({"faces": []})").empty());
}

TEST(ReadFacesAnswer, RoundTrip) {
    const std::vector<std::vector<VertexId>> cycles{{VertexId(4294967294U), VertexId(0)}, {}, {VertexId(5)}};
    const std::vector<std::vector<Index>> expected{{4294967294U, 0}, {}, {5}};
    EXPECT_EQ(read_faces_answer(write_faces(cycles)), expected);
}

TEST(ReadFacesAnswer, DataFile) {
    const std::string text = read_file(std::string(DCEL_TEST_DATA_DIR) + "/json/square_faces.json");
    ASSERT_FALSE(text.empty());
    EXPECT_EQ(read_faces_answer(text), (std::vector<std::vector<Index>>{{0, 1, 2, 3}, {1, 0, 3, 2}}));
}

TEST(ReadFacesAnswerErrors, ShapesAndIds) {
    expect_faces_error(R"({"faces": [[0, 1], [0, 1, -3]]})", InputErrorKind::BadIndex,
                       "faces[1][2]: vertex index -3 is negative");
    expect_faces_error("[[0, 1], [0.5]]", InputErrorKind::BadIndex, "[1][0]: vertex index 0.5 is not an integer");
    expect_faces_error(R"({"cycles": []})", InputErrorKind::Shape,
                       R"(missing key "faces": expected {"faces": [[v, ...], ...]})");
    expect_faces_error(R"({"faces": [], "faces": []})", InputErrorKind::Shape, R"(duplicate key "faces")");
    expect_faces_error(R"({"faces": [0, 1, 2]})", InputErrorKind::Shape,
                       "faces[0]: expected a face cycle [v, ...], found a number");
    expect_faces_error(R"({"faces": {}})", InputErrorKind::Shape,
                       "faces: expected an array of face cycles [[v, ...], ...], found an object");
    expect_faces_error(
        R"("faces")", InputErrorKind::Shape,
        R"(top level: expected a faces answer {"faces": [[v, ...], ...]} or [[v, ...], ...], found a string)");
    expect_faces_error("[[0, 1]", InputErrorKind::Syntax, "line 1, column 8: unexpected end of input: expected ',' or ']'");
    expect_faces_error("[[0, 1]] []", InputErrorKind::Syntax, "line 1, column 10: unexpected content after the end");
}

// ---------------------------------------------------------------- read_answer

TEST(ReadAnswer, DumpOrFaces) {
    const auto dump = read_answer(kSegmentLines);
    ASSERT_EQ(dump.index(), 1U);
    expect_same_dump(std::get<DcelDump>(dump), segment_dump());

    // "half_edges" after "faces": still a dump.
    const auto late = read_answer(R"({"faces": [{"outer": null}], "vertices": [], "half_edges": []})");
    ASSERT_EQ(late.index(), 1U);
    EXPECT_EQ(std::get<DcelDump>(late).faces.size(), 1U);

    const auto faces = read_answer(R"({"faces": [[0, 1, 2], []]})");
    ASSERT_EQ(faces.index(), 0U);
    EXPECT_EQ(std::get<0>(faces), (std::vector<std::vector<Index>>{{0, 1, 2}, {}}));

    const auto bare = read_answer("[[3, 4]]");
    ASSERT_EQ(bare.index(), 0U);
    EXPECT_EQ(std::get<0>(bare), (std::vector<std::vector<Index>>{{3, 4}}));

    // A nested "half_edges" key does not make a dump.
    const auto nested = read_answer(R"({"meta": {"half_edges": 1}, "faces": []})");
    EXPECT_EQ(nested.index(), 0U);
}

TEST(ReadAnswer, Errors) {
    const auto read = [](std::string_view text) { return [text] { static_cast<void>(read_answer(text)); }; };
    // A dump's errors are a dump reader's errors.
    expect_input_error(read(R"({"vertices": [], "half_edges": [{"origin": 0}], "faces": []})"), InputErrorKind::Shape,
                       R"(half_edges[0]: missing key "twin")");
    expect_input_error(read(R"({"vertices": [], "half_edges": []})"), InputErrorKind::Shape, R"(missing key "faces")");
    // Otherwise a faces answer's.
    expect_input_error(read(R"({"faces": [[0, "1"]]})"), InputErrorKind::Shape,
                       "faces[0][1]: expected a vertex index (a non-negative integer), found a string");
    expect_input_error(read(R"({"vertices": []})"), InputErrorKind::Shape, R"(missing key "faces")");
    expect_input_error(read("true"), InputErrorKind::Shape, "top level: expected a faces answer");
    // Syntax errors are reported wherever they are, before or after "half_edges".
    expect_input_error(read(R"({"vertices": [[0, 0]]], "half_edges": [], "faces": []})"), InputErrorKind::Syntax,
                       "line 1, column 22: unexpected character ']': expected ',' or '}' after an object member");
    expect_input_error(read(R"({"vertices": [], "half_edges": [], "faces": [}])"), InputErrorKind::Syntax,
                       "line 1, column 46: unexpected character '}': expected a JSON value");
    expect_input_error(read(""), InputErrorKind::Syntax, "line 1, column 1: empty input");
}

}  // namespace
}  // namespace dcel::io
