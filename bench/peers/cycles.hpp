// What every implementation hands back for --verify: its boundary cycles as
// sequences of vertex ids, in next order. Compared as a multiset of
// canonical cycles (each rotated to its smallest directed edge), so the
// numbering of half-edges and faces does not matter.
#pragma once

#include <cstdint>
#include <vector>

namespace dcel::bench {

using Cycles = std::vector<std::vector<std::uint32_t>>;

// A peer's answer: how many boundary cycles it found and, when asked for
// (--verify), the cycles themselves. Timed runs ask only for the count, so
// that listing cycles costs nothing the peer would not pay anyway.
struct PeerResult {
    std::size_t count = 0;
    Cycles cycles;
};

// Sorted canonical form, for comparing two answers.
[[nodiscard]] Cycles canonical(Cycles cycles);

}  // namespace dcel::bench
