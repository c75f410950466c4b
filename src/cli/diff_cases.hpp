// The case schedule of `dcel diff`: case i is a graph from dcel::gen, with
// the family cycling through every family and the size growing with i, all
// determined by (run seed, i, max vertices). So a case replays from its
// number alone, whatever --cases or --time the run had.
#pragma once

#include <cstddef>
#include <cstdint>

#include "dcel/gen/generate.hpp"

namespace dcel::cli {

struct CaseSpec {
    std::size_t number = 0;  // i, counted from 0
    gen::Params params;      // family, seed and target size handed to gen::generate
};

// Family i mod (number of families); target size 2, 2, ..., growing by 3
// every round of all families, capped at max_vertices; the generator seed is
// mixed from the run seed and i.
[[nodiscard]] CaseSpec case_spec(std::uint64_t run_seed, std::size_t i, std::size_t max_vertices);

}  // namespace dcel::cli
