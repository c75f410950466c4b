// The library side of the hostile-input work: the escaping of user text for
// messages (dcel/format.hpp), and stab on a star too large for a quadratic
// walk, against an answer worked out independently with exact integer
// arithmetic.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "dcel/build.hpp"
#include "dcel/format.hpp"
#include "dcel/stab.hpp"

namespace dcel {
namespace {

// ---------------------------------------------------------------- escaping

TEST(EscapeForMessage, KeepsPrintableTextAndUtf8) {
    EXPECT_EQ(escape_for_message("West 1-2 (a, b) [x] {y} 'q' \"d\""), "West 1-2 (a, b) [x] {y} 'q' \"d\"");
    EXPECT_EQ(escape_for_message("Zürich 東京 😀"), "Zürich 東京 😀");
    EXPECT_FALSE(needs_escaping("Zürich 東京 😀 \\ \""));
}

TEST(EscapeForMessage, ControlCharactersBecomeEscapes) {
    EXPECT_EQ(escape_for_message("a\nb\rc\td"), "a\\nb\\rc\\td");
    EXPECT_EQ(escape_for_message(std::string("nul\0x", 5)), "nul\\u0000x");
    EXPECT_EQ(escape_for_message("\x1b]0;title\x07\x1b[31m"), "\\u001B]0;title\\u0007\\u001B[31m");
    EXPECT_EQ(escape_for_message("del\x7f"), "del\\u007F");
    // C1 controls, written as UTF-8 (U+0085 next line, U+009B the 8-bit CSI).
    EXPECT_EQ(escape_for_message("\xc2\x85\xc2\x9b"), "\\u0085\\u009B");
    // Separators and bidirectional controls reorder or break the line.
    EXPECT_EQ(escape_for_message("a\xe2\x80\xa8"
                                 "b\xe2\x80\xae"
                                 "c\xe2\x81\xa6"
                                 "d\xe2\x80\x8f"),
              "a\\u2028b\\u202Ec\\u2066d\\u200F");
    for (const char* unsafe : {"\n", "\x1b", "\x7f", "\xc2\x85", "\xe2\x80\xa9", "\xe2\x81\xa9"}) {
        EXPECT_TRUE(needs_escaping(unsafe)) << escape_for_message(unsafe);
    }
}

TEST(EscapeForMessage, InvalidUtf8BecomesByteEscapes) {
    EXPECT_EQ(escape_for_message("\xff\xfe"), "\\xFF\\xFE");
    EXPECT_EQ(escape_for_message("\xc0\xaf"), "\\xC0\\xAF");                    // overlong '/'
    EXPECT_EQ(escape_for_message("\xed\xa0\x80"), "\\xED\\xA0\\x80");           // a UTF-16 surrogate
    EXPECT_EQ(escape_for_message("ab\xe6\x9d"), "ab\\xE6\\x9D");                // cut short
    EXPECT_EQ(escape_for_message("\xf4\x90\x80\x80"), "\\xF4\\x90\\x80\\x80");  // above U+10FFFF
    EXPECT_TRUE(needs_escaping("ok\xff"));
}

TEST(EscapeForMessage, BackslashAndQuote) {
    // Backslash is doubled so that every escape reads one way back; a quote
    // is escaped only between quotes.
    EXPECT_EQ(escape_for_message("a\\nb\""), "a\\\\nb\"");
    EXPECT_EQ(quote_for_message("say \"hi\"\\"), "\"say \\\"hi\\\"\\\\\"");
    EXPECT_EQ(quote_for_message(""), "\"\"");
}

TEST(EscapeForMessage, LongTextIsCutAtACharacterBoundary) {
    EXPECT_EQ(escape_for_message(std::string(300, 'x')), std::string(kMaxShownBytes, 'x') + "...");
    EXPECT_EQ(escape_for_message("abcdef", 6), "abcdef");
    EXPECT_EQ(escape_for_message("abcdefg", 6), "abcdef...");
    // "é" is two bytes: it is not split.
    EXPECT_EQ(escape_for_message("abcdé", 5), "abcd...");
    EXPECT_EQ(quote_for_message("abcdé", 6), "\"abcdé\"");
}

TEST(EscapeForMessage, EveryByteStringGivesOnePrintableLine) {
    // Random bytes, control-heavy: the result has no byte below 0x20, no DEL,
    // no C1 control, and is valid UTF-8 (needs_escaping finds nothing).
    std::mt19937_64 rng(7);
    for (int round = 0; round < 2000; ++round) {
        std::string s(rng() % 40, '\0');
        for (char& c : s) c = static_cast<char>(rng() % 4 == 0 ? rng() % 0x20 : rng() % 256);
        const std::string e = escape_for_message(s);
        EXPECT_FALSE(needs_escaping(e)) << e;
        EXPECT_TRUE(std::none_of(e.begin(), e.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20; }));
    }
}

// ---------------------------------------------------------------- stab on a large star

struct Spoke {
    long long x, y;  // the spoke goes from (0, 0) to (x, y)
};

long long cross(long long ax, long long ay, long long bx, long long by) { return ax * by - ay * bx; }
int sign(long long v) { return (v > 0) - (v < 0); }

// n spokes from the origin in distinct directions (primitive vectors), to
// integer points within [-r, r]^2.
std::vector<Spoke> random_star(std::size_t n, long long r, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::set<std::pair<long long, long long>> directions;
    std::vector<Spoke> spokes;
    while (spokes.size() < n) {
        const auto x = static_cast<long long>(rng() % static_cast<std::uint64_t>(2 * r + 1)) - r;
        const auto y = static_cast<long long>(rng() % static_cast<std::uint64_t>(2 * r + 1)) - r;
        if (x == 0 && y == 0) continue;
        const long long g = std::gcd(x, y);
        if (directions.insert({x / g, y / g}).second) spokes.push_back({x, y});
    }
    return spokes;
}

PlanarGraph star_graph(const std::vector<Spoke>& spokes) {
    PlanarGraph g;
    g.vertices.push_back({0, 0});
    for (std::size_t i = 0; i < spokes.size(); ++i) {
        g.vertices.push_back({static_cast<double>(spokes[i].x), static_cast<double>(spokes[i].y)});
        g.edges.push_back({VertexId(0), VertexId(static_cast<Index>(i + 1))});
    }
    return g;
}

// The answer by brute force: every spoke the segment (or line) P-Q crosses at
// an interior point of both, ordered by the parameter t of the crossing
// P + t (Q - P), t = num / den compared exactly by cross-multiplying in 64-bit integers. The star
// has one face, so the pieces alternate face 0 and a crossing. Empty when the
// line through P and Q meets the centre or a spoke's end (not this test's case).
std::vector<StabPiece> expected_crossings(const std::vector<Spoke>& spokes, long long px, long long py, long long qx,
                                          long long qy, bool line) {
    struct Crossing {
        long long num, den;  // den > 0
        Index edge;
    };
    std::vector<Crossing> found;
    const long long dx = qx - px, dy = qy - py;
    if (cross(dx, dy, -px, -py) == 0) return {};
    for (std::size_t i = 0; i < spokes.size(); ++i) {
        const Spoke s = spokes[i];
        const int o_centre = sign(cross(dx, dy, -px, -py));
        const int o_end = sign(cross(dx, dy, s.x - px, s.y - py));
        if (o_end == 0) return {};
        if (o_centre * o_end >= 0) continue;  // the spoke stays on one side of the line
        if (!line) {
            const int op = sign(cross(s.x, s.y, px, py));
            const int oq = sign(cross(s.x, s.y, qx, qy));
            if (op * oq >= 0) continue;  // P and Q on one side of the spoke's line
        }
        // cross(S, P + t (Q - P)) = 0  =>  t = -cross(S, P) / cross(S, Q - P)
        long long num = -cross(s.x, s.y, px, py);
        long long den = cross(s.x, s.y, dx, dy);
        if (den < 0) num = -num, den = -den;
        found.push_back({num, den, static_cast<Index>(i)});
    }
    std::sort(found.begin(), found.end(), [](const Crossing& a, const Crossing& b) {
        return a.num * b.den < b.num * a.den;  // each factor below 3e7: exact in 64 bits
    });
    std::vector<StabPiece> pieces{StabPiece::in_face(FaceId(0))};
    for (const Crossing& c : found) {
        pieces.push_back(StabPiece::across(EdgeId(c.edge)));
        pieces.push_back(StabPiece::in_face(FaceId(0)));
    }
    return pieces;
}

TEST(StabLargeStar, SegmentsAndLinesMatchExactBruteForce) {
    // 1e5 spokes: the walk re-enters the unbounded face (2e5 half-edges) at
    // every crossing; a walk that rescans the face each time takes minutes.
    const std::vector<Spoke> spokes = random_star(100000, 1000, 11);
    const Dcel d = build(star_graph(spokes));
    std::mt19937_64 rng(5);
    int crossed = 0;
    for (int round = 0; round < 12; ++round) {
        // Ends outside the star's box, in general position (odd coordinates
        // far out; the checks in expected_crossings confirm it).
        const auto coordinate = [&] { return static_cast<long long>(rng() % 6001) - 3000; };
        long long px = coordinate(), py = coordinate(), qx = coordinate(), qy = coordinate();
        if (round % 2 == 0) px = -5001, qx = 5003;  // across the whole star
        if (px == qx && py == qy) continue;
        if (std::abs(px) <= 1000 && std::abs(py) <= 1000) continue;  // P inside the box: may sit on a spoke
        if (std::abs(qx) <= 1000 && std::abs(qy) <= 1000) continue;
        const Point p{static_cast<double>(px), static_cast<double>(py)};
        const Point q{static_cast<double>(qx), static_cast<double>(qy)};
        const std::vector<StabPiece> segment = expected_crossings(spokes, px, py, qx, qy, false);
        if (segment.empty()) continue;  // through the centre or a spoke's end
        EXPECT_EQ(stab_segment(d, p, q), segment) << "segment from " << px << "," << py << " to " << qx << "," << qy;
        EXPECT_EQ(stab_line(d, p, q), expected_crossings(spokes, px, py, qx, qy, true));
        crossed += static_cast<int>(segment.size() / 2);
    }
    EXPECT_GT(crossed, 100000);  // the segments really crossed the star many times
}

}  // namespace
}  // namespace dcel
