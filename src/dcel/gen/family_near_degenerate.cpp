// Near-degenerate coordinates. Either a thin fan (rays from the origin to
// consecutive lattice points on a line that nearly passes through it, so
// neighbouring directions differ by about 1/N^2 radians: far below what
// atan2 can resolve), or a graph from another family mapped coordinatewise by
// an exact, increasing affine map: a large offset with tiny differences, tiny
// magnitudes, or subnormals, with some zeros turned into -0.0. An increasing
// affine map per axis keeps every orientation sign, so validity and the
// combinatorial answer are unchanged. The maps are one-to-one, so the vertex
// count is the base family's (exactly n), and so is the cost.
#include <cmath>

#include "dcel/gen/families.hpp"

namespace dcel::gen::detail {
namespace {

// Valid by design: the P_i are distinct points of a line that misses the
// centre, so the rays to them have distinct directions and meet only at the
// centre; each Q_i = -P_i lies on the opposite ray. Chain edges join
// consecutive lattice points of one line (nothing between them) and meet a
// ray only where it ends. O(n).
PlanarGraph thin_fan(Rng& rng, std::size_t n) {
    PlanarGraph g;
    if (n == 0) return g;
    const std::int64_t N = (std::int64_t{1} << rng.between(20, 50)) + rng.between(0, 1 << 20);
    g.vertices.push_back(at(0, 0));
    const VertexId centre(0);
    // P_i = (N + i, N + i + 1) on y = x + 1, and Q_i = -P_i on y = x - 1:
    // the cross product of consecutive points is -1 (a triangle of area 1/2).
    const std::size_t on_p_side = n / 2;  // and the other n - 1 - n / 2 on the Q side
    for (const std::int64_t sign : {1, -1}) {
        const std::size_t count = sign == 1 ? on_p_side : n - 1 - on_p_side;
        for (std::size_t i = 0; i < count; ++i) {
            const auto k = static_cast<std::int64_t>(i);
            g.vertices.push_back(at(sign * (N + k), sign * (N + k + 1)));
            const VertexId p(static_cast<Index>(g.vertices.size() - 1));
            if (rng.chance(3, 4)) g.edges.push_back({centre, p});
            if (i > 0 && rng.chance(3, 4)) g.edges.push_back({VertexId(p.index() - 1), p});
        }
    }
    return g;
}

PlanarGraph base_graph(Rng& rng, std::size_t n) {
    switch (rng.below(6)) {
        case 0: return random_segments(rng, n);
        case 1: return triangulation(rng, n);
        case 2: return star(rng, n);
        case 3: return collinear_chain(rng, n);
        case 4: return grid_with_holes(rng, n);
        default: return components(rng, n);
    }
}

}  // namespace

PlanarGraph near_degenerate(Rng& rng, std::size_t n) {
    if (rng.chance(1, 3)) return thin_fan(rng, n);
    PlanarGraph g = base_graph(rng, n);  // integer coordinates below 2^26
    switch (rng.below(3)) {
        case 0: {
            // x -> (M + x) 2^(k-52) with 2^52 + 2^50 <= M < 2^52 + 2^51 + 2^50:
            // M + x is an integer below 2^53, so every value is exact and the
            // points differ by a few units in the last place of the offset.
            const std::int64_t mx = (std::int64_t{1} << 52) + (std::int64_t{1} << 50) +
                                    rng.between(0, (std::int64_t{1} << 51) - 1);
            const std::int64_t my = (std::int64_t{1} << 52) + (std::int64_t{1} << 50) +
                                    rng.between(0, (std::int64_t{1} << 51) - 1);
            const int kx = static_cast<int>(rng.between(-30, 60));
            const int ky = static_cast<int>(rng.between(-30, 60));
            for (Point& p : g.vertices) {
                p = {std::ldexp(static_cast<double>(mx + static_cast<std::int64_t>(p.x)), kx - 52),
                     std::ldexp(static_cast<double>(my + static_cast<std::int64_t>(p.y)), ky - 52)};
            }
            break;
        }
        case 1: {
            // Tiny magnitudes, down into the subnormals: x 2^-e is exact for
            // an integer x when e <= 1074.
            const int e = static_cast<int>(rng.between(1000, 1074));
            for (Point& p : g.vertices) p = {std::ldexp(p.x, -e), std::ldexp(p.y, -e)};
            break;
        }
        default: break;  // keep the integers; only the zeros change sign
    }
    for (Point& p : g.vertices) {
        if (p.x == 0 && rng.chance(1, 2)) p.x = -0.0;
        if (p.y == 0 && rng.chance(1, 2)) p.y = -0.0;
    }
    return g;
}

}  // namespace dcel::gen::detail
