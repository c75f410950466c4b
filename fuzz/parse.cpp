// parse: arbitrary bytes as JSON, through every reader and build().
//
// Checks that each reader (graph, dump, faces answer, answer) either gives a
// clean InvalidInput (a kind a reader may raise, a one-line message) or a
// value that survives a write/read round trip unchanged; that a graph read
// builds into a DCEL that validate() passes, whose faces written straight
// from it (write_faces_of) are write_faces(boundary_cycles()), or is
// refused with a clean error; and that validate() and validate_all() agree
// on any dump read, however broken. Never a crash, hang, leak or undefined behaviour.
//
// Compares with an independent JSON parser, nlohmann/json
// (support/json_reference.hpp): the library's JSON reader accepts exactly
// the documents nlohmann accepts, but those nested deeper than the
// reader's limit (which it refuses) and those with a number beyond the
// range of a double (which nlohmann refuses; the reader refuses them only
// where it reads the number). The graph and faces readers accept exactly
// the documents whose values, as nlohmann reads them, have the documented
// shape (and read_points the documents that are one array of points), and
// read the same values (but where a number that is no integer
// reads as one, 5e-3241 or 1.00000000000000001: the reader decides an index
// on the exact decimal and must refuse it, nlohmann's double cannot tell);
// a dump the reader accepts holds nlohmann's values field by field.
//
// And the two routes from decimal text to a double (io/decimal.hpp):
// std::from_chars and the strtod_l fallback that libc++ builds use must
// give the same answer (match length, error, bits) wherever a number could
// start in the input.
#include <bit>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "dcel/build.hpp"
#include "dcel/error.hpp"
#include "dcel/io/dcel_json.hpp"
#include "dcel/io/decimal.hpp"
#include "dcel/io/graph_json.hpp"
#include "dcel/io/json_reader.hpp"
#include "dcel/queries.hpp"
#include "dcel/validate.hpp"
#include "support/fuzz_check.hpp"
#include "support/json_reference.hpp"

namespace dcel::fuzz {
namespace {

// Readers and build() are O(n log n), validate() too; 64 KiB keeps one run
// well under libFuzzer's timeout even for documents of ~10^4 elements.
// (libFuzzer's default -max_len of 4096 stays far below it.)
constexpr std::size_t kMaxInput = 64 * 1024;

bool same_points(const std::vector<Point>& a, const std::vector<Point>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        // Bitwise: -0.0 must come back as -0.0.
        if (std::bit_cast<std::uint64_t>(a[i].x) != std::bit_cast<std::uint64_t>(b[i].x) ||
            std::bit_cast<std::uint64_t>(a[i].y) != std::bit_cast<std::uint64_t>(b[i].y)) {
            return false;
        }
    }
    return true;
}

bool same_dump(const DcelDump& a, const DcelDump& b) {
    return same_points(a.vertices, b.vertices) && a.vertex_out == b.vertex_out && a.half_edges == b.half_edges &&
           a.faces == b.faces;
}

bool reader_kind(InputErrorKind k) {
    return k == InputErrorKind::Syntax || k == InputErrorKind::Shape || k == InputErrorKind::BadIndex ||
           k == InputErrorKind::BadCoordinate || k == InputErrorKind::TooLarge;
}

void check_clean(const InvalidInput& e, bool from_reader) {
    const std::string_view what = e.what();
    FUZZ_CHECK(!what.empty() && what.find('\n') == std::string_view::npos, "not a one-line message: " << what);
    if (from_reader) FUZZ_CHECK(reader_kind(e.kind()), "a reader raised " << to_string(e.kind()) << ": " << what);
}

// validate() on any dump, however broken: it must agree with validate_all().
void check_validators_agree(const DcelDump& d) {
    const CheckResult first = validate(d);
    const std::vector<Violation> all = validate_all(d);
    FUZZ_CHECK(first.has_value() == !all.empty(),
               "validate " << (first ? first->message : "passes") << " but validate_all found " << all.size());
    if (first) {
        FUZZ_CHECK(first->message.find('\n') == std::string::npos, "multi-line violation: " << first->message);
        FUZZ_CHECK(all.front().invariant == first->invariant, "validate and validate_all disagree on the first");
    }
}

// At up to 16 places where a number could start (after a byte that cannot
// be part of one), parse_double and its strtod fallback agree.
void check_decimal_routes(std::string_view text) {
    auto starts = [](char c) {
        return (c >= '0' && c <= '9') || c == '-' || c == '.' || c == 'i' || c == 'I' || c == 'n' || c == 'N';
    };
    int tried = 0;
    for (std::size_t i = 0; i < text.size() && tried < 16; ++i) {
        if (!starts(text[i]) || (i > 0 && starts(text[i - 1]))) continue;
        ++tried;
        double a = 0.5, b = 0.5;  // untouched on error, as from_chars leaves it
        const auto ra = io::parse_double(text.data() + i, text.data() + text.size(), a);
        const auto rb = io::parse_double_strtod(text.data() + i, text.data() + text.size(), b);
        FUZZ_CHECK(ra.ptr == rb.ptr && ra.ec == rb.ec && std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b),
                   "parse_double and its strtod fallback differ at byte "
                       << i << ": " << (ra.ptr - text.data() - i) << " vs " << (rb.ptr - text.data() - i) << " bytes, " << a
                       << " vs " << b);
    }
}

// Only documents nlohmann accepts, the reader's depth limit allows and that
// repeat no key have values to compare.
bool comparable(const JsonFacts& facts) {
    return facts.accepted && facts.depth <= io::JsonReader::kMaxDepth && !facts.duplicate_key;
}

bool reader_accepts_json(std::string_view text) {
    try {
        io::JsonReader r(text);
        r.skip_value();
        r.end_document();
        return true;
    } catch (const InvalidInput&) {
        return false;
    }
}

void check_json_syntax(std::string_view text, const JsonFacts& facts) {
    const bool ours = reader_accepts_json(text);
    if (facts.has_nul) {
        // nlohmann stops at a NUL; JSON has none outside strings and none raw inside.
        FUZZ_CHECK(!ours, "the reader accepts a document with a NUL byte");
    } else if (facts.accepted && facts.duplicate_key) {
        // docs/formats.md: a key given twice in any object is refused.
        FUZZ_CHECK(!ours, "the reader accepts an object that gives a key twice");
    } else if (facts.accepted) {
        FUZZ_CHECK(ours == (facts.depth <= io::JsonReader::kMaxDepth), "nlohmann accepts a document "
                                                                           << facts.depth << " deep; the reader "
                                                                           << (ours ? "accepts" : "refuses") << " it");
    } else if (!facts.number_overflow) {
        FUZZ_CHECK(!ours, "the reader accepts a document nlohmann refuses: " << facts.error);
    }
}

void graph_path(std::string_view text, const JsonFacts& facts) {
    PlanarGraph g;
    const std::optional<PlanarGraph> expected = comparable(facts) ? expected_graph(text) : std::optional<PlanarGraph>();
    try {
        g = io::read_graph(text);
    } catch (const InvalidInput& e) {
        check_clean(e, true);
        // An index nlohmann rounded to an integer is one the reader must refuse.
        FUZZ_CHECK(!expected || facts.rounded_to_integer, "read_graph refuses a graph nlohmann reads: " << e.what());
        return;
    }
    if (comparable(facts)) {
        FUZZ_CHECK(expected, "read_graph accepts a document that is no graph by nlohmann's reading");
        FUZZ_CHECK(expected->vertices == g.vertices && expected->edges == g.edges,
                   "read_graph reads other values than nlohmann");
    }
    const PlanarGraph again = io::read_graph(io::write_graph(g));
    FUZZ_CHECK(same_points(g.vertices, again.vertices) && g.edges == again.edges, "graph round trip changed it");

    Dcel d;
    try {
        d = build(g);
    } catch (const InvalidInput& e) {
        check_clean(e, false);
        FUZZ_CHECK(e.kind() != InputErrorKind::Syntax && e.kind() != InputErrorKind::Shape,
                   "build raised " << to_string(e.kind()));
        return;
    }
    FUZZ_CHECK(d.num_vertices() == g.vertices.size() && d.num_edges() == g.edges.size(), "build lost elements");
    const CheckResult v = validate(d);
    FUZZ_CHECK(!v, "validate rejects a built DCEL: [" << to_string(v->invariant) << "] " << v->message);
    FUZZ_CHECK(io::write_faces_of(d) == io::write_faces(boundary_cycles(d)),
               "write_faces_of differs from write_faces(boundary_cycles())");
    const DcelDump dump = to_dump(d);
    for (const io::DumpStyle style : {io::DumpStyle::Lines, io::DumpStyle::Compact}) {
        FUZZ_CHECK(same_dump(io::read_dump(io::write_dump(dump, style)), dump), "dump round trip changed it");
    }
}

// read_points (`dcel locate --points`): nlohmann's array of points, or a clean refusal.
void points_path(std::string_view text, const JsonFacts& facts) {
    const auto expected = comparable(facts) ? expected_points(text) : std::nullopt;
    std::vector<Point> points;
    try {
        points = io::read_points(text);
    } catch (const InvalidInput& e) {
        check_clean(e, true);
        FUZZ_CHECK(!expected, "read_points refuses points nlohmann reads: " << e.what());
        return;
    }
    if (comparable(facts)) {
        FUZZ_CHECK(expected, "read_points accepts a document that is no array of points by nlohmann's reading");
        FUZZ_CHECK(*expected == points, "read_points reads other values than nlohmann");
    }
}

void dump_path(std::string_view text, const JsonFacts& facts) {
    DcelDump d;
    try {
        d = io::read_dump(text);
    } catch (const InvalidInput& e) {
        check_clean(e, true);
        return;
    }
    if (comparable(facts)) FUZZ_CHECK(dump_matches(text, d), "read_dump reads other values than nlohmann");
    FUZZ_CHECK(same_dump(io::read_dump(io::write_dump(d, io::DumpStyle::Compact)), d), "dump round trip changed it");
    check_validators_agree(d);
}

void faces_path(std::string_view text, const JsonFacts& facts) {
    std::vector<std::vector<Index>> cycles;
    const auto expected = comparable(facts) ? expected_faces(text) : std::nullopt;
    try {
        cycles = io::read_faces_answer(text);
    } catch (const InvalidInput& e) {
        check_clean(e, true);
        // An index nlohmann rounded to an integer is one the reader must refuse.
        FUZZ_CHECK(!expected || facts.rounded_to_integer,
                   "read_faces_answer refuses an answer nlohmann reads: " << e.what());
        return;
    }
    if (comparable(facts)) {
        FUZZ_CHECK(expected, "read_faces_answer accepts a document that is no answer by nlohmann's reading");
        FUZZ_CHECK(*expected == cycles, "read_faces_answer reads other values than nlohmann");
    }
    std::vector<std::vector<VertexId>> ids;
    for (const auto& c : cycles) {
        ids.emplace_back();
        for (const Index v : c) ids.back().push_back(VertexId(v));
    }
    FUZZ_CHECK(io::read_faces_answer(io::write_faces(ids)) == cycles, "faces round trip changed them");
}

void answer_path(std::string_view text) {
    std::variant<std::vector<std::vector<Index>>, DcelDump> answer;
    try {
        answer = io::read_answer(text);
    } catch (const InvalidInput& e) {
        check_clean(e, true);
        return;
    }
    // read_answer only dispatches: its result must be what the reader it
    // chose gives on its own (which must not throw now).
    if (const auto* dump = std::get_if<DcelDump>(&answer)) {
        FUZZ_CHECK(same_dump(*dump, io::read_dump(text)), "read_answer and read_dump differ");
    } else {
        FUZZ_CHECK(std::get<0>(answer) == io::read_faces_answer(text), "read_answer and read_faces_answer differ");
    }
}

}  // namespace
}  // namespace dcel::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > dcel::fuzz::kMaxInput) return -1;  // -1: not added to the corpus
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const dcel::fuzz::JsonFacts facts = dcel::fuzz::json_facts(text);
    dcel::fuzz::check_json_syntax(text, facts);
    dcel::fuzz::check_decimal_routes(text);
    dcel::fuzz::graph_path(text, facts);
    dcel::fuzz::points_path(text, facts);
    dcel::fuzz::dump_path(text, facts);
    dcel::fuzz::faces_path(text, facts);
    dcel::fuzz::answer_path(text);
    return 0;
}
