// One function per generator family (internal to dcel::gen). Each returns a
// valid planar straight-line graph with about `n` vertices, built from
// integer coordinates (NearDegenerate maps them exactly to awkward doubles).
// Validity comes from GraphBuilder's brute-force checks, or from a
// construction whose validity is argued where it skips them.
#pragma once

#include <cstddef>
#include <cstdint>

#include "dcel/gen/rng.hpp"
#include "dcel/graph.hpp"

namespace dcel::gen::detail {

[[nodiscard]] PlanarGraph random_segments(Rng& rng, std::size_t n);
[[nodiscard]] PlanarGraph triangulation(Rng& rng, std::size_t n);
[[nodiscard]] PlanarGraph tree(Rng& rng, std::size_t n);
[[nodiscard]] PlanarGraph grid_with_holes(Rng& rng, std::size_t n);
[[nodiscard]] PlanarGraph nested_polygons(Rng& rng, std::size_t n);
[[nodiscard]] PlanarGraph comb(Rng& rng, std::size_t n);
[[nodiscard]] PlanarGraph star(Rng& rng, std::size_t n);
[[nodiscard]] PlanarGraph collinear_chain(Rng& rng, std::size_t n);
[[nodiscard]] PlanarGraph components(Rng& rng, std::size_t n);
[[nodiscard]] PlanarGraph near_degenerate(Rng& rng, std::size_t n);

// A small primitive integer direction (gcd 1), uniformly from a fixed list.
struct Step {
    std::int64_t dx;
    std::int64_t dy;
};
[[nodiscard]] Step random_direction(Rng& rng);

[[nodiscard]] inline Point at(std::int64_t x, std::int64_t y) { return {static_cast<double>(x), static_cast<double>(y)}; }

}  // namespace dcel::gen::detail
