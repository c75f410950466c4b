// edit: sequences of edits (dcel/edit.hpp), compared with build() and with
// the harness's own model of the graph.
//
// Compares each edit's verdict with build(): the oracle
// (tests/support/edit_oracle.hpp) asks build() about the graph the edit would
// make, and the edit must succeed exactly when build() accepts it. A refused
// edit must throw TopologyError or InvalidInput and leave every array as it
// was. After every accepted edit: validate() passes; the DCEL equals the
// rebuild of its own graph up to face numbering
// (tests/support/rebuild_compare.hpp); its vertices and edges are bit for bit
// those of the harness's model (support/edit_model.hpp, from the documented
// id rules), and its Change reports the vertex and edge ids the model
// expects, and a face added or removed exactly when the count changes. At
// the end: the DCEL equals a from-scratch build() of the model's graph.
//
// Input: bytes. Byte 0 picks the start map: 0 empty, 1 the countries, 2
// nested squares with holes in holes (mod 8; 3..7 a generated graph: family
// byte, seed byte, size byte). Each step then takes 6 bytes: op, a, b, x, y,
// flags. x and y are small grid coordinates (-1 .. 7); flags bits 0-1 give
// `at` (the new point at a vertex or an edge's middle), and bit 2 says 16
// raw bytes follow: the point as two doubles (non-finite ones become 0), so
// exactness is fuzzed too; bits 3-5 all set make a and b wild ids, any
// 32-bit id instead of one modulo the count, so that the refusal of an id
// past the end (or the null id) is fuzzed too (support/edit_input.hpp). The custom mutator
// (support/edit_mutator.hpp) inserts, deletes, copies, swaps and changes
// whole steps, and gives new steps raw points a few ulps from the start
// map's vertices or within rounding of the line through two of them.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "dcel/dump.hpp"
#include "support/edit_input.hpp"
#include "support/edit_model.hpp"
#include "support/edit_mutator.hpp"
#include "support/edit_oracle.hpp"
#include "support/fuzz_check.hpp"
#include "support/rebuild_compare.hpp"

namespace dcel::fuzz {
namespace {

using test_support::Step;

// Each step costs a rebuild, a validation and an oracle build of a graph of
// at most a few hundred elements; 64 steps keep an input well under a
// second. 4 KB holds 64 steps even when every one carries raw doubles.
constexpr std::size_t kMaxInput = 4096;
constexpr int kMaxSteps = 64;

// One step: the verdict against the oracle, then the state against the
// model. `model` is the graph the DCEL must hold, updated on success.
void check_step(Dcel& d, PlanarGraph& model, const Step& s, int index) {
    const test_support::Resolved r = test_support::resolve(d, s);
    if (!r.applicable) return;
    const bool valid = test_support::expected_valid(d, s, r);
    const DcelDump before = to_dump(d);
    const std::size_t faces_before = d.num_faces();
    Change change;
    bool refused = false;
    bool bad_index = false;
    std::string reason;
    try {
        change = test_support::apply(d, s, r);
    } catch (const TopologyError& e) {
        refused = true;
        reason = e.what();
    } catch (const InvalidInput& e) {
        refused = true;
        reason = e.what();
        bad_index = e.kind() == InputErrorKind::BadIndex;
    }
    FUZZ_CHECK(!(refused && valid), "step " << index << " " << s << ": refused an edit build() accepts: " << reason);
    FUZZ_CHECK(!(!refused && !valid), "step " << index << " " << s << ": accepted an edit build() rejects");
    FUZZ_CHECK(r.ids_in_range || bad_index,
               "step " << index << " " << s << ": an id past the end was not refused as a bad index: " << reason);
    if (refused) {
        FUZZ_CHECK(test_support::same_dump(before, to_dump(d)),
                   "step " << index << " " << s << ": a refusal changed the DCEL");
        return;
    }
    const auto problem = test_support::soundness_problem(d);  // validate(), and equality with the rebuild of to_graph(d)
    FUZZ_CHECK(!problem, "step " << index << " " << s << ": unsound after the edit: " << *problem);

    const ExpectedEdit expected = expected_after(model, s, r);
    const auto wrong = graph_difference(to_graph(d), expected.graph);
    FUZZ_CHECK(!wrong, "step " << index << " " << s << ": " << *wrong);
    FUZZ_CHECK(change.vertices == expected.vertices && change.edges == expected.edges,
               "step " << index << " " << s << ": the Change's vertex or edge ids are not the documented ones");
    FUZZ_CHECK((d.num_faces() > faces_before) == !change.faces.added.is_null() &&
                   (d.num_faces() < faces_before) == !change.faces.removed.is_null(),
               "step " << index << " " << s << ": " << faces_before << " faces became " << d.num_faces()
                       << ", but the Change says otherwise");
    model = expected.graph;
}

}  // namespace
}  // namespace dcel::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace dcel;
    if (size > fuzz::kMaxInput) return -1;
    fuzz::Bytes in(data, size);
    PlanarGraph model = fuzz::start_graph(in);
    Dcel d = build(model);
    for (int step = 0; step < fuzz::kMaxSteps && !in.empty(); ++step) fuzz::check_step(d, model, fuzz::read_step(in), step);

    // The end state against a from-scratch build of the model's graph.
    const auto difference = test_support::difference_between(d, build(model));
    FUZZ_CHECK(!difference, "after all steps, the DCEL differs from build() of the model's graph: " << *difference);
    return 0;
}

extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t max_size,
                                               unsigned int seed) {
    return dcel::fuzz::mutate_edit_input(data, size, std::min(max_size, dcel::fuzz::kMaxInput), seed);
}

extern "C" std::size_t LLVMFuzzerCustomCrossOver(const std::uint8_t* data1, std::size_t size1, const std::uint8_t* data2,
                                                 std::size_t size2, std::uint8_t* out, std::size_t max_out,
                                                 unsigned int seed) {
    return dcel::fuzz::cross_over_edit_inputs(data1, size1, data2, size2, out, std::min(max_out, dcel::fuzz::kMaxInput),
                                              seed);
}
