// The custom mutator and cross-over of the edit harness: whole steps are
// inserted, deleted, copied, swapped or changed, so libFuzzer's mutations
// keep the step structure (a byte mutation that shifts the input by one
// turns every later step into noise). New steps often carry a raw point
// near the start map's geometry: a vertex moved a few ulps, or a point on
// (within rounding of) the line through two vertices, where an edit's
// exactness is tested hardest.
#pragma once

#include <cstddef>
#include <cstdint>

namespace dcel::fuzz {

std::size_t mutate_edit_input(std::uint8_t* data, std::size_t size, std::size_t max_size, unsigned int seed);
std::size_t cross_over_edit_inputs(const std::uint8_t* data1, std::size_t size1, const std::uint8_t* data2,
                                   std::size_t size2, std::uint8_t* out, std::size_t max_out, unsigned int seed);

}  // namespace dcel::fuzz
