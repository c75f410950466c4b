// check: valid DCEL dumps corrupted by commands, through validate().
//
// Compares validate() with an independent judge (support/reference_dcel.hpp:
// brute-force exact geometry and a DCEL rebuilt from scratch): validate()
// must flag exactly the dumps that are not the correct DCEL of their own
// geometry. So it catches every corruption that changes the structure, and
// accepts what does not: renumbering faces, half-edges or vertices, naming
// a cycle or a vertex's outgoing half-edge by another half-edge, reordering
// lists, moving a vertex where the DCEL stays the same. validate() and
// validate_all() must agree, and neither may crash or hang.
//
// Input: a graph as in support/text_graph.hpp, then commands (word, numbers),
// applied in order to the dump of its build(). Ids are taken modulo the
// element count so a command always lands; a value of -1 is null:
//   next|prev|twin h x   origin h v   face h f     set a half-edge field
//   outer f h   inner f h   uninner f i   isolated f v   unisolated f i
//   out v h     noout (drop vertex_out)    x|y v value   move a vertex
//   swapnext a b     exchange next(a), next(b) and fix prev (a rewiring)
//   swapface f g | swaphalf a b | swapvertex a b   renumber (always valid)
//   addvertex x y    addface h    dropface
// e.g.  points 0 0, 4 0, 0 4 edges 0 1, 1 2, 2 0  swapnext 0 2
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>

#include "dcel/build.hpp"
#include "dcel/dump.hpp"
#include "dcel/error.hpp"
#include "dcel/io/dcel_json.hpp"
#include "dcel/validate.hpp"
#include "oracles/dump_judge.hpp"
#include "support/dump_edits.hpp"
#include "support/fuzz_check.hpp"
#include "support/text_graph.hpp"

namespace dcel::fuzz {
namespace {

using oracle::judge_dump;
using oracle::Judgement;

// The judge checks all pairs of the dump's graph (O(V E + E^2) exact
// orientations); small graphs and a few commands keep a run well under a
// millisecond, and every corruption is local.
constexpr std::size_t kMaxInput = 4096;
constexpr GraphCaps kCaps{16, 24};
constexpr std::size_t kMaxCommands = 8;

std::string show(const DcelDump& d) {
    try {
        return io::write_dump(d, io::DumpStyle::Compact);
    } catch (const InvalidInput&) {
        return "(a dump with a non-finite coordinate)";
    }
}

void check_dump(const DcelDump& d, const std::string& commands) {
    const CheckResult first = validate(d);
    const std::vector<Violation> all = validate_all(d);
    FUZZ_CHECK(first.has_value() == !all.empty(), "validate and validate_all disagree");
    const Judgement j = judge_dump(d);
    FUZZ_CHECK(first.has_value() == !j.valid,
               (first ? "validate flags [" + std::string(to_string(first->invariant)) + "] " + first->message
                      : std::string("validate passes"))
                   << "; the reference says " << (j.valid ? "valid" : j.reason) << "\ncommands:" << commands
                   << "\ndump: " << show(d));
}

}  // namespace
}  // namespace dcel::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace dcel;
    using namespace dcel::fuzz;
    if (size > kMaxInput) return -1;
    TokenReader in(std::string_view(reinterpret_cast<const char*>(data), size));
    const PlanarGraph g = decode_graph(in, kCaps);
    Dcel built;
    try {
        built = build(g);
    } catch (const InvalidInput&) {
        return -1;  // only valid graphs are corrupted; nonplanar covers the rest
    }
    DcelDump d = to_dump(built);
    const Judgement original = judge_dump(d);
    FUZZ_CHECK(original.valid, "the reference rejects build()'s DCEL: " << original.reason);

    std::string applied;
    for (std::size_t n = 0; n < kMaxCommands && !in.at_end(); ++n) applied += apply_edit(d, in);
    check_dump(d, applied);
    return 0;
}
