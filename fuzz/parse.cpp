// parse: arbitrary bytes as JSON, through every reader and build().
//
// Checks that each reader (graph, dump, faces answer, answer) either gives a
// clean InvalidInput (a kind a reader may raise, a one-line message) or a
// value that survives a write/read round trip unchanged; that a graph read
// builds into a DCEL that validate() passes, or is refused with a clean
// error; and that validate() and validate_all() agree on any dump read,
// however broken. Never a crash, hang, leak or undefined behaviour.
#include <bit>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>

#include "dcel/build.hpp"
#include "dcel/error.hpp"
#include "dcel/io/dcel_json.hpp"
#include "dcel/io/graph_json.hpp"
#include "dcel/validate.hpp"
#include "support/fuzz_check.hpp"

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

void graph_path(std::string_view text) {
    PlanarGraph g;
    try {
        g = io::read_graph(text);
    } catch (const InvalidInput& e) {
        check_clean(e, true);
        return;
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
    const DcelDump dump = to_dump(d);
    for (const io::DumpStyle style : {io::DumpStyle::Lines, io::DumpStyle::Compact}) {
        FUZZ_CHECK(same_dump(io::read_dump(io::write_dump(dump, style)), dump), "dump round trip changed it");
    }
}

void dump_path(std::string_view text) {
    DcelDump d;
    try {
        d = io::read_dump(text);
    } catch (const InvalidInput& e) {
        check_clean(e, true);
        return;
    }
    FUZZ_CHECK(same_dump(io::read_dump(io::write_dump(d, io::DumpStyle::Compact)), d), "dump round trip changed it");
    check_validators_agree(d);
}

void faces_path(std::string_view text) {
    std::vector<std::vector<Index>> cycles;
    try {
        cycles = io::read_faces_answer(text);
    } catch (const InvalidInput& e) {
        check_clean(e, true);
        return;
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
    dcel::fuzz::graph_path(text);
    dcel::fuzz::dump_path(text);
    dcel::fuzz::faces_path(text);
    dcel::fuzz::answer_path(text);
    return 0;
}
