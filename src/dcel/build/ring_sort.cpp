#include "dcel/build/ring_sort.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>
#include <vector>

#include "dcel/geometry/predicates.hpp"

namespace dcel::detail {
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

// One comparator of a sorting network: branch-free (min/max become cmov).
inline void compare_swap(std::uint64_t& a, std::uint64_t& b) {
    const std::uint64_t lo = std::min(a, b);
    b = std::max(a, b);
    a = lo;
}

// Batcher's odd-even merge sort for 8 keys: 19 comparators, no branches,
// so the unpredictable comparisons of a ring's angles cost no mispredictions.
// Its first 5 comparators sort keys 0..3 on their own, which is all a ring
// of degree <= 4 (a grid's) needs. The keys are held in locals so that the
// network runs in registers: through memory, each comparator would wait on
// the previous one's stores.
void sort8(std::uint64_t* k, std::size_t n) {
    std::uint64_t k0 = k[0];
    std::uint64_t k1 = k[1];
    std::uint64_t k2 = k[2];
    std::uint64_t k3 = k[3];
    compare_swap(k0, k1);
    compare_swap(k2, k3);
    compare_swap(k0, k2);
    compare_swap(k1, k3);
    compare_swap(k1, k2);
    if (n > 4) {
        std::uint64_t k4 = k[4];
        std::uint64_t k5 = k[5];
        std::uint64_t k6 = k[6];
        std::uint64_t k7 = k[7];
        compare_swap(k4, k5);
        compare_swap(k6, k7);
        compare_swap(k4, k6);
        compare_swap(k5, k7);
        compare_swap(k5, k6);
        compare_swap(k0, k4);
        compare_swap(k1, k5);
        compare_swap(k2, k6);
        compare_swap(k3, k7);
        compare_swap(k2, k4);
        compare_swap(k3, k5);
        compare_swap(k1, k2);
        compare_swap(k3, k4);
        compare_swap(k5, k6);
        k[4] = k4;
        k[5] = k5;
        k[6] = k6;
        k[7] = k7;
    }
    k[0] = k0;
    k[1] = k1;
    k[2] = k2;
    k[3] = k3;
}

// The exact check after a guessed order: one orient2d per adjacent pair in
// one quadrant (the guess compared quadrants exactly). Returns the first
// same-direction index (ring.size() for none), or kWrongOrder.
constexpr std::size_t kWrongOrder = ~std::size_t{0};
std::size_t confirm(Point centre, std::span<const RingEntry> ring) {
    std::size_t same = ring.size();
    for (std::size_t i = 0; i + 1 < ring.size(); ++i) {
        const RingEntry& a = ring[i];
        const RingEntry& b = ring[i + 1];
        if (a.quadrant != b.quadrant) continue;
        const Sign s = orient2d(centre, a.target, b.target);
        if (s == Sign::Zero && a.half_edge < b.half_edge) {
            if (same == ring.size()) same = i;
        } else if (s != Sign::Positive) {
            return kWrongOrder;
        }
    }
    return same;
}

// The steps of sort_ring that run for every small ring are forced inline:
// left to GCC, the sorting network's step stays a call, which costs more
// than the network itself on rings of degree 3 to 6.
//
// Two entries: one exact comparison, no guess. Returns 0 when they leave
// in one direction, else 2.
[[gnu::always_inline]] inline std::size_t sort_two(Point centre, std::span<RingEntry> ring) {
    const PairOrder order = order_pair(centre, ring[0].target, ring[0].half_edge, ring[1].target, ring[1].half_edge);
    if (order.swap) std::swap(ring[0], ring[1]);
    return order.same_direction ? 0 : 2;
}

// Puts ring[key[j] & 0xFFFFFFFF] at position j for every j, in place, cycle
// by cycle of the permutation (a sorted copy of the ring would add 32 bytes
// an entry to the build's peak memory).
void apply_sorted_keys(std::span<RingEntry> ring, const std::vector<std::uint64_t>& key) {
    const std::size_t n = ring.size();
    std::vector<char> placed(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        if (placed[i] != 0) continue;
        const RingEntry first = ring[i];
        std::size_t j = i;
        for (;;) {
            placed[j] = 1;
            const std::size_t from = key[j] & 0xFFFFFFFFU;
            if (from == i) {
                ring[j] = first;
                break;
            }
            ring[j] = ring[from];
            j = from;
        }
    }
}

// Large rings (a star's centre, more than 24 entries): std::sort on integer
// keys (quadrant, 30 bits of the guess, position), then the exact
// confirmation; std::sort with the exact order when the guess was wrong.
std::size_t sort_large(Point centre, std::span<RingEntry> ring) {
    const std::size_t n = ring.size();
    std::vector<std::uint64_t> key(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto guess = static_cast<std::uint64_t>(approximate_angle(centre, ring[i]) * 0x1.fffffffp29);
        key[i] = (std::uint64_t{ring[i].quadrant} << 62U) | (guess << 32U) | i;
    }
    std::sort(key.begin(), key.end());
    apply_sorted_keys(ring, key);
    const std::size_t same = confirm(centre, ring);
    if (same != kWrongOrder) return same;
    std::sort(ring.begin(), ring.end(), ExactLess{centre});
    return first_same_direction(centre, ring);
}

// 3 to 8 entries in the guessed order: keys of quadrant (2 bits), the guess
// in [0, 1] (56 bits) and position (5 bits) through the sorting network,
// then the entries gathered in key order.
[[gnu::always_inline]] inline void guess_order_up_to_8(Point centre, std::span<RingEntry> ring) {
    const std::size_t n = ring.size();
    std::uint64_t key[8];
    for (std::size_t i = 0; i < 8; ++i) {
        if (i >= n) {
            key[i] = ~std::uint64_t{0};
            continue;
        }
        const auto guess = static_cast<std::uint64_t>(approximate_angle(centre, ring[i]) * 0x1p55);
        key[i] = (std::uint64_t{ring[i].quadrant} << 61U) | (guess << 5U) | i;
    }
    sort8(key, n);
    // Raw storage: an array of RingEntry would be zeroed on every call.
    static_assert(std::is_trivially_copyable_v<RingEntry>);
    alignas(RingEntry) std::byte sorted[8 * sizeof(RingEntry)];
    for (std::size_t i = 0; i < n; ++i) std::memcpy(sorted + i * sizeof(RingEntry), &ring[key[i] & 31U], sizeof(RingEntry));
    std::memcpy(ring.data(), sorted, n * sizeof(RingEntry));
}

// 9 to 24 entries in the guessed order: insertion sort on (quadrant, guess,
// half-edge), the guesses computed once and moved with their entries.
[[gnu::always_inline]] inline void guess_order_up_to_24(Point centre, std::span<RingEntry> ring) {
    const std::size_t n = ring.size();
    double key[24];
    for (std::size_t i = 0; i < n; ++i) key[i] = approximate_angle(centre, ring[i]);
    for (std::size_t i = 1; i < n; ++i) {
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
}

}  // namespace

// Small rings (3 to 24 entries): order by a floating-point guess at the
// angle, then confirm each adjacent pair exactly. A sequence whose
// neighbours are all in exact order is in exact order, so the guess is only
// ever a shortcut; when a pair is out of order (directions closer than
// rounding can tell), sort exactly. Ties in the guess keep the ring's order,
// i.e. half-edge order for rings that come in that order.
std::size_t sort_ring(Point centre, std::span<RingEntry> ring) {
    for (RingEntry& e : ring) e.quadrant = quadrant_of(centre, e.target);
    const std::size_t n = ring.size();
    if (n < 2) return n;  // nothing to order (and an empty span's data() may be null)
    if (n == 2) return sort_two(centre, ring);
    if (n > 24) return sort_large(centre, ring);
    if (n <= 8) {
        guess_order_up_to_8(centre, ring);
    } else {
        guess_order_up_to_24(centre, ring);
    }
    const std::size_t same = confirm(centre, ring);
    if (same != kWrongOrder) return same;
    insertion_sort(ring, ExactLess{centre});
    return first_same_direction(centre, ring);
}

std::size_t first_same_direction(Point centre, std::span<const RingEntry> ring) {
    for (std::size_t i = 0; i + 1 < ring.size(); ++i) {
        if (ring[i].quadrant == ring[i + 1].quadrant && orient2d(centre, ring[i].target, ring[i + 1].target) == Sign::Zero) {
            return i;
        }
    }
    return ring.size();
}

}  // namespace dcel::detail
