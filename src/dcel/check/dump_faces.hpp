// Internal to dcel::check: a dump's next-cycles as vertex cycles, and the
// comparison of its face records (outer boundaries, holes, isolated
// vertices) with the reference, once its cycles are matched.
#pragma once

#include <vector>

#include "dcel/check/collector.hpp"
#include "dcel/check/cycles.hpp"
#include "dcel/dump.hpp"

namespace dcel::check::detail {

struct DumpCycles {
    CycleList cycles;                 // origins along next, from the smallest half-edge
    std::vector<HalfEdgeId> through;  // that smallest half-edge, per cycle
    std::vector<Index> cycle_of;      // per half-edge of the dump
};

// Requires references in range and next a permutation (validate's
// References and NextPrev checkers passed).
[[nodiscard]] DumpCycles dump_cycles(const DcelDump& d);

// Requires the same, plus `match` from match_cycles over `cycles`.
void compare_face_records(const Reference& ref, const DcelDump& answer, const DumpCycles& cycles, const CycleMatch& match,
                          Collector& out);

}  // namespace dcel::check::detail
