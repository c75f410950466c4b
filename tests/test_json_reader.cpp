// JsonReader: the strict JSON pull parser under the dcel readers. Syntax
// errors are checked here, mostly through read_graph (the public entry point);
// each assertion names the error kind and a piece of the message that includes
// the location. Every expected value is worked out by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <random>
#include <string>
#include <string_view>

#include "dcel/error.hpp"
#include "dcel/io/dcel_json.hpp"
#include "dcel/io/graph_json.hpp"
#include "dcel/io/json_reader.hpp"
#include "dcel/io/json_writer.hpp"

namespace dcel::io {
namespace {

// Runs `body`, which must throw InvalidInput of `kind` whose one-line message
// contains `part`.
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

void expect_syntax(std::string_view text, std::string_view part) {
    SCOPED_TRACE(std::string(text.substr(0, 80)));
    expect_input_error([&] { static_cast<void>(read_graph(text)); }, InputErrorKind::Syntax, part);
}

// A graph document with one coordinate spelled `x`: {"vertices": [[x, 0]], "edges": []}.
// The coordinate starts at column 16.
std::string with_coordinate(std::string_view x) { return R"({"vertices": [[)" + std::string(x) + R"(, 0]], "edges": []})"; }

// ------------------------------------------------------------------ reader API

TEST(JsonReader, WalksArraysObjectsAndScalars) {
    JsonReader r(R"( {"a": [1, 2.5, null], "b": {"c": true}, "d": "x"} )");
    ASSERT_EQ(r.peek(), JsonType::Object);
    r.begin_object("an object");
    ASSERT_TRUE(r.next_member());
    EXPECT_EQ(r.key(), "a");
    r.begin_array("an array");
    ASSERT_TRUE(r.next_element());
    EXPECT_EQ(r.read_index("index"), 1U);
    ASSERT_TRUE(r.next_element());
    EXPECT_EQ(r.path(), "a[1]");
    EXPECT_EQ(r.read_double(), 2.5);
    ASSERT_TRUE(r.next_element());
    EXPECT_EQ(r.read_index_or_null("index"), kNoIndex);
    EXPECT_FALSE(r.next_element());
    EXPECT_EQ(r.path(), "a");
    ASSERT_TRUE(r.next_member());
    EXPECT_EQ(r.key(), "b");
    EXPECT_EQ(r.peek(), JsonType::Object);
    r.skip_value();
    ASSERT_TRUE(r.next_member());
    EXPECT_EQ(r.key(), "d");
    EXPECT_EQ(r.peek(), JsonType::String);
    r.skip_value();
    EXPECT_FALSE(r.next_member());
    EXPECT_EQ(r.path(), "");
    r.end_document();
}

TEST(JsonReader, PeekReportsEveryType) {
    const std::array<std::pair<const char*, JsonType>, 8> cases{{
        {"null", JsonType::Null},
        {"true", JsonType::True},
        {"false", JsonType::False},
        {"-1", JsonType::Number},
        {"0", JsonType::Number},
        {"\"s\"", JsonType::String},
        {"[]", JsonType::Array},
        {"{}", JsonType::Object},
    }};
    for (const auto& [text, type] : cases) {
        JsonReader r(text);
        EXPECT_EQ(r.peek(), type) << text;
        r.skip_value();
        r.end_document();
    }
}

TEST(JsonReader, KnownMembersSkipUnknownOnes) {
    JsonReader r(R"({"zzz": [[1, {"q": [2]}], "s"], "b": 2, "other": null, "a": 1})");
    static constexpr std::array<std::string_view, 2> kKeys{"a", "b"};
    r.begin_object("an object");
    std::uint64_t seen = 0;
    EXPECT_EQ(r.next_known_member(kKeys, seen), 1);
    EXPECT_EQ(r.read_index("b"), 2U);
    EXPECT_EQ(r.next_known_member(kKeys, seen), 0);
    EXPECT_EQ(r.read_index("a"), 1U);
    EXPECT_EQ(r.next_known_member(kKeys, seen), -1);
    EXPECT_EQ(seen, 3U);
    r.end_document();
}

TEST(JsonReader, FinishArrayCountsAllElements) {
    JsonReader r("[1, [2, 3], {\"k\": 4}, 5]");
    r.begin_array("an array");
    ASSERT_TRUE(r.next_element());
    r.skip_value();
    EXPECT_EQ(r.finish_array(), 4U);
    r.end_document();
}

TEST(JsonReader, NumberTextIsTheLiteralAsWritten) {
    JsonReader r(R"([18446744073709551615, -0.0, 5e-324, "x"])");
    r.begin_array("an array");
    ASSERT_TRUE(r.next_element());
    EXPECT_EQ(r.read_number_text(), "18446744073709551615");  // beyond a double's integers
    ASSERT_TRUE(r.next_element());
    EXPECT_EQ(r.read_number_text(), "-0.0");
    ASSERT_TRUE(r.next_element());
    EXPECT_EQ(r.read_number_text(), "5e-324");
    ASSERT_TRUE(r.next_element());
    expect_input_error([&] { static_cast<void>(r.read_number_text("a seed")); }, InputErrorKind::Shape,
                       "[3]: expected a seed, found a string");
    JsonReader bad("[1.]");
    bad.begin_array("an array");
    ASSERT_TRUE(bad.next_element());
    expect_input_error([&] { static_cast<void>(bad.read_number_text()); }, InputErrorKind::Syntax,
                       "a digit must follow the decimal point");
}

TEST(JsonReader, EscapedKeysAreUnescaped) {
    JsonReader r(R"({"a\"b\\c\/d\b\f\n\r\t\u00e9\u20AC\uD83D\uDE00": 0})");
    r.begin_object("an object");
    ASSERT_TRUE(r.next_member());
    // U+00E9 = C3 A9, U+20AC = E2 82 AC, U+1F600 = F0 9F 98 80.
    EXPECT_EQ(r.key(), "a\"b\\c/d\b\f\n\r\t\xC3\xA9\xE2\x82\xAC\xF0\x9F\x98\x80");
    r.skip_value();
    EXPECT_FALSE(r.next_member());
}

TEST(JsonReader, PathsQuoteKeysThatAreNotIdentifiers) {
    JsonReader r(R"({"a b": [{"x.y": [7]}]})");
    r.begin_object("o");
    ASSERT_TRUE(r.next_member());
    r.begin_array("a");
    ASSERT_TRUE(r.next_element());
    r.begin_object("o");
    ASSERT_TRUE(r.next_member());
    r.begin_array("a");
    ASSERT_TRUE(r.next_element());
    EXPECT_EQ(r.path(), R"(["a b"][0]["x.y"][0])");
    EXPECT_EQ(r.path(2), R"(["a b"][0])");
}

TEST(JsonReader, PathsEscapeQuotesAndControlCharactersInKeys) {
    // The key is a"b<U+0001>c<DEL>: shown as JSON would spell it.
    JsonReader r("{\"a\\\"b\\u0001c\x7f\": [7]}");
    r.begin_object("o");
    ASSERT_TRUE(r.next_member());
    r.begin_array("a");
    ASSERT_TRUE(r.next_element());
    EXPECT_EQ(r.path(), "[\"a\\\"b\\u0001c\\u007F\"][0]");  // JSON allows either case of hex digit
}

TEST(JsonReader, TypeErrorsNameWhatWasFound) {
    expect_input_error([] { static_cast<void>(read_graph(R"({"vertices": false, "edges": []})")); }, InputErrorKind::Shape,
                       "vertices: expected an array of points [[x, y], ...], found false");
    expect_input_error([] { static_cast<void>(read_graph(R"({"vertices": true, "edges": []})")); }, InputErrorKind::Shape,
                       "found true");
    expect_input_error([] { static_cast<void>(read_graph(R"({"vertices": null, "edges": []})")); }, InputErrorKind::Shape,
                       "found null");
}

TEST(JsonWriter, PiecesLargerThanItsBufferGoStraightThrough) {
    // The buffer holds 16 KiB: a 40000-byte piece between two short ones must
    // come out whole and in order.
    std::string out;
    const std::string big(40000, 'x');
    {
        JsonWriter w(out);
        w.raw("[\"");
        w.raw(std::string_view(big));
        w.raw("\"]");
        w.flush();
    }
    EXPECT_EQ(out, "[\"" + big + "\"]");
}

TEST(JsonReader, RawUtf8InStringsIsAccepted) {
    // 2-, 3- and 4-byte sequences at the edges of the valid ranges.
    JsonReader r("[\"\xC2\x80 \xDF\xBF \xE0\xA0\x80 \xED\x9F\xBF \xEE\x80\x80 \xF0\x90\x80\x80 \xF4\x8F\xBF\xBF\"]");
    r.skip_value();
    r.end_document();
}

// ------------------------------------------------------------ document level

TEST(JsonSyntax, EmptyInput) {
    expect_syntax("", "line 1, column 1: empty input: expected a JSON document");
    expect_syntax(" \n\t ", "line 2, column 3: empty input");
    expect_syntax("\xEF\xBB\xBF", "line 1, column 1: empty input");
}

TEST(JsonSyntax, ByteOrderMarkIsSkipped) {
    const PlanarGraph g = read_graph("\xEF\xBB\xBF{\"vertices\": [[1, 2]], \"edges\": []}");
    ASSERT_EQ(g.vertices.size(), 1U);
    EXPECT_EQ(g.vertices[0].x, 1.0);
    EXPECT_EQ(g.vertices[0].y, 2.0);
    // Columns count from after the BOM.
    expect_syntax("\xEF\xBB\xBF[x]", "line 1, column 2: invalid literal 'x'");
}

TEST(JsonSyntax, TrailingContent) {
    expect_syntax(R"({"vertices": [], "edges": []} x)",
                  "line 1, column 31: unexpected content after the end of the JSON document (character 'x')");
    expect_syntax("[[], []]\n[]", "line 2, column 1: unexpected content after the end of the JSON document");
    expect_syntax("[[], []],", "line 1, column 9: unexpected content");
}

TEST(JsonSyntax, TruncatedDocument) {
    expect_syntax(R"({"vertices": [[0, 1])",
                  "line 1, column 21: unexpected end of input: expected ',' or ']' (is the document truncated?)");
    expect_syntax(R"({"vertices": [[0, 1]], )", "line 1, column 24: unexpected end of input: expected a key");
    expect_syntax(R"({"vertices")", "line 1, column 12: unexpected end of input: expected ':'");
    expect_syntax(R"({"vertices": )", "line 1, column 14: unexpected end of input: expected a JSON value");
    expect_syntax("[", "line 1, column 2: unexpected end of input: expected a value or ']'");
    expect_syntax("{", "line 1, column 2: unexpected end of input: expected a key in double quotes or '}'");
    expect_syntax("[[[0, 0]], [[0, 1]]", "line 1, column 20: unexpected end of input: expected ',' or ']'");
}

TEST(JsonSyntax, LinesAndColumns) {
    expect_syntax("{\n  \"vertices\": [\n    [0, 0],\n    [1, oops]\n  ],\n  \"edges\": []\n}",
                  "line 4, column 9: invalid literal 'oops'");
    // CRLF line ends count once.
    expect_syntax("{\r\n\"vertices\": [\r\n[1, ?]]}", "line 3, column 5: unexpected character '?'");
    // Columns count characters, not bytes: "é" is two bytes.
    expect_syntax("{\"\xC3\xA9\": x}", "line 1, column 7: invalid literal 'x'");
}

TEST(JsonSyntax, DataFileTruncated) {
    const std::string path = std::string(DCEL_TEST_DATA_DIR) + "/json/truncated_graph.json";
    std::FILE* f = std::fopen(path.c_str(), "rb");
    ASSERT_NE(f, nullptr) << path;
    std::string text;
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) text.append(buf, n);
    std::fclose(f);
    expect_syntax(text, "line 5, column 1: unexpected end of input: expected a JSON value (is the document truncated?)");
}

// ------------------------------------------------------------------ literals

TEST(JsonSyntax, NaNAndInfinity) {
    expect_syntax(with_coordinate("NaN"),
                  "line 1, column 16: invalid literal 'NaN': JSON has no NaN or Infinity; coordinates must be finite "
                  "numbers");
    expect_syntax(with_coordinate("Infinity"), "line 1, column 16: invalid literal 'Infinity': JSON has no NaN");
    expect_syntax(with_coordinate("-Infinity"), "line 1, column 16: invalid literal '-Infinity': JSON has no NaN");
    expect_syntax(with_coordinate("nan"), "line 1, column 16: invalid literal 'nan': JSON has no NaN");
    expect_syntax(with_coordinate("inf"), "line 1, column 16: invalid literal 'inf': JSON has no NaN");
    expect_syntax(with_coordinate("+inf"), "line 1, column 16: invalid literal '+inf': JSON has no NaN");
}

TEST(JsonSyntax, BadLiterals) {
    expect_syntax(with_coordinate("True"), "line 1, column 16: invalid literal 'True': JSON literals are lowercase");
    expect_syntax(with_coordinate("NULL"), "invalid literal 'NULL': JSON literals are lowercase");
    expect_syntax(with_coordinate("nul"), "line 1, column 16: invalid literal 'nul'");
    expect_syntax(with_coordinate("nullx"), "line 1, column 16: invalid literal 'nullx'");
    expect_syntax(with_coordinate("truefalse"), "invalid literal 'truefalse'");
    expect_syntax(with_coordinate("undefined"), "line 1, column 16: invalid literal 'undefined'");
    expect_syntax(with_coordinate("'1'"),
                  "line 1, column 16: unexpected single quote: JSON strings are written in double quotes");
    expect_syntax(with_coordinate("/* c */ 1"), "line 1, column 16: unexpected '/': JSON has no comments");
    expect_syntax(with_coordinate("\x01"), "line 1, column 16: unexpected control character U+0001: expected a JSON value");
    expect_syntax(with_coordinate("\xC3\xA9"), "line 1, column 16: unexpected character U+00E9");
    expect_syntax(with_coordinate("\xFF"), "line 1, column 16: unexpected byte 0xFF (not valid UTF-8)");
    expect_syntax(with_coordinate("\f1"), "line 1, column 16: unexpected control character U+000C");
}

TEST(JsonSyntax, LongWordsAreCutInMessages) {
    const std::string word(1000, 'z');
    try {
        static_cast<void>(read_graph(with_coordinate(word)));
        FAIL();
    } catch (const InvalidInput& e) {
        EXPECT_LT(std::string(e.what()).size(), 200U);
        EXPECT_NE(std::string(e.what()).find("zzz...'"), std::string::npos) << e.what();
    }
}

// ------------------------------------------------------------------- numbers

TEST(JsonSyntax, NumberGrammar) {
    expect_syntax(with_coordinate("01"), "line 1, column 16: invalid number '01': leading zeros are not allowed");
    expect_syntax(with_coordinate("-01"), "line 1, column 16: invalid number '-01': leading zeros");
    expect_syntax(with_coordinate("00.5"), "invalid number '00.5': leading zeros");
    expect_syntax(with_coordinate("+1"), "line 1, column 16: invalid number '+1': JSON numbers have no '+' sign");
    expect_syntax(with_coordinate(".5"), "line 1, column 16: invalid number '.5': write a digit before the decimal point");
    expect_syntax(with_coordinate("-.5"), "line 1, column 16: invalid number '-.5': write a digit before the decimal");
    expect_syntax(with_coordinate("1."), "line 1, column 16: invalid number '1.': a digit must follow the decimal point");
    expect_syntax(with_coordinate("1.e5"), "invalid number '1.e5': a digit must follow the decimal point");
    expect_syntax(with_coordinate("1e"), "line 1, column 16: invalid number '1e': the exponent has no digits");
    expect_syntax(with_coordinate("1e+"), "invalid number '1e+': the exponent has no digits");
    expect_syntax(with_coordinate("1E-"), "invalid number '1E-': the exponent has no digits");
    expect_syntax(with_coordinate("0x1F"), "line 1, column 16: invalid number '0x1F': hexadecimal numbers are not allowed");
    expect_syntax(with_coordinate("-0X1"), "invalid number '-0X1': hexadecimal");
    expect_syntax(with_coordinate("-"), "line 1, column 16: invalid number '-': a minus sign must be followed by a digit");
    expect_syntax(with_coordinate("--1"), "invalid number '--1': a minus sign must be followed by a digit");
    expect_syntax(with_coordinate("1.5.3"), "line 1, column 16: invalid number '1.5.3'");
    expect_syntax(with_coordinate("1e5e3"), "invalid number '1e5e3'");
    expect_syntax(with_coordinate("12abc"), "invalid number '12abc'");
    expect_syntax(with_coordinate("1_000"), "invalid number '1_000'");
}

TEST(JsonSyntax, ValidNumberSpellings) {
    const PlanarGraph g = read_graph(
        R"({"vertices": [[-0, 0e0], [1E5, 1e-5], [0.000, 1.5E+3], [-12.25e-1, 10e+00], [123456789012345678901234567890, 0]], "edges": []})");
    ASSERT_EQ(g.vertices.size(), 5U);
    EXPECT_EQ(g.vertices[0].x, 0.0);
    EXPECT_TRUE(std::signbit(g.vertices[0].x));
    EXPECT_EQ(g.vertices[0].y, 0.0);
    EXPECT_EQ(g.vertices[1].x, 100000.0);
    EXPECT_EQ(g.vertices[1].y, 0.00001);
    EXPECT_EQ(g.vertices[2].x, 0.0);
    EXPECT_EQ(g.vertices[2].y, 1500.0);
    EXPECT_EQ(g.vertices[3].x, -1.225);
    EXPECT_EQ(g.vertices[3].y, 10.0);
    EXPECT_EQ(g.vertices[4].x, 123456789012345678901234567890.0);
}

// ------------------------------------------------------------------- strings

TEST(JsonSyntax, Strings) {
    expect_syntax(R"({"vertices": [], "edges": [], "a\x": 1})",
                  "line 1, column 33: invalid escape '\\x' in a string: the escapes are \\\" \\\\ \\/ \\b");
    expect_syntax("{\"vertices\": [], \"edges\": [], \"a\\\x01\": 1}",
                  "line 1, column 33: invalid escape '\\' followed by control character U+0001 in a string");
    expect_syntax(R"({"vertices": [], "edges": [], "\u12G4": 1})",
                  "line 1, column 32: invalid escape in a string: \\u must be followed by 4 hex digits");
    expect_syntax(R"({"vertices": [], "edges": [], "\u12": 1})", "line 1, column 32: invalid escape in a string");
    expect_syntax(R"({"vertices": [], "edges": [], "\uD800": 1})",
                  "line 1, column 32: unpaired surrogate '\\uD800' in a string: a high surrogate must be followed");
    expect_syntax(R"({"vertices": [], "edges": [], "\uD800\u0041": 1})", "unpaired surrogate '\\uD800'");
    expect_syntax(R"({"vertices": [], "edges": [], "\uDC00": 1})",
                  "line 1, column 32: unpaired surrogate '\\uDC00' in a string: a low surrogate must follow a high one");
    expect_syntax("{\"vertices\": [], \"edges\": [], \"a\tb\": 1}",
                  "line 1, column 33: control character U+0009 in a string: escape it as \\t");
    expect_syntax(
        "{\"vertices\": [], \"edges\": [], \"ab\n\": 1}",
        "line 1, column 34: control character U+000A in a string: escape it as \\n (or is a closing '\"' missing?)");
    expect_syntax("{\"vertices\": [], \"edges\": [], \"a\rb\": 1}",
                  "line 1, column 33: control character U+000D in a string: escape it as \\r");
    expect_syntax("{\"vertices\": [], \"edges\": [], \"a\bb\": 1}",
                  "line 1, column 33: control character U+0008 in a string: escape it as \\b");
    expect_syntax("{\"vertices\": [], \"edges\": [], \"a\fb\": 1}",
                  "line 1, column 33: control character U+000C in a string: escape it as \\f");
    expect_syntax(std::string("{\"vertices\": [], \"edges\": [], \"a\0\": 1}", 38),
                  "line 1, column 33: control character U+0000 in a string: escape it as \\u0000");
    expect_syntax(R"({"vertices": [], "edges": [], "abc)",
                  "line 1, column 31: unterminated string: no closing '\"' before the end of input");
    expect_syntax(R"({"vertices": [], "edges": [], "abc\)", "line 1, column 31: unterminated string");
}

TEST(JsonSyntax, InvalidUtf8) {
    const auto key = [](std::string_view bytes) {
        return "{\"vertices\": [], \"edges\": [], \"" + std::string(bytes) + "\": 1}";
    };
    // The key starts at column 32.
    expect_syntax(key("\xFF"), "line 1, column 32: invalid UTF-8 in a string (byte 0xFF): the document must be UTF-8");
    expect_syntax(key("\x80"), "invalid UTF-8 in a string (byte 0x80)");              // a lone continuation byte
    expect_syntax(key("\xC0\x80"), "invalid UTF-8 in a string (byte 0xC0)");          // overlong NUL
    expect_syntax(key("\xC1\xBF"), "invalid UTF-8 in a string (byte 0xC1)");          // overlong
    expect_syntax(key("\xE0\x9F\xBF"), "invalid UTF-8 in a string (byte 0xE0)");      // overlong 3-byte
    expect_syntax(key("\xED\xA0\x80"), "invalid UTF-8 in a string (byte 0xED)");      // UTF-16 surrogate
    expect_syntax(key("\xF0\x8F\xBF\xBF"), "invalid UTF-8 in a string (byte 0xF0)");  // overlong 4-byte
    expect_syntax(key("\xF4\x90\x80\x80"), "invalid UTF-8 in a string (byte 0xF4)");  // above U+10FFFF
    expect_syntax(key("\xF5\x80\x80\x80"), "invalid UTF-8 in a string (byte 0xF5)");
    expect_syntax(key("a\xC3"), "line 1, column 33: invalid UTF-8 in a string (byte 0xC3)");  // truncated sequence
    expect_syntax(key("\xE2\x82"), "invalid UTF-8 in a string (byte 0xE2)");
    expect_syntax("{\"vertices\": [], \"edges\": [], \"\xE2\x82", "invalid UTF-8 in a string (byte 0xE2)");
}

// ----------------------------------------------------------------- structure

TEST(JsonSyntax, Separators) {
    expect_syntax(R"({"vertices": [[0 1]], "edges": []})",
                  "line 1, column 18: unexpected character '1': expected ',' or ']' after an array element");
    expect_syntax(R"({"vertices": [[0, 1],], "edges": []})",
                  "line 1, column 22: unexpected ']' after ',': JSON does not allow trailing commas");
    expect_syntax(R"({"vertices": [], "edges": [],})",
                  "line 1, column 30: unexpected '}' after ',': JSON does not allow trailing commas");
    expect_syntax(R"({"vertices" [], "edges": []})",
                  "line 1, column 13: unexpected character '[': expected ':' after the key \"vertices\"");
    expect_syntax(R"({"vertices": [] "edges": []})",
                  "line 1, column 17: unexpected character '\"': expected ',' or '}' after an object member");
    expect_syntax(R"({vertices: [], "edges": []})",
                  "line 1, column 2: unexpected character 'v': JSON keys must be in double quotes");
    expect_syntax(R"({'vertices': []})",
                  "line 1, column 2: unexpected single quote: JSON keys are written in double quotes");
    expect_syntax(R"({1: []})", "line 1, column 2: unexpected character '1': expected a key in double quotes");
    expect_syntax(R"({"vertices": [,], "edges": []})", "line 1, column 15: unexpected character ',': expected a JSON value");
    expect_syntax(R"({"vertices": [[0, 0]}, "edges": []})",
                  "line 1, column 21: unexpected character '}': expected ',' or ']' after an array element");
    expect_syntax(R"({"vertices": [], "edges": [], "x": })",
                  "line 1, column 36: unexpected character '}': expected a JSON value");
    expect_syntax(R"([[], []] ])",
                  "line 1, column 10: unexpected content after the end of the JSON document (character ']')");
}

TEST(JsonSyntax, NestingLimit) {
    // 256 levels are fine (inside an ignored key: the object is level 1).
    const std::string ok = R"({"vertices": [], "edges": [], "deep": )" + std::string(255, '[') + std::string(255, ']') + "}";
    EXPECT_NO_THROW(static_cast<void>(read_graph(ok)));
    // The 257th level is a syntax error at its bracket (column 38 + 256).
    const std::string deep = R"({"vertices": [], "edges": [], "deep": )" + std::string(256, '[') + std::string(256, ']') +
                             "}";
    expect_syntax(deep, "line 1, column 294: nesting deeper than 256 levels");
}

TEST(JsonSyntax, VeryDeepNestingFailsFastWithoutRecursion) {
    const std::string arrays(100000, '[');
    std::string objects;
    for (int i = 0; i < 100000; ++i) objects += "{\"a\":";
    {
        JsonReader r(arrays);
        expect_input_error([&] { r.skip_value(); }, InputErrorKind::Syntax,
                           "line 1, column 257: nesting deeper than 256 levels");
    }
    // Where a reader skips the value (an unknown key), the depth limit is what stops it.
    expect_syntax(objects, "line 1, column 1281: nesting deeper than 256 levels");
    expect_input_error([&] { static_cast<void>(read_dump(objects)); }, InputErrorKind::Syntax, "nesting deeper");
    expect_input_error([&] { static_cast<void>(read_faces_answer(objects)); }, InputErrorKind::Syntax, "nesting deeper");
    expect_input_error([&] { static_cast<void>(read_answer(objects)); }, InputErrorKind::Syntax, "nesting deeper");
    std::string mixed = R"({"vertices": [], "half_edges": [], "faces": [], "x": )";
    for (int i = 0; i < 50000; ++i) mixed += "[{\"k\":";
    expect_input_error([&] { static_cast<void>(read_dump(mixed)); }, InputErrorKind::Syntax, "nesting deeper");
    // Where a reader expects a number, the first array in its place is the
    // error (errors are reported in document order).
    expect_input_error([&] { static_cast<void>(read_graph(arrays)); }, InputErrorKind::Shape,
                       "[0][0][0]: expected a number, found an array");
    expect_input_error([&] { static_cast<void>(read_faces_answer(arrays)); }, InputErrorKind::Shape,
                       "[0][0]: expected a vertex index (a non-negative integer), found an array");
    expect_input_error([&] { static_cast<void>(read_answer(arrays)); }, InputErrorKind::Shape, "[0][0]: expected");
}

// ------------------------------------------------------------------ fuzzing

// Mutations of valid documents must give a result or InvalidInput, nothing
// else (run under sanitizers to catch out-of-bounds reads).
TEST(JsonReaderFuzz, MutatedDocumentsNeverCrash) {
    const std::array<std::string, 4> seeds{
        R"({"vertices": [[0, 0], [1.5, -2e-3], [1e300, 4.9e-324]], "edges": [[0, 1], [1, 2]], "x": {"y": ["\u00e9\n"]}})",
        R"([[[0, 0], [1, 0]], [[0, 1]]])",
        R"({"vertices": [[0, 0], [1, 0]], "vertex_out": [0, null], "half_edges": [{"origin": 0, "twin": 1, "next": 1, "prev": 1, "face": 0}, {"origin": 1, "twin": 0, "next": 0, "prev": 0, "face": 0}], "faces": [{"outer": null, "inner": [0], "isolated": []}]})",
        R"({"faces": [[0, 1, 2], [], [2, 1, 0]]})",
    };
    const std::string alphabet = "[]{}\",:.-+eE0123456789 \\u\"tfnalsrx\xC3\xA9\xFF\n";
    std::mt19937 rng(12345);
    int parsed = 0;
    for (int round = 0; round < 20000; ++round) {
        std::string doc = seeds[static_cast<std::size_t>(round) % seeds.size()];
        const int edits = 1 + static_cast<int>(rng() % 4);
        for (int k = 0; k < edits && !doc.empty(); ++k) {
            const std::size_t at = rng() % doc.size();
            const char c = alphabet[rng() % alphabet.size()];
            switch (rng() % 4) {
                case 0: doc[at] = c; break;
                case 1: doc.insert(doc.begin() + static_cast<std::ptrdiff_t>(at), c); break;
                case 2: doc.erase(at, 1); break;
                default: doc.resize(at); break;
            }
        }
        // Exact-size heap copies so that a read past the end is caught by ASan.
        const std::unique_ptr<char[]> exact(new char[doc.size()]);
        std::copy(doc.begin(), doc.end(), exact.get());
        const std::string_view text(exact.get(), doc.size());
        try {
            static_cast<void>(read_graph(text));
            ++parsed;
        } catch (const InvalidInput&) {
        }
        try {
            static_cast<void>(read_dump(text));
        } catch (const InvalidInput&) {
        }
        try {
            static_cast<void>(read_answer(text));
        } catch (const InvalidInput&) {
        }
    }
    EXPECT_GT(parsed, 0);
}

}  // namespace
}  // namespace dcel::io
