// The exact rotation system of a graph drawn with straight edges: around
// every vertex, its outgoing half-edges counterclockwise from east, by the
// oracles' own angle order (exact.hpp). Sorted once per graph and shared:
// the reference DCEL's next, Boost's embedding (the same rings reversed,
// clockwise) and the oracle harness's check of faces_around all read it.
#pragma once

#include <vector>

#include "dcel/geometry/point.hpp"
#include "dcel/ids.hpp"

namespace dcel::oracle {

// Half-edges by their origins and twins, over a list of points: a dump's
// own numbering, or a graph's (half-edge 2k runs u->v of edge k, 2k+1 back).
struct HalfEdgeGraph {
    std::vector<Point> points;
    std::vector<Index> origin;  // per half-edge
    std::vector<Index> twin;    // per half-edge: a fixed-point-free involution
};

struct Rotations {
    std::vector<std::vector<Index>> ring;  // per vertex: its outgoing half-edges, counterclockwise from east
    std::vector<Index> position;           // per half-edge: where it sits in its origin's ring
};

// Requires no two half-edges leaving a vertex in the same direction (a valid graph).
[[nodiscard]] Rotations rotation_system(const HalfEdgeGraph& h);

}  // namespace dcel::oracle
