#include "dcel/ring_sort.hpp"

#include <algorithm>
#include <cmath>

#include "dcel/geometry/predicates.hpp"

namespace dcel {
namespace {

// The exact order: quadrant, then orient2d, then half-edge id.
struct ExactLess {
    Point centre;
    bool operator()(const RingEntry& a, const RingEntry& b) const {
        if (a.quadrant != b.quadrant) return a.quadrant < b.quadrant;
        const Sign s = orient2d(centre, a.target, b.target);  // positive: a comes first
        return s == Sign::Zero ? a.half_edge < b.half_edge : s == Sign::Positive;
    }
};

// A guess at the angle within the quadrant, only used to order entries
// before the exact check: b / (a + b) in [0, 1], with (a, b) the direction
// turned into the first quadrant. Monotone in the true angle up to
// rounding; NaN (from overflowed differences) becomes 0.
double approximate_angle(Point centre, const RingEntry& e) {
    const double dx = e.target.x - centre.x;
    const double dy = e.target.y - centre.y;
    double a = 0;
    double b = 0;
    switch (e.quadrant) {
        case 0: a = dx, b = dy; break;
        case 1: a = dy, b = -dx; break;
        case 2: a = -dx, b = -dy; break;
        default: a = -dy, b = dx; break;
    }
    const double t = b / (a + b);
    return t >= 0 && t <= 1 ? t : 0.0;
}

template <class Less>
void insertion_sort(std::span<RingEntry> ring, Less less) {
    for (std::size_t i = 1; i < ring.size(); ++i) {
        const RingEntry e = ring[i];
        std::size_t j = i;
        for (; j > 0 && less(e, ring[j - 1]); --j) ring[j] = ring[j - 1];
        ring[j] = e;
    }
}

}  // namespace

std::size_t sort_ring(Point centre, std::span<RingEntry> ring) {
    for (RingEntry& e : ring) e.quadrant = quadrant_of(centre, e.target);
    const ExactLess exact{centre};
    if (ring.size() > 24) {
        std::sort(ring.begin(), ring.end(), exact);
        return first_same_direction(centre, ring);
    }
    // Small rings: sort by the approximate angle (cheap comparisons of
    // doubles), then confirm each adjacent pair exactly. A sequence whose
    // neighbours are all in exact order is in exact order, so the guess is
    // only ever a shortcut; when a pair is out of order (directions closer
    // than rounding can tell), sort exactly.
    double key[24];
    for (std::size_t i = 0; i < ring.size(); ++i) key[i] = approximate_angle(centre, ring[i]);
    for (std::size_t i = 1; i < ring.size(); ++i) {
        const RingEntry e = ring[i];
        const double k = key[i];
        std::size_t j = i;
        auto before = [&](std::size_t x) {  // e goes before ring[x]
            if (e.quadrant != ring[x].quadrant) return e.quadrant < ring[x].quadrant;
            return k < key[x] || (k == key[x] && e.half_edge < ring[x].half_edge);
        };
        for (; j > 0 && before(j - 1); --j) {
            ring[j] = ring[j - 1];
            key[j] = key[j - 1];
        }
        ring[j] = e;
        key[j] = k;
    }
    // The same orient2d calls also find the first same-direction pair.
    std::size_t same = ring.size();
    for (std::size_t i = 0; i + 1 < ring.size(); ++i) {
        const RingEntry& a = ring[i];
        const RingEntry& b = ring[i + 1];
        if (a.quadrant != b.quadrant) continue;  // the sort above compared quadrants exactly
        const Sign s = orient2d(centre, a.target, b.target);
        if (s == Sign::Zero && a.half_edge < b.half_edge) {
            if (same == ring.size()) same = i;
        } else if (s != Sign::Positive) {
            insertion_sort(ring, exact);
            return first_same_direction(centre, ring);
        }
    }
    return same;
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
