// Every boundary cycle of a Dcel, in the canonical order: each cycle starts
// at its smallest half-edge, and cycles come in order of that half-edge.
// This is the order of `dcel faces` output and of boundary_cycles().
//
// Why not the plain loop (each id not yet seen, in increasing order, starts
// a walk): on a DCEL whose ids are not in spatial order (shuffled input),
// every step of a walk is a cache miss that depends on the previous one, so
// the walks run at memory latency. The scan fetches the first steps of the
// walks a few dozen ids ahead while it walks the current one, so their
// misses overlap. O(H) time, H bits of memory.
#pragma once

#include <functional>
#include <span>

#include "dcel/dcel.hpp"

namespace dcel::detail {

// How a scan went, for tests and benchmarks: the ids are scanned in blocks,
// each with or without the prefetch pipeline (see cycle_scan.cpp).
struct CycleScanStats {
    std::size_t blocks = 0;
    std::size_t prefetched_blocks = 0;
};

// Calls visit(origins) once per boundary cycle, in the order above, with the
// origins of the cycle's half-edges in next order. The span is valid only
// during the call.
//
// The prefetch pipeline runs only on DCELs of at least prefetch_from
// half-edges: on smaller ones the arrays sit in cache and it only costs
// (tests lower it to reach the pipeline on small inputs).
inline constexpr std::size_t kPrefetchFromHalfEdges = std::size_t{1} << 18;
CycleScanStats for_each_boundary_cycle(const Dcel& d, const std::function<void(std::span<const VertexId>)>& visit,
                                       std::size_t prefetch_from = kPrefetchFromHalfEdges);

}  // namespace dcel::detail
