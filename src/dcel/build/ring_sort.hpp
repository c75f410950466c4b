// Sorting the half-edges that leave one vertex into exact counterclockwise
// order from east, as compare_angle orders them, ties by half-edge id.
//
// Each direction first gets its quadrant from coordinate comparisons
// ([0, pi/2), [pi/2, pi), [pi, 3pi/2), [3pi/2, 2pi)); two directions in one
// quadrant are less than pi/2 apart, so orient2d decides between them. This
// is the order compare_angle gives, with fewer orient2d calls. A ring of two
// (most vertices of chains, polygons and trees) gets the exact comparator
// once. Larger rings are first ordered by a floating-point guess at the angle (a branch-free
// network up to 8 entries, insertion sort up to 24, std::sort on integer
// keys above), then confirmed with one orient2d per adjacent pair; when the
// guess was wrong anywhere, the ring is sorted again exactly.
// O(d log d) for d entries.
#pragma once

#include <cstddef>
#include <span>

#include "dcel/geometry/point.hpp"
#include "dcel/geometry/predicates.hpp"
#include "dcel/ids.hpp"

namespace dcel::detail {

struct RingEntry {
    Point target;  // where the half-edge goes
    HalfEdgeId half_edge;
    Index payload = 0;  // carried along (build keeps the target's rank here)
    unsigned char quadrant = 0;
};

// 0..3 as above; requires p != centre.
[[nodiscard]] inline unsigned char quadrant_of(Point centre, Point p) {
    if (p.y > centre.y) return p.x > centre.x ? 0 : 1;
    if (p.y < centre.y) return p.x < centre.x ? 2 : 3;
    return p.x > centre.x ? 0 : 2;
}

// A ring of two, a and b (most vertices of chains, polygons and trees), in
// sort_ring's order: whether they swap, and whether they point the same
// way (then the smaller half-edge id comes first). Targets differ from
// centre. Different quadrants need no orient2d at all.
struct PairOrder {
    bool swap = false;
    bool same_direction = false;
};
[[nodiscard]] inline PairOrder order_pair(Point centre, Point a, HalfEdgeId ha, Point b, HalfEdgeId hb) {
    const unsigned char qa = quadrant_of(centre, a);
    const unsigned char qb = quadrant_of(centre, b);
    if (qa != qb) return {qb < qa, false};
    const Sign s = orient2d(centre, a, b);  // positive: a first
    return {s == Sign::Negative || (s == Sign::Zero && hb < ha), s == Sign::Zero};
}

// Fills each entry's quadrant and sorts; returns first_same_direction of the
// result. Requires every target != centre.
[[nodiscard]] std::size_t sort_ring(Point centre, std::span<RingEntry> ring);

// In a sorted ring: the first i with ring[i] and ring[i+1] pointing the same
// way, or ring.size() when all directions differ. O(d).
[[nodiscard]] std::size_t first_same_direction(Point centre, std::span<const RingEntry> ring);

}  // namespace dcel::detail
