// io::json_string: expected literals written by hand from RFC 8259 section 7,
// and a round trip through the project's JSON reader (a separate module)
// for every ASCII byte.
#include <gtest/gtest.h>

#include <string>

#include "dcel/io/json_reader.hpp"
#include "dcel/io/json_string.hpp"

namespace dcel::io {
namespace {

TEST(JsonString, EscapesQuotesBackslashesAndControlCharacters) {
    EXPECT_EQ(json_string(""), R"("")");
    EXPECT_EQ(json_string("West"), R"("West")");
    EXPECT_EQ(json_string("say \"hi\""), R"("say \"hi\"")");
    EXPECT_EQ(json_string("C:\\maps"), R"("C:\\maps")");
    EXPECT_EQ(json_string("a\nb\tc"), R"("a\nb\tc")");
    // Other control characters as \u00XX, NUL and DEL's neighbour 0x1F included.
    EXPECT_EQ(json_string(std::string("\0\x01\x1f", 3)), R"("\u0000\u0001\u001f")");
    // '/' and DEL need no escape; UTF-8 passes through byte for byte.
    EXPECT_EQ(json_string("a/b\x7f"), "\"a/b\x7f\"");
    EXPECT_EQ(json_string("\xC3\xA9t\xC3\xA9"), "\"\xC3\xA9t\xC3\xA9\"");
}

TEST(JsonString, EveryAsciiByteRoundTripsThroughTheReader) {
    for (int c = 0; c < 0x80; ++c) {
        const std::string s = "<" + std::string(1, static_cast<char>(c)) + ">";
        const std::string doc = "{" + json_string(s) + ": 0}";
        JsonReader r(doc);
        r.begin_object("an object");
        ASSERT_TRUE(r.next_member()) << "byte " << c;
        EXPECT_EQ(r.key(), s) << "byte " << c;
        r.skip_value();
        EXPECT_FALSE(r.next_member());
    }
}

}  // namespace
}  // namespace dcel::io
