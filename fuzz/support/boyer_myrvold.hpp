// Boost's Boyer-Myrvold planarity test as an oracle: is the abstract graph
// planar at all, whatever the coordinates? If not, no straight-line drawing
// of it is free of crossings, so build() must reject it.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "dcel/ids.hpp"

namespace dcel::fuzz {

// Vertices 0..n-1; edges with an end >= n are ignored. Self-loops and
// repeated edges are dropped first: they never change planarity, and Boost's
// test is documented for simple graphs.
[[nodiscard]] bool boost_is_planar(std::size_t n, const std::vector<std::pair<Index, Index>>& edges);

}  // namespace dcel::fuzz
