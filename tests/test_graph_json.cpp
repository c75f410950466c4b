// read_graph / write_graph: both input forms, every shape and value error with
// its JSON path, exact numbers (rounding, subnormals, underflow, overflow) and
// round trips. Every expected value is worked out by hand.
#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <string_view>
#include <system_error>

#include "dcel/error.hpp"
#include "dcel/io/graph_json.hpp"
#include "dcel/io/limited_readers.hpp"

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

void expect_graph_error(std::string_view text, InputErrorKind kind, std::string_view part) {
    SCOPED_TRACE(std::string(text.substr(0, 100)));
    expect_input_error([&] { static_cast<void>(read_graph(text)); }, kind, part);
}

// Bitwise equality: tells -0.0 from 0.0.
bool same_double(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

std::string read_file(const std::string& path) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (f == nullptr) return {};
    std::string text;
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) text.append(buf, n);
    std::fclose(f);
    return text;
}

// {"vertices": [[x, 0]], "edges": []} with x spelled as given.
std::string with_x(std::string_view x) { return R"({"vertices": [[)" + std::string(x) + R"(, 0]], "edges": []})"; }
double read_x(std::string_view x) {
    const PlanarGraph g = read_graph(with_x(x));
    return g.vertices.at(0).x;
}
// {"vertices": [], "edges": [[i, 0]]} with i spelled as given.
std::string with_index(std::string_view i) { return R"({"vertices": [], "edges": [[)" + std::string(i) + R"(, 0]]})"; }
Index read_u(std::string_view i) { return read_graph(with_index(i)).edges.at(0).u.index(); }

void expect_square(const PlanarGraph& g) {
    ASSERT_EQ(g.vertices.size(), 4U);
    EXPECT_EQ(g.vertices[0], (Point{0, 0}));
    EXPECT_EQ(g.vertices[1], (Point{1, 0}));
    EXPECT_EQ(g.vertices[2], (Point{1, 1}));
    EXPECT_EQ(g.vertices[3], (Point{0, 1}));
    ASSERT_EQ(g.edges.size(), 4U);
    EXPECT_EQ(g.edges[0], (GraphEdge{VertexId(0), VertexId(1)}));
    EXPECT_EQ(g.edges[1], (GraphEdge{VertexId(1), VertexId(2)}));
    EXPECT_EQ(g.edges[2], (GraphEdge{VertexId(2), VertexId(3)}));
    EXPECT_EQ(g.edges[3], (GraphEdge{VertexId(3), VertexId(0)}));
}

// --------------------------------------------------------------------- forms

TEST(ReadGraph, ObjectForm) {
    const PlanarGraph g = read_graph(R"({"vertices": [[0, 0], [1, 0.5], [-2.25, 3e2]], "edges": [[0, 1], [2, 1]]})");
    ASSERT_EQ(g.vertices.size(), 3U);
    EXPECT_EQ(g.vertices[1].x, 1.0);
    EXPECT_EQ(g.vertices[1].y, 0.5);
    EXPECT_EQ(g.vertices[2].x, -2.25);
    EXPECT_EQ(g.vertices[2].y, 300.0);
    ASSERT_EQ(g.edges.size(), 2U);
    EXPECT_EQ(g.edges[1].u.index(), 2U);
    EXPECT_EQ(g.edges[1].v.index(), 1U);
}

TEST(ReadGraph, PositionalForm) {
    const PlanarGraph g = read_graph("[[[0, 0], [1, 0.5]], [[0, 1]]]");
    ASSERT_EQ(g.vertices.size(), 2U);
    EXPECT_EQ(g.vertices[1], (Point{1, 0.5}));
    ASSERT_EQ(g.edges.size(), 1U);
    EXPECT_EQ(g.edges[0], (GraphEdge{VertexId(0), VertexId(1)}));
}

TEST(ReadGraph, EmptyGraphs) {
    const PlanarGraph a = read_graph(R"({"vertices": [], "edges": []})");
    EXPECT_TRUE(a.vertices.empty());
    EXPECT_TRUE(a.edges.empty());
    const PlanarGraph b = read_graph("[[], []]");
    EXPECT_TRUE(b.vertices.empty());
    EXPECT_TRUE(b.edges.empty());
}

TEST(ReadGraph, KeysInAnyOrderAndUnknownKeysIgnored) {
    const PlanarGraph g = read_graph(R"( { "name" : "t", "edges":[[1,0]] , "meta": {"a": [1, {"b": null}], "c": true},
        "vertices" :[ [ 5 , 6 ],[7,8] ], "z": [] } )");
    ASSERT_EQ(g.vertices.size(), 2U);
    EXPECT_EQ(g.vertices[0], (Point{5, 6}));
    EXPECT_EQ(g.vertices[1], (Point{7, 8}));
    ASSERT_EQ(g.edges.size(), 1U);
    EXPECT_EQ(g.edges[0], (GraphEdge{VertexId(1), VertexId(0)}));
}

TEST(ReadGraph, EscapedKeyMatches) {
    const PlanarGraph g = read_graph(R"({"vert\u0069ces": [[1, 2]], "\u0065dges": []})");
    ASSERT_EQ(g.vertices.size(), 1U);
}

TEST(ReadGraph, DataFiles) {
    const std::string dir = std::string(DCEL_TEST_DATA_DIR) + "/json/";
    const std::string object_form = read_file(dir + "square_graph.json");
    ASSERT_FALSE(object_form.empty());
    expect_square(read_graph(object_form));
    const std::string positional = read_file(dir + "square_graph_positional.json");
    ASSERT_FALSE(positional.empty());
    expect_square(read_graph(positional));
}

// -------------------------------------------------------------- shape errors

TEST(ReadGraphErrors, TopLevelType) {
    expect_graph_error(
        R"("graph")", InputErrorKind::Shape,
        R"(top level: expected a graph: {"vertices": [[x, y], ...], "edges": [[u, v], ...]} or [[[x, y], ...], [[u, v], ...]], found a string)");
    expect_graph_error("42", InputErrorKind::Shape, "top level: expected a graph: {");
    expect_graph_error("null", InputErrorKind::Shape, "found null");
}

TEST(ReadGraphErrors, MissingKeys) {
    expect_graph_error(R"({"vertices": [[0, 0]]})", InputErrorKind::Shape,
                       R"(missing key "edges": expected {"vertices": [[x, y], ...], "edges": [[u, v], ...]})");
    expect_graph_error(R"({"edges": []})", InputErrorKind::Shape, R"(missing key "vertices")");
    expect_graph_error("{}", InputErrorKind::Shape, R"(missing key "vertices")");
    // Keys are case sensitive.
    expect_graph_error(R"({"Vertices": [], "edges": []})", InputErrorKind::Shape, R"(missing key "vertices")");
}

TEST(ReadGraphErrors, DuplicateKey) {
    expect_graph_error(R"({"vertices": [], "edges": [], "vertices": []})", InputErrorKind::Shape,
                       R"(top level: duplicate key "vertices" at line 1, column 31: give each key once)");
    // Also when the second spelling uses an escape.
    expect_graph_error(R"({"edges": [], "vertices": [], "\u0065dges": []})", InputErrorKind::Shape,
                       R"(duplicate key "edges" at line 1, column 31)");
}

TEST(ReadGraphErrors, WrongTypes) {
    expect_graph_error(R"({"vertices": {}, "edges": []})", InputErrorKind::Shape,
                       "vertices: expected an array of points [[x, y], ...], found an object");
    expect_graph_error(R"({"vertices": [], "edges": "none"})", InputErrorKind::Shape,
                       "edges: expected an array of edges [[u, v], ...], found a string");
    expect_graph_error(R"({"vertices": [[0, 0], 5], "edges": []})", InputErrorKind::Shape,
                       "vertices[1]: expected a point [x, y], found a number");
    expect_graph_error(R"({"vertices": [[0, 0], [1, "2"]], "edges": []})", InputErrorKind::Shape,
                       "vertices[1][1]: expected a number, found a string");
    expect_graph_error(R"({"vertices": [[null, 0]], "edges": []})", InputErrorKind::Shape,
                       "vertices[0][0]: expected a number, found null");
    expect_graph_error(R"({"vertices": [[true, 0]], "edges": []})", InputErrorKind::Shape,
                       "vertices[0][0]: expected a number, found true");
    expect_graph_error(R"({"vertices": [[[0], 0]], "edges": []})", InputErrorKind::Shape,
                       "vertices[0][0]: expected a number, found an array");
    expect_graph_error(R"({"vertices": [{"x": 0, "y": 0}], "edges": []})", InputErrorKind::Shape,
                       "vertices[0]: expected a point [x, y], found an object");
    expect_graph_error(R"({"vertices": [], "edges": [[0, "1"]]})", InputErrorKind::Shape,
                       "edges[0][1]: expected a vertex index (a non-negative integer), found a string");
    expect_graph_error(R"({"vertices": [], "edges": [[0, null]]})", InputErrorKind::Shape,
                       "edges[0][1]: expected a vertex index (a non-negative integer), found null");
    expect_graph_error(R"({"vertices": [], "edges": [0, 1]})", InputErrorKind::Shape,
                       "edges[0]: expected an edge [u, v], found a number");
    expect_graph_error(R"([[[0, 0]], {}])", InputErrorKind::Shape, "[1]: expected an array of edges");
    // A malformed scalar where another type is expected is still a syntax error.
    expect_graph_error(R"({"vertices": [01], "edges": []})", InputErrorKind::Syntax, "invalid number '01'");
    expect_graph_error(R"({"vertices": ["a\q"], "edges": []})", InputErrorKind::Syntax, "invalid escape");
}

TEST(ReadGraphErrors, Arity) {
    expect_graph_error(R"({"vertices": [[0, 0], [1, 1], [1, 2, 3]], "edges": []})", InputErrorKind::Shape,
                       "vertices[2]: expected a point [x, y], found an array of 3 elements");
    expect_graph_error(R"({"vertices": [[0]], "edges": []})", InputErrorKind::Shape,
                       "vertices[0]: expected a point [x, y], found an array of 1 element");
    expect_graph_error(R"({"vertices": [[]], "edges": []})", InputErrorKind::Shape,
                       "vertices[0]: expected a point [x, y], found an empty array");
    expect_graph_error(R"({"vertices": [[0, 0, [1, [2]], {"a": 3}]], "edges": []})", InputErrorKind::Shape,
                       "vertices[0]: expected a point [x, y], found an array of 4 elements");
    expect_graph_error(R"({"vertices": [], "edges": [[0, 1], [1, 2, 3]]})", InputErrorKind::Shape,
                       "edges[1]: expected an edge [u, v], found an array of 3 elements");
    expect_graph_error(R"({"vertices": [], "edges": [[0]]})", InputErrorKind::Shape,
                       "edges[0]: expected an edge [u, v], found an array of 1 element");
    expect_graph_error(
        "[[], [], []]", InputErrorKind::Shape,
        "top level: expected a graph [vertices, edges]: [[[x, y], ...], [[u, v], ...]], found an array of 3 elements");
    expect_graph_error("[[]]", InputErrorKind::Shape, "top level: expected a graph [vertices, edges]");
    expect_graph_error("[]", InputErrorKind::Shape, "found an empty array");
    // Syntax errors in the elements being counted still come first.
    expect_graph_error(R"({"vertices": [[0, 0, 1, x]], "edges": []})", InputErrorKind::Syntax,
                       "line 1, column 25: invalid literal 'x'");
}

// -------------------------------------------------------------- index errors

TEST(ReadGraphErrors, BadIndexes) {
    expect_graph_error(with_index("0.5"), InputErrorKind::BadIndex, "edges[0][0]: vertex index 0.5 is not an integer");
    expect_graph_error(with_index("-1"), InputErrorKind::BadIndex, "edges[0][0]: vertex index -1 is negative");
    expect_graph_error(with_index("-1.0"), InputErrorKind::BadIndex, "vertex index -1.0 is negative");
    expect_graph_error(with_index("-0.5"), InputErrorKind::BadIndex, "vertex index -0.5 is negative");
    expect_graph_error(with_index("1e-5"), InputErrorKind::BadIndex, "vertex index 1e-5 is not an integer");
    expect_graph_error(with_index("4294967294.5"), InputErrorKind::BadIndex, "4294967294.5 is not an integer");
    // Closer to an integer than a double can tell: still not an integer.
    expect_graph_error(with_index("3.0000000000000000000001"), InputErrorKind::BadIndex, "is not an integer");
    expect_graph_error(with_index("4294967295"), InputErrorKind::BadIndex,
                       "edges[0][0]: vertex index 4294967295 is too large: ids are 32-bit, the largest is 4294967294");
    expect_graph_error(with_index("4294967296"), InputErrorKind::BadIndex, "is too large");
    expect_graph_error(with_index("12345678901234567890"), InputErrorKind::BadIndex, "is too large");
    expect_graph_error(with_index("1e10"), InputErrorKind::BadIndex, "vertex index 1e10 is too large");
    expect_graph_error(with_index("4.294967295e9"), InputErrorKind::BadIndex, "is too large");
    expect_graph_error(with_index("1e99999999999999999999"), InputErrorKind::BadIndex, "is too large");
    expect_graph_error(R"({"vertices": [], "edges": [[0, 1], [2, -3]]})", InputErrorKind::BadIndex,
                       "edges[1][1]: vertex index -3 is negative");
}

TEST(ReadGraph, IntegralSpellingsAreIndexes) {
    EXPECT_EQ(read_u("0"), 0U);
    EXPECT_EQ(read_u("-0"), 0U);
    EXPECT_EQ(read_u("0.0"), 0U);
    EXPECT_EQ(read_u("-0.0e5"), 0U);
    EXPECT_EQ(read_u("0e99999999999999999999"), 0U);
    EXPECT_EQ(read_u("1.0"), 1U);
    EXPECT_EQ(read_u("1e0"), 1U);
    EXPECT_EQ(read_u("1E+0"), 1U);
    EXPECT_EQ(read_u("2.5e1"), 25U);
    EXPECT_EQ(read_u("100e-2"), 1U);
    EXPECT_EQ(read_u("0.07e2"), 7U);
    EXPECT_EQ(read_u("4294967294"), 4294967294U);
    EXPECT_EQ(read_u("4294967294.000"), 4294967294U);
    EXPECT_EQ(read_u("42949672940e-1"), 4294967294U);
    EXPECT_EQ(read_u("4.294967294e9"), 4294967294U);
}

// --------------------------------------------------------------- coordinates

TEST(ReadGraph, CoordinatesRoundCorrectly) {
    EXPECT_TRUE(same_double(read_x("0.1"), 0.1));
    EXPECT_TRUE(same_double(read_x("-0"), -0.0));
    EXPECT_TRUE(same_double(read_x("-0.0e-7"), -0.0));
    EXPECT_TRUE(same_double(read_x("1.7976931348623157e308"), std::numeric_limits<double>::max()));
    // Halfway between DBL_MAX and 2^1024 is 1.797693134862315807937...e308.
    EXPECT_TRUE(same_double(read_x("1.7976931348623158e308"), std::numeric_limits<double>::max()));
    EXPECT_TRUE(same_double(read_x("2.2250738585072014e-308"), std::numeric_limits<double>::min()));
    // 2^-1074 = 4.9406564584124654e-324 is the smallest subnormal.
    const double tiny = std::numeric_limits<double>::denorm_min();
    EXPECT_TRUE(same_double(read_x("4.9e-324"), tiny));
    EXPECT_TRUE(same_double(read_x("5e-324"), tiny));
    EXPECT_TRUE(same_double(read_x("-5e-324"), -tiny));
    EXPECT_TRUE(same_double(read_x("1e-323"), 2 * tiny));  // 1e-323 / 2^-1074 = 2.02...
    EXPECT_TRUE(same_double(read_x("2.2250738585072009e-308"), std::numeric_limits<double>::min() - tiny));
    // Half of the smallest subnormal is 2.4703282292062327208...e-324: just
    // above rounds up to it, just below rounds to zero.
    EXPECT_TRUE(same_double(read_x("2.4703282292062328e-324"), tiny));
    EXPECT_TRUE(same_double(read_x("2.4703282292062327e-324"), 0.0));
    // Underflow rounds to a zero of the right sign.
    EXPECT_TRUE(same_double(read_x("1e-400"), 0.0));
    EXPECT_TRUE(same_double(read_x("-1e-400"), -0.0));
    EXPECT_TRUE(same_double(read_x("1e-99999999999999999999"), 0.0));
    EXPECT_TRUE(same_double(read_x("-123.456e-99999"), -0.0));
    // Many digits, exponent far from the value's magnitude.
    EXPECT_TRUE(same_double(read_x("0." + std::string(399, '0') + "1e400"), 1.0));
    EXPECT_TRUE(same_double(read_x("1" + std::string(400, '0') + "e-400"), 1.0));
    EXPECT_TRUE(same_double(read_x("0." + std::string(500, '0') + "1"), 0.0));
    EXPECT_TRUE(same_double(read_x("9007199254740993"), 9007199254740992.0));  // 2^53 + 1: a tie, to even
    EXPECT_TRUE(same_double(read_x("9007199254740995"), 9007199254740996.0));  // 2^53 + 3: a tie, to even
}

// The reader converts short decimals itself (an exact integer divided by an
// exact power of ten) and longer ones with std::from_chars; both must give the
// correctly rounded double, which from_chars (libstdc++ >= 12) is the oracle for.
TEST(ReadGraph, ShortDecimalsAgreeWithFromChars) {
    std::mt19937_64 rng(7);
    for (int round = 0; round < 200000; ++round) {
        std::string s = rng() % 2 ? "-" : "";
        const int int_digits = 1 + static_cast<int>(rng() % 10);
        const int frac_digits = static_cast<int>(rng() % 12);
        for (int i = 0; i < int_digits; ++i)
            s += static_cast<char>('0' + (i == 0 && int_digits > 1 ? 1 + rng() % 9 : rng() % 10));
        if (frac_digits > 0) {
            s += '.';
            for (int i = 0; i < frac_digits; ++i) s += static_cast<char>('0' + rng() % 10);
        }
        double expected = 0;
        const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), expected);
        ASSERT_EQ(ec, std::errc()) << s;
        ASSERT_TRUE(same_double(read_x(s), expected)) << s;
    }
}

TEST(ReadGraphErrors, CoordinatesBeyondDoubleRange) {
    expect_graph_error(R"({"vertices": [[0, 0], [1e400, 0]], "edges": []})", InputErrorKind::BadCoordinate,
                       "vertices[1][0]: 1e400 is beyond the range of a double");
    expect_graph_error(with_x("-1e400"), InputErrorKind::BadCoordinate, "vertices[0][0]: -1e400 is beyond the range");
    expect_graph_error(with_x("1.7976931348623159e308"), InputErrorKind::BadCoordinate, "is beyond the range of a double");
    expect_graph_error(with_x("1e99999999999999999999"), InputErrorKind::BadCoordinate, "beyond the range");
    // The literal is cut to 40 characters in the message.
    expect_graph_error(with_x("1" + std::string(400, '0')), InputErrorKind::BadCoordinate,
                       "vertices[0][0]: 1" + std::string(39, '0') + "... is beyond the range");
    expect_graph_error(with_x("0." + std::string(100, '0') + "1e500"), InputErrorKind::BadCoordinate, "beyond the range");
}

// ---------------------------------------------------------------- TooLarge

TEST(ReadGraphErrors, TooLarge) {
    CountLimits limits;
    limits.vertices = 2;
    limits.edges = 1;
    EXPECT_NO_THROW(static_cast<void>(detail::read_graph(R"({"vertices": [[0, 0], [1, 1]], "edges": [[0, 1]]})", limits)));
    expect_input_error(
        [&] { static_cast<void>(detail::read_graph(R"({"vertices": [[0, 0], [1, 1], [2, 2]], "edges": []})", limits)); },
        InputErrorKind::TooLarge, "vertices[2]: more than 2 vertices: vertex ids are 32-bit");
    expect_input_error([&] { static_cast<void>(detail::read_graph("[[], [[0, 1], [1, 0]]]", limits)); },
                       InputErrorKind::TooLarge, "[1][1]: more than 1 edges: each edge takes two 32-bit half-edge ids");
    // The defaults are what 32-bit ids can name.
    EXPECT_EQ(CountLimits{}.vertices, 4294967295U);
    EXPECT_EQ(CountLimits{}.edges, 2147483647U);
}

// -------------------------------------------------------------- write_graph

TEST(WriteGraph, ExactText) {
    PlanarGraph g;
    g.vertices = {{0, 0}, {1, 0.5}};
    g.edges = {{VertexId(0), VertexId(1)}};
    EXPECT_EQ(write_graph(g), "{\"vertices\": [[0, 0], [1, 0.5]], \"edges\": [[0, 1]]}\n");
    EXPECT_EQ(write_graph(PlanarGraph{}), "{\"vertices\": [], \"edges\": []}\n");
}

TEST(WriteGraph, ShortestRoundTripNumbers) {
    PlanarGraph g;
    g.vertices = {{-0.0, 0.1},
                  {5e-324, std::numeric_limits<double>::max()},
                  {1e20, -1.5e-300},
                  {123456.789, 2.5},
                  {1.0 / 3.0, 4294967296.0}};
    g.edges = {{VertexId(4294967294U), VertexId(3)}};
    const std::string text = write_graph(g);
    EXPECT_EQ(text,
              "{\"vertices\": [[-0, 0.1], [5e-324, 1.7976931348623157e+308], [1e+20, -1.5e-300], [123456.789, 2.5], "
              "[0.3333333333333333, 4294967296]], \"edges\": [[4294967294, 3]]}\n");
    const PlanarGraph back = read_graph(text);
    ASSERT_EQ(back.vertices.size(), g.vertices.size());
    for (std::size_t i = 0; i < g.vertices.size(); ++i) {
        EXPECT_TRUE(same_double(back.vertices[i].x, g.vertices[i].x)) << i;
        EXPECT_TRUE(same_double(back.vertices[i].y, g.vertices[i].y)) << i;
    }
    EXPECT_EQ(back.edges, g.edges);
}

TEST(WriteGraph, NullIdIsWrittenAsNullAndRejectedOnRead) {
    PlanarGraph g;
    g.edges = {{VertexId(), VertexId(0)}};
    const std::string text = write_graph(g);
    EXPECT_EQ(text, "{\"vertices\": [], \"edges\": [[null, 0]]}\n");
    expect_graph_error(text, InputErrorKind::Shape,
                       "edges[0][0]: expected a vertex index (a non-negative integer), found null");
}

TEST(WriteGraph, NonFiniteCoordinatesAreRefused) {
    PlanarGraph g;
    g.vertices = {{0, 0}, {1, std::numeric_limits<double>::quiet_NaN()}};
    expect_input_error([&] { static_cast<void>(write_graph(g)); }, InputErrorKind::BadCoordinate,
                       "vertices[1][1]: NaN cannot be written as JSON");
    g.vertices = {{-std::numeric_limits<double>::infinity(), 0}};
    expect_input_error([&] { static_cast<void>(write_graph(g)); }, InputErrorKind::BadCoordinate,
                       "vertices[0][0]: -Infinity cannot be written as JSON");
}

// ------------------------------------------------------------------- large

// 200k vertices on a line, x = i, y = i / 2 (exact in decimal and binary), and
// the path edges [i, i + 1]; written by hand, not by write_graph.
TEST(ReadGraph, LargeDocument) {
    constexpr int kN = 200000;
    std::string text = "{\"vertices\": [";
    char buf[64];
    for (int i = 0; i < kN; ++i) {
        const int len = std::snprintf(buf, sizeof buf, "%s[%d, %d%s]", i == 0 ? "" : ", ", i, i / 2, i % 2 ? ".5" : "");
        text.append(buf, static_cast<std::size_t>(len));
    }
    text += "],\n\"edges\": [";
    for (int i = 0; i + 1 < kN; ++i) {
        const int len = std::snprintf(buf, sizeof buf, "%s[%d, %d]", i == 0 ? "" : ",\n", i, i + 1);
        text.append(buf, static_cast<std::size_t>(len));
    }
    text += "]}";
    const PlanarGraph g = read_graph(text);
    ASSERT_EQ(g.vertices.size(), static_cast<std::size_t>(kN));
    ASSERT_EQ(g.edges.size(), static_cast<std::size_t>(kN - 1));
    for (int i = 0; i < kN; ++i) {
        ASSERT_EQ(g.vertices[static_cast<std::size_t>(i)].x, static_cast<double>(i)) << i;
        ASSERT_EQ(g.vertices[static_cast<std::size_t>(i)].y, i * 0.5) << i;
    }
    for (int i = 0; i + 1 < kN; ++i) {
        ASSERT_EQ(g.edges[static_cast<std::size_t>(i)].u.index(), static_cast<Index>(i));
        ASSERT_EQ(g.edges[static_cast<std::size_t>(i)].v.index(), static_cast<Index>(i + 1));
    }
    // An error deep in it names the line: edge k is on line 2 + k.
    text.replace(text.rfind("[199997, 199998]"), 16, "[199997, 1.5]");
    expect_graph_error(text, InputErrorKind::BadIndex, "edges[199997][1]: vertex index 1.5 is not an integer");
    text.replace(text.rfind("[199997, 1.5]"), 13, "[199997 199998]");
    expect_graph_error(text, InputErrorKind::Syntax,
                       "line 199999, column 9: unexpected character '1': expected ',' or ']' after an array element");
}

// Writing a large graph (many buffer flushes) gives exactly the text built by
// hand in the same format.
TEST(WriteGraph, LargeDocument) {
    constexpr int kN = 100000;
    PlanarGraph g;
    std::string expected = "{\"vertices\": [";
    char buf[64];
    for (int i = 0; i < kN; ++i) {
        g.vertices.push_back({static_cast<double>(i), -i * 0.25});
        // -i/4 is exact; its shortest form has 0, 2 or 1 fraction digits (.0 omitted).
        const char* frac[] = {"", ".25", ".5", ".75"};
        const int len = std::snprintf(buf, sizeof buf, "%s[%d, %s%d%s]", i == 0 ? "" : ", ", i, i == 0 ? "" : "-", i / 4,
                                      frac[i % 4]);
        expected.append(buf, static_cast<std::size_t>(len));
    }
    expected += "], \"edges\": [";
    for (int i = 0; i + 1 < kN; ++i) {
        g.edges.push_back({VertexId(static_cast<Index>(i)), VertexId(static_cast<Index>(i + 1))});
        const int len = std::snprintf(buf, sizeof buf, "%s[%d, %d]", i == 0 ? "" : ", ", i, i + 1);
        expected.append(buf, static_cast<std::size_t>(len));
    }
    expected += "]}\n";
    EXPECT_EQ(write_graph(g), expected);
}

}  // namespace
}  // namespace dcel::io
