// Test support: random valid maps grown by random edits from an empty DCEL,
// with a fixed seed (so a failure reproduces). Refused edits are skipped.
// Points lie on a small integer grid, and splits at midpoints add halves, so
// collinear points, shared x-coordinates and vertical edges are common.
#pragma once

#include <cstdint>
#include <random>

#include "dcel/edit.hpp"
#include "dcel/error.hpp"

namespace dcel::test_support {

inline Dcel random_map(std::uint64_t seed, int steps, int grid) {
    std::mt19937_64 rng(seed);
    auto below = [&](std::size_t n) { return static_cast<Index>(rng() % n); };
    auto coord = [&] { return static_cast<double>(below(static_cast<std::size_t>(grid) + 1)); };
    Dcel d;
    for (int i = 0; i < steps; ++i) {
        const std::size_t nv = d.num_vertices();
        const std::size_t ne = d.num_edges();
        try {
            switch (below(10)) {
                case 0:
                case 1: (void)add_vertex(d, {coord(), coord()}); break;
                case 7:
                    if (nv > 0) {
                        const Point p{coord(), coord()};  // a braced list draws left to right
                        const VertexId from(below(nv));
                        (void)add_edge_to_point(d, from, p);
                    }
                    break;
                case 8:
                    if (ne > 0) {
                        const HalfEdgeId h = half_edge_of(EdgeId(below(ne)), 0);
                        const Point a = d.point(d.origin(h));
                        const Point b = d.point(d.target(h));
                        (void)split_edge(d, edge_of(h), {(a.x + b.x) / 2, (a.y + b.y) / 2});
                    }
                    break;
                case 9:
                    if (ne > 0 && below(3) == 0) (void)remove_edge(d, EdgeId(below(ne)));
                    break;
                default:
                    if (nv > 1) {
                        // One draw per statement, so that gcc and clang builds make the same map.
                        const VertexId w(below(nv));
                        const VertexId u(below(nv));
                        (void)add_edge(d, u, w);
                    }
                    break;
            }
        } catch (const TopologyError&) {
            // refused: the map stays as it was
        }
    }
    return d;
}

}  // namespace dcel::test_support
