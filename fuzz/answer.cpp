// answer: other programs' answers, read and judged by dcel::check (the
// checker's untrusted side).
//
// Every input gets a verdict, never a crash: an answer that cannot be read
// becomes check::unreadable_answer, as in `dcel check`. On every verdict:
// each difference message and note is one line that needs_escaping()
// (dcel/format.hpp) passes, and names only vertices of the graph; the text
// report has one line per difference and note; the JSON report is valid
// UTF-8, parses with the library's JsonReader and gives back every field
// (messages byte for byte); an answer that differs is drawn
// (check/counterexample_svg.hpp) from its cycles and polygons as
// `dcel diff --svg` prepares them (check/answer_drawing.hpp, which the diff engine calls); validate()
// and validate_all() agree on a dump read. Every kind
// the text's shape fits reads as that kind (`dcel diff` reads them without
// a net), and under each of them and each of the eight convention
// combinations the checker's verdict is the independent oracle's
// (oracles/answer_meaning.hpp) on the answer read
// (support/answer_plain.hpp).
//
// Input: five header bytes, then the body.
//   byte 0  the graph's family: (byte - '0') mod 10 (dcel::gen)
//   byte 1  its seed
//   byte 2  its size: (byte - '0') mod 17 vertices
//   byte 3  the answer kind: (byte - '0') mod 5: detected, faces, dump,
//           polygons, rings
//   byte 4  (byte - '0') mod 16, bits: 1 --face-on right, 2 --one-based,
//           4 --unoriented, 8 mode B
// Mode A: the body is an answer's text.
// Mode B: the body is choices (support/answer_spellings.hpp), the first of
//   which says whether to corrupt: the reference's own answer of the kind
//   (of a kind chosen, and detected, when byte 3 says detected) in one of
//   the spellings docs/checking.md allows, maybe corrupted. The checker must
//   agree exactly when the oracle finds the answer right: always for a
//   respelling, and after a corruption only when it kept the meaning. Then
//   the text gets every check of mode A, and so does the reference's answer
//   as `dcel faces --answer KIND` prints it (check::reference_answer), which
//   must agree.
// The header is printable, so that seeds can be written by hand: "1a83" and
// "8" is family 1 (triangulation), seed 97 ('a'), 8 vertices, polygons,
// mode B; "3e<0" and "1" are nested polygons, seed 101, 12 vertices ('<'),
// detected, --face-on right, mode A.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "dcel/build.hpp"
#include "dcel/check/answer.hpp"
#include "dcel/check/answer_drawing.hpp"
#include "dcel/check/counterexample_svg.hpp"
#include "dcel/check/report.hpp"
#include "dcel/error.hpp"
#include "dcel/format.hpp"
#include "dcel/gen/generate.hpp"
#include "dcel/io/json_reader.hpp"
#include "dcel/validate.hpp"
#include "oracles/answer_meaning.hpp"
#include "support/answer_plain.hpp"
#include "support/answer_spellings.hpp"
#include "support/fuzz_check.hpp"

namespace dcel::fuzz {
namespace {

using check::AnswerKind;
using check::Conventions;
using check::Report;

// Reading and comparing are O(n log n) in the answer; eight comparisons
// and a drawing per input on graphs of at most 16 vertices keep a run near
// a millisecond. An answer for such a graph fits in a few kilobytes in any
// spelling.
constexpr std::size_t kMaxInput = 16 * 1024;
constexpr std::size_t kHeader = 5;
constexpr std::size_t kMaxVertices = 16;

std::size_t digit(std::uint8_t b, std::size_t n) { return static_cast<std::uint8_t>(b - '0') % n; }

// Well-formed UTF-8 (RFC 3629: no overlongs, surrogates or code points past
// U+10FFFF), decided here rather than by the library's own escaper.
bool valid_utf8(std::string_view s) {
    for (std::size_t i = 0; i < s.size();) {
        const auto c = static_cast<unsigned char>(s[i]);
        std::size_t n = 0;
        std::uint32_t cp = 0, least = 0;
        if (c < 0x80) {
            ++i;
            continue;
        }
        if (c >= 0xC2 && c <= 0xDF) {
            n = 1, cp = c & 0x1FU, least = 0x80;
        } else if (c >= 0xE0 && c <= 0xEF) {
            n = 2, cp = c & 0x0FU, least = 0x800;
        } else if (c >= 0xF0 && c <= 0xF4) {
            n = 3, cp = c & 0x07U, least = 0x10000;
        } else {
            return false;
        }
        if (i + n >= s.size()) return false;
        for (std::size_t k = 1; k <= n; ++k) {
            const auto d = static_cast<unsigned char>(s[i + k]);
            if ((d & 0xC0U) != 0x80U) return false;
            cp = (cp << 6U) | (d & 0x3FU);
        }
        if (cp < least || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return false;
        i += n + 1;
    }
    return true;
}

void check_line(std::string_view what, std::string_view line) {
    FUZZ_CHECK(line.find_first_of("\n\r") == std::string_view::npos, what << " spans lines: " << escape_for_message(line));
    FUZZ_CHECK(!needs_escaping(line), what << " needs escaping: " << escape_for_message(line));
}

// The JSON report read back with the library's own reader: the same
// verdict, counts, kinds, messages (byte for byte), vertices and notes.
void check_json(const Report& report, const std::string& json) {
    FUZZ_CHECK(valid_utf8(json), "the JSON report is not UTF-8: " << escape_for_message(json));
    {
        io::JsonReader any(json);
        any.skip_value();
        any.end_document();
    }
    io::JsonReader r(json);
    r.begin_object("the report");
    std::size_t seen = 0;
    while (r.next_member()) {
        const std::string key(r.key());
        ++seen;
        if (key == "agrees") {
            const io::JsonType t = r.peek();
            FUZZ_CHECK((t == io::JsonType::True) == report.agrees() && (t == io::JsonType::True || t == io::JsonType::False),
                       "\"agrees\" says otherwise: " << json);
            r.skip_value();
        } else if (key == "count") {
            FUZZ_CHECK(r.read_index("count") == report.differences.size() + report.unlisted, "\"count\": " << json);
        } else if (key == "unlisted") {
            FUZZ_CHECK(r.read_index("unlisted") == report.unlisted, "\"unlisted\": " << json);
        } else if (key == "differences") {
            r.begin_array("differences");
            std::size_t i = 0;
            while (r.next_element()) {
                FUZZ_CHECK(i < report.differences.size(), "more differences in the JSON: " << json);
                const check::Difference& d = report.differences[i++];
                r.begin_object("a difference");
                while (r.next_member()) {
                    const std::string k(r.key());
                    if (k == "kind") {
                        FUZZ_CHECK(r.read_string() == check::kind_name(d.kind), "kind: " << json);
                    } else if (k == "message") {
                        FUZZ_CHECK(r.read_string() == d.message, "message: " << json);
                    } else if (k == "vertices") {
                        r.begin_array("vertices");
                        std::size_t j = 0;
                        while (r.next_element()) {
                            FUZZ_CHECK(j < d.vertices.size() && r.read_index("vertex") == d.vertices[j],
                                       "vertices: " << json);
                            ++j;
                        }
                        FUZZ_CHECK(j == d.vertices.size(), "vertices: " << json);
                    } else {
                        FUZZ_CHECK(false, "unknown key " << k << " in " << json);
                    }
                }
            }
            FUZZ_CHECK(i == report.differences.size(), "fewer differences in the JSON: " << json);
        } else if (key == "notes") {
            r.begin_array("notes");
            std::size_t i = 0;
            while (r.next_element()) {
                FUZZ_CHECK(i < report.notes.size() && r.read_string() == report.notes[i], "notes: " << json);
                ++i;
            }
            FUZZ_CHECK(i == report.notes.size(), "fewer notes in the JSON: " << json);
        } else {
            FUZZ_CHECK(false, "unknown key " << key << " in " << json);
        }
    }
    r.end_document();
    FUZZ_CHECK(seen == 5, "the JSON report has " << seen << " keys: " << json);
}

void check_report(const Dcel& reference, const Report& report) {
    std::size_t lines = report.notes.size() + (report.agrees() ? 1 : 1 + report.differences.size());
    if (report.unlisted != 0) {
        FUZZ_CHECK(!report.agrees(), "unlisted differences but none listed");
        ++lines;
    }
    for (const check::Difference& d : report.differences) {
        check_line("a difference", d.message);
        for (const Index v : d.vertices) {
            FUZZ_CHECK(v < reference.num_vertices(), "a " << check::kind_name(d.kind) << " difference names vertex " << v
                                                          << " of " << reference.num_vertices() << ": " << d.message);
        }
    }
    for (const std::string& note : report.notes) check_line("a note", note);
    const std::string text = check::report_text(report);
    FUZZ_CHECK(!text.empty() && text.back() == '\n', "the text report does not end a line");
    FUZZ_CHECK(static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) == lines,
               "the text report has not one line per difference and note:\n"
                   << text);
    check_json(report, check::report_json(report));
}

void draw(const PlanarGraph& g, const Dcel& reference, const check::Answer& a, const Conventions& c) {
    check::CounterexampleDrawing drawing{.graph = &g, .reference = &reference};
    drawing.answer_cycles = check::drawn_cycles(a, c);
    drawing.answer_polygons = check::drawn_regions(a, reference, c);
    const std::string svg = check::render_counterexample_svg(drawing);
    FUZZ_CHECK(svg.find("<svg") != std::string::npos && valid_utf8(svg), "a broken picture");
}

// The verdict on one text, as `dcel check` gives it, with every check
// above; the report under the conventions asked for. And for each kind
// the text fits and each convention, the checker's verdict must be the
// oracle's on the answer read (support/answer_plain.hpp).
Report judge(const PlanarGraph& g, const Dcel& reference, const oracle::AnswerJudge& meaning, std::string_view text,
             std::optional<AnswerKind> kind, const Conventions& c) {
    check::Answer answer;
    try {
        answer = check::read_answer(text, kind);
    } catch (const InvalidInput& e) {
        Report report = check::unreadable_answer(std::string("ANSWER -: ") + e.what());
        check_report(reference, report);
        // Nothing to draw but the picture's own refusal: no reference given.
        FUZZ_CHECK(check::render_counterexample_svg({.graph = &g}).find("<svg") != std::string::npos, "no picture");
        return report;
    }
    if (answer.kind == AnswerKind::Dump) {
        FUZZ_CHECK(validate(answer.dump).has_value() == !validate_all(answer.dump).empty(),
                   "validate and validate_all disagree on a dump read");
    }
    FUZZ_CHECK(!answer.fits.empty() && answer.fits.front() == answer.kind, "fits does not start with the kind read");
    FUZZ_CHECK(!kind || answer.kind == *kind, "read as another kind than the one given");
    Report asked;
    for (const AnswerKind fit : answer.fits) {
        check::Answer as = answer;
        if (fit != answer.kind) {
            try {
                as = check::read_answer(text, fit);
            } catch (const InvalidInput& e) {
                FUZZ_CHECK(false,
                           "the shape fits " << check::answer_kind_name(fit) << " but does not read as it: " << e.what());
            }
        }
        for (int bits = 0; bits < 8; ++bits) {
            const Conventions each{
                .face_on_right = (bits & 1) != 0, .one_based = (bits & 2) != 0, .unoriented = (bits & 4) != 0};
            const bool mine = each.face_on_right == c.face_on_right && each.one_based == c.one_based &&
                              each.unoriented == c.unoriented;
            // The conventions asked for get every check; the others only
            // the cheap ones (one line each).
            const Report r = check::compare(reference, as, each);
            const oracle::AnswerVerdict v = oracle_verdict(meaning, as, each);
            FUZZ_CHECK(r.agrees() == v.right,
                       "read as " << check::answer_kind_name(fit) << (each.face_on_right ? ", --face-on right" : "")
                                  << (each.one_based ? ", --one-based" : "") << (each.unoriented ? ", --unoriented" : "")
                                  << ", the checker " << (r.agrees() ? "agrees" : "differs") << " but the oracle says "
                                  << (v.right ? "right" : "wrong: " + v.why) << "\n"
                                  << check::report_text(r));
            if (mine && fit == answer.kind) {
                check_report(reference, r);
                asked = r;
            } else {
                for (const check::Difference& d : r.differences) check_line("a difference", d.message);
                for (const std::string& n : r.notes) check_line("a note", n);
            }
        }
    }
    // `dcel diff --svg` draws only answers that differ; so does this (the
    // picture is two thirds of a run's time).
    if (!asked.agrees()) draw(g, reference, answer, c);
    return asked;
}

}  // namespace
}  // namespace dcel::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace dcel;
    using namespace dcel::fuzz;
    if (size < kHeader || size > kMaxInput) return -1;
    const auto families = gen::all_families();
    const gen::Params params{families[digit(data[0], families.size())], data[1], digit(data[2], kMaxVertices + 1)};
    const PlanarGraph g = gen::generate(params);
    const Dcel reference = build(g);
    const std::size_t kind_byte = digit(data[3], 5);
    const std::size_t bits = digit(data[4], 16);
    const check::Conventions c{
        .face_on_right = (bits & 1U) != 0, .one_based = (bits & 2U) != 0, .unoriented = (bits & 4U) != 0};
    const std::optional<check::AnswerKind> kind = kind_byte == 0
                                                      ? std::nullopt
                                                      : std::optional(static_cast<check::AnswerKind>(kind_byte - 1));
    const std::span<const std::uint8_t> body(data + kHeader, size - kHeader);
    const oracle::AnswerJudge meaning(g);
    if ((bits & 8U) == 0) {
        (void)judge(g, reference, meaning, std::string_view(reinterpret_cast<const char*>(body.data()), body.size()), kind,
                    c);
        return 0;
    }
    test_support::Choices choices(body);
    test_support::TrialSetup setup;
    setup.corrupt = choices.one_in(2);
    setup.kind = kind ? *kind : static_cast<check::AnswerKind>(choices.below(4));
    setup.give_kind = kind.has_value();
    setup.conventions = c;
    const test_support::Trial trial = test_support::make_trial(reference, meaning, setup, choices);
    FUZZ_CHECK(setup.corrupt || trial.expected.right, "the reference's own answer, respelled, is wrong by the oracle: "
                                                          << trial.expected.why << "\ntext: " << trial.text << "\n"
                                                          << trial.story);
    const std::string failure = test_support::judge_trial(reference, trial);
    FUZZ_CHECK(failure.empty(), failure);
    // The reference's answer as `dcel faces --answer KIND` prints it, plainly.
    const std::string own = check::reference_answer(reference, setup.kind);
    FUZZ_CHECK(judge(g, reference, meaning, own, setup.kind, {}).agrees(), "the reference's own answer differs: " << own);
    (void)judge(g, reference, meaning, trial.text, kind, c);
    return 0;
}
