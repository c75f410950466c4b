// Peer: the classic atan2 construction (shared/seeds/000), with its next rule
// fixed: next(h) = the half-edge leaving v just clockwise of twin(h), i.e.
// ring_v[pos(twin(h)) - 1] in the counterclockwise ring. Everything else is
// as the seed has it: per-vertex vectors of (atan2, half-edge), a linear
// scan for each twin's ring position (O(sum of d^2)), a walk of the cycles.
// No validation, no holes, floating-point angles: bench only.
#pragma once

#include "dcel/graph.hpp"
#include "peers/cycles.hpp"

namespace dcel::bench {

// Returns the cycles as the seed does (its output is part of its cost).
[[nodiscard]] Cycles atan2_cycles(const PlanarGraph& g);

}  // namespace dcel::bench
