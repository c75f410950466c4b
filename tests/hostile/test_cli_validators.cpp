// The CLI's strict number parsing (src/cli/cli_support.hpp): the parse_*
// functions, and the same rules as CLI11 validators on a real option, with
// the messages a user sees.
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "cli_support.hpp"

namespace dcel::cli {
namespace {

// The message parse_* throws, or "" when it accepts the word.
template <class F>
std::string refusal(F&& f) {
    try {
        f();
    } catch (const UsageError& e) {
        return e.what();
    }
    return "";
}

TEST(ParseUnsigned, TakesDigitsInRangeOnly) {
    EXPECT_EQ(parse_unsigned("0", "N"), 0U);
    EXPECT_EQ(parse_unsigned("007", "N"), 7U);
    EXPECT_EQ(parse_unsigned("18446744073709551615", "N"), UINT64_MAX);
    EXPECT_EQ(refusal([] { (void)parse_unsigned("18446744073709551616", "--seed"); }),
              "--seed: expected a non-negative integer (at most 18446744073709551615), found \"18446744073709551616\"");
    EXPECT_EQ(refusal([] { (void)parse_unsigned("-1", "--cases", 0, 1000); }),
              "--cases: expected an integer from 0 to 1000, found \"-1\"");
    for (const char* bad : {"", " 1", "1 ", "+1", "1e3", "1.0", "0x10", "1000001", "٣"}) {
        EXPECT_NE(refusal([&] { (void)parse_unsigned(bad, "N", 0, 1000000); }), "") << bad;
    }
    EXPECT_EQ(refusal([] { (void)parse_unsigned("5", "N", 6, 9); }), "N: expected an integer from 6 to 9, found \"5\"");
}

TEST(ParseNumber, ReadsJsonNumbersLikeTheJsonReader) {
    EXPECT_EQ(parse_number("-1.5", "T"), -1.5);
    EXPECT_EQ(parse_number("2e-3", "T"), 0.002);
    EXPECT_EQ(parse_number("0.1", "T"), 0.1);  // correctly rounded
    // An underflowing literal is zero of its sign, as in a JSON file.
    EXPECT_EQ(parse_coordinate("1e-400", "X"), 0.0);
    EXPECT_TRUE(std::signbit(parse_coordinate("-1e-400", "X")));
    EXPECT_EQ(parse_coordinate("4.9e-324", "X"), 4.9e-324);
    for (const char* bad : {"nan", "NaN", "inf", "-inf", "1e400", "+1", ".5", "5.", "0x10", "1 ", " 1", "", "1,5", "--1"}) {
        EXPECT_EQ(refusal([&] { (void)parse_coordinate(bad, "X"); }),
                  std::string("X: expected a finite number, found \"") + bad + "\"")
            << bad;
    }
}

TEST(ParseNumber, RangeInTheMessageIsShort) {
    const NumberRange seconds{0, 1e7, true};
    EXPECT_EQ(parse_number("0.001", "--time", seconds), 0.001);
    EXPECT_EQ(refusal([&] { (void)parse_number("0", "--time", seconds); }),
              "--time: expected a finite number greater than 0 and at most 1e+07, found \"0\"");
    EXPECT_EQ(refusal([&] { (void)parse_number("1e300", "--time", seconds); }),
              "--time: expected a finite number greater than 0 and at most 1e+07, found \"1e300\"");
    EXPECT_EQ(refusal([] {
                  (void)parse_number("-1", "--shrink-time", {0, 1e6});
              }),
              "--shrink-time: expected a finite number at least 0 and at most 1e+06, found \"-1\"");
}

TEST(ParseByteSize, DigitsAndPowersOf1024) {
    EXPECT_EQ(parse_byte_size("0", "B"), 0U);
    EXPECT_EQ(parse_byte_size("1500", "B"), 1500U);
    EXPECT_EQ(parse_byte_size("64K", "B"), 65536U);
    EXPECT_EQ(parse_byte_size("512M", "B"), 536870912U);
    EXPECT_EQ(parse_byte_size("2G", "B"), std::uint64_t{2} << 30);
    EXPECT_EQ(parse_byte_size("16777215T", "B"), std::uint64_t{16777215} << 40);
    for (const char* bad : {"16777216T", "1KB", "k", "K", "-1", "1.5G", "1Ki", ""}) {
        EXPECT_NE(refusal([&] { (void)parse_byte_size(bad, "B"); }), "") << bad;
    }
}

// The validators on real options, as a command declares them.
struct Parsed {
    std::string error;  // CLI11's message, "" when parsing succeeded
};

Parsed parse(CLI::App& app, std::vector<std::string> args) {
    std::reverse(args.begin(), args.end());  // CLI11 takes them last first
    try {
        app.parse(args);
    } catch (const CLI::ParseError& e) {
        return {e.what()};
    }
    return {};
}

TEST(Validators, CheckAndRewriteForCli11) {
    CLI::App app;
    std::size_t cases = 7;
    std::uint64_t seed = 0;
    double time = 0;
    std::uint64_t bytes = 0;
    app.add_option("--cases", cases)->transform(unsigned_in(1, 1000000));
    app.add_option("--seed", seed)->transform(unsigned_in());
    app.add_option("--time", time)->transform(number_in({0, 1e7, true}));
    app.add_option("--bytes", bytes)->transform(byte_size());

    EXPECT_EQ(parse(app, {"--cases", "0010", "--seed", "18446744073709551615", "--time", "2.5", "--bytes", "3K"}).error, "");
    EXPECT_EQ(cases, 10U);
    EXPECT_EQ(seed, UINT64_MAX);
    EXPECT_EQ(time, 2.5);
    EXPECT_EQ(bytes, 3072U);
    // 1e-400 reads as 0, as in a JSON file, which the range refuses; the
    // message quotes the word as typed.
    EXPECT_EQ(parse(app, {"--time", "1e-400"}).error,
              "--time: expected a finite number greater than 0 and at most 1e+07, found \"1e-400\"");
    EXPECT_EQ(parse(app, {"--cases", "-1"}).error, "--cases: expected an integer from 1 to 1000000, found \"-1\"");
    EXPECT_EQ(parse(app, {"--cases", "0"}).error, "--cases: expected an integer from 1 to 1000000, found \"0\"");
    EXPECT_EQ(parse(app, {"--seed", "18446744073709551616"}).error,
              "--seed: expected a non-negative integer (at most 18446744073709551615), found \"18446744073709551616\"");
    EXPECT_EQ(parse(app, {"--time", "nan"}).error,
              "--time: expected a finite number greater than 0 and at most 1e+07, found \"nan\"");
    EXPECT_EQ(parse(app, {"--time", "1e300"}).error,
              "--time: expected a finite number greater than 0 and at most 1e+07, found \"1e300\"");
    EXPECT_EQ(parse(app, {"--time", "a\nb"}).error,
              "--time: expected a finite number greater than 0 and at most 1e+07, found \"a\\nb\"");
}

TEST(DisplayName, EscapesPaths) {
    EXPECT_EQ(display_name("-"), "<stdin>");
    EXPECT_EQ(display_name("a\nb\x1b.json"), "a\\nb\\u001B.json");
}

}  // namespace
}  // namespace dcel::cli
