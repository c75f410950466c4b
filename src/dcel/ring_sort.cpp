#include "dcel/ring_sort.hpp"

#include <algorithm>

#include "dcel/geometry/predicates.hpp"

namespace dcel {

void sort_ring(Point centre, std::span<RingEntry> ring) {
    for (RingEntry& e : ring) e.quadrant = quadrant_of(centre, e.target);
    const auto less = [centre](const RingEntry& a, const RingEntry& b) {
        if (a.quadrant != b.quadrant) return a.quadrant < b.quadrant;
        const Sign s = orient2d(centre, a.target, b.target);  // positive: a comes first
        return s == Sign::Zero ? a.half_edge < b.half_edge : s == Sign::Positive;
    };
    if (ring.size() > 24) {
        std::sort(ring.begin(), ring.end(), less);
        return;
    }
    for (std::size_t i = 1; i < ring.size(); ++i) {  // insertion sort: rings are small
        const RingEntry e = ring[i];
        std::size_t j = i;
        for (; j > 0 && less(e, ring[j - 1]); --j) ring[j] = ring[j - 1];
        ring[j] = e;
    }
}

std::size_t first_same_direction(Point centre, std::span<const RingEntry> ring) {
    for (std::size_t i = 0; i + 1 < ring.size(); ++i) {
        if (ring[i].quadrant == ring[i + 1].quadrant &&
            orient2d(centre, ring[i].target, ring[i + 1].target) == Sign::Zero) {
            return i;
        }
    }
    return ring.size();
}

}  // namespace dcel
