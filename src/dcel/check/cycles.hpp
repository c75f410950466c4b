// Internal to dcel::check: matching an answer's vertex cycles against the
// reference's boundary cycles, shared by the faces and the dump comparisons.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "dcel/check/collector.hpp"
#include "dcel/check/compare.hpp"
#include "dcel/dcel.hpp"

namespace dcel::check::detail {

// The reference, indexed for lookups by vertex pair and by cycle.
class Reference {
public:
    explicit Reference(const Dcel& d);

    [[nodiscard]] const Dcel& dcel() const { return d_; }
    // The half-edge u->v, or null when u, v is not an edge (ids must be < V).
    [[nodiscard]] HalfEdgeId find(Index u, Index v) const;
    [[nodiscard]] Index cycle_of(HalfEdgeId h) const { return cycle_of_[h.index()]; }
    [[nodiscard]] Index cycle_count() const { return static_cast<Index>(smallest_.size()); }
    [[nodiscard]] Index cycle_length(Index c) const { return length_[c]; }
    // Cycles are numbered in order of their smallest half-edge, as `dcel faces` lists them.
    [[nodiscard]] std::vector<Index> cycle_vertices(Index c) const;

private:
    const Dcel& d_;
    std::vector<std::uint64_t> keys_;  // (origin << 32 | target), sorted
    std::vector<HalfEdgeId> by_key_;   // the half-edge of each key
    std::vector<Index> cycle_of_;
    std::vector<Index> length_;
    std::vector<HalfEdgeId> smallest_;
};

// How the answer names its cycles in messages: "answer cycle 3 [0, 1, 2]"
// for a faces answer, "the answer's cycle through h5 [0, 1, 2]" for a dump.
struct AnswerCycles {
    const CycleList* cycles = nullptr;
    std::vector<HalfEdgeId> through;  // dumps: one answer half-edge per cycle; empty for faces
    // Faces: the number the answer gave cycle i, when some were set aside
    // before matching (null: cycle i is answer cycle i).
    const std::vector<std::size_t>* numbering = nullptr;
    [[nodiscard]] std::string label(std::size_t i) const;
};

enum class CycleStatus : std::uint8_t {
    Invalid,      // empty, a vertex id out of range, or a step that is not an edge
    Matched,      // a reference cycle, the first time the answer lists it
    Duplicate,    // a reference cycle the answer already listed
    Reversed,     // a missing reference cycle, walked backwards
    Unexplained,  // none of the above
};

struct CycleMatch {
    std::vector<CycleStatus> status;     // per answer cycle
    std::vector<Index> reference_cycle;  // per answer cycle: for Matched, Duplicate, Reversed
    std::vector<Index> first_match;      // per reference cycle: the answer cycle, or kNoIndex
};

// Reports vertex-count, not-an-edge, wrong-next, reversed, missing and extra
// cycles into `out`, and returns what each cycle turned out to be.
CycleMatch match_cycles(const Reference& ref, const AnswerCycles& answer, Collector& out);

// "[0, 1, 2]"; long cycles are cut after a dozen vertices.
[[nodiscard]] std::string cycle_text(std::span<const Index> vertices);

}  // namespace dcel::check::detail
