// Families with faces inside faces: grids with holes and islands, nested
// polygons, and many small components mixed with isolated vertices.
#include <algorithm>
#include <cmath>

#include "dcel/gen/brute_force.hpp"
#include "dcel/gen/families.hpp"
#include "dcel/gen/graph_builder.hpp"
#include "dcel/geometry/predicates.hpp"

namespace dcel::gen::detail {

PlanarGraph grid_with_holes(Rng& rng, std::size_t n) {
    GraphBuilder b;
    const auto side = static_cast<std::int64_t>(std::sqrt(static_cast<double>(n)));
    if (side < 1) return b.take();
    const std::int64_t w = std::max<std::int64_t>(1, side + rng.between(-side / 2, side / 2));
    const std::int64_t h = std::max<std::int64_t>(1, static_cast<std::int64_t>(n) / w);
    const std::int64_t s = rng.between(1, 2);
    auto id = [&](std::int64_t i, std::int64_t j) { return VertexId(static_cast<Index>(i * h + j)); };
    for (std::int64_t i = 0; i < w; ++i) {
        for (std::int64_t j = 0; j < h; ++j) (void)b.add_point(at(i * s, j * s));
    }
    // Islands: the edges that leave a few random rectangles are cut, so each
    // rectangle's inside becomes a component sitting in a hole.
    struct Rect {
        std::int64_t i0, i1, j0, j1;
        [[nodiscard]] bool inside(std::int64_t i, std::int64_t j) const { return i0 <= i && i <= i1 && j0 <= j && j <= j1; }
    };
    std::vector<Rect> islands;
    for (std::int64_t k = rng.between(0, 3); k > 0 && w > 2 && h > 2; --k) {
        const std::int64_t i0 = rng.between(1, w - 2), j0 = rng.between(1, h - 2);
        islands.push_back({i0, rng.between(i0, w - 2), j0, rng.between(j0, h - 2)});
    }
    auto cut = [&](std::int64_t i, std::int64_t j, std::int64_t k, std::int64_t l) {
        return std::any_of(islands.begin(), islands.end(), [&](const Rect& r) { return r.inside(i, j) != r.inside(k, l); });
    };
    const std::uint64_t keep = rng.between(5, 8);  // each grid edge survives with probability keep/8
    for (std::int64_t i = 0; i < w; ++i) {
        for (std::int64_t j = 0; j < h; ++j) {
            if (i + 1 < w && !cut(i, j, i + 1, j) && rng.chance(keep, 8)) (void)b.add_edge(id(i, j), id(i + 1, j));
            if (j + 1 < h && !cut(i, j, i, j + 1) && rng.chance(keep, 8)) (void)b.add_edge(id(i, j), id(i, j + 1));
            // At most one diagonal per cell, so diagonals never cross.
            if (i + 1 < w && j + 1 < h && rng.chance(1, 6)) {
                if (rng.chance(1, 2)) (void)b.add_edge(id(i, j), id(i + 1, j + 1));
                else (void)b.add_edge(id(i + 1, j), id(i, j + 1));
            }
        }
    }
    return b.take();
}

namespace {

// A polygon around (cx, cy) whose vertices lie in the 8 (or 4 axis)
// directions at L-infinity radius in [r/2, r]. It contains the square of
// half-side r/4 - 1 strictly (each edge from radius a to radius b, a, b >= r/2,
// passes outside it), which is where the children go.
// Recursive on purpose: the depth is at most log4 of the radius.
// NOLINTNEXTLINE(misc-no-recursion)
void nest(GraphBuilder& b, Rng& rng, std::int64_t cx, std::int64_t cy, std::int64_t r, std::size_t n) {
    static const Step kEight[] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
    static const Step kFour[] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    const bool eight = rng.chance(2, 3);
    const std::size_t k = eight ? 8 : 4;
    if (b.num_vertices() + k > n || r < 16) {
        if (b.num_vertices() < n) (void)b.add_point(at(cx, cy));  // a leaf: an isolated vertex
        return;
    }
    std::vector<Point> ring;
    for (std::size_t i = 0; i < k; ++i) {
        const Step d = eight ? kEight[i] : kFour[i];
        const std::int64_t rho = rng.between(r / 2, r);
        ring.push_back(at(cx + rho * d.dx, cy + rho * d.dy));
    }
    for (std::size_t i = 0; i < k; ++i) (void)b.add_segment(ring[i], ring[(i + 1) % k]);
    const std::int64_t q = r / 4 - 1;
    switch (rng.below(5)) {
        case 0: break;  // an empty face
        case 1: (void)b.add_point(at(cx, cy)); break;
        case 2: nest(b, rng, cx, cy, q - 1, n); break;
        case 3:
            nest(b, rng, cx - q / 2, cy, q / 2 - 1, n);
            nest(b, rng, cx + q / 2, cy, q / 2 - 1, n);
            if (rng.chance(1, 2)) (void)b.add_point(at(cx, cy));  // between the two children
            break;
        default:
            for (const std::int64_t sx : {-1, 1}) {
                for (const std::int64_t sy : {-1, 1}) nest(b, rng, cx + sx * q / 2, cy + sy * q / 2, q / 2 - 1, n);
            }
            break;
    }
}

}  // namespace

PlanarGraph nested_polygons(Rng& rng, std::size_t n) {
    GraphBuilder b;
    const std::int64_t r = std::int64_t{1} << rng.between(12, 24);
    const std::int64_t groups = rng.between(1, 3);
    for (std::int64_t i = 0; i < groups; ++i) nest(b, rng, i * 3 * r, rng.between(-r, r), r, n);
    return b.take();
}

PlanarGraph components(Rng& rng, std::size_t n) {
    // One small shape per cell of a coarse grid; shapes stay inside their
    // cells, so they are separate components (the builder checks anyway).
    GraphBuilder b;
    const std::int64_t cell = 8;
    const auto across = static_cast<std::int64_t>(std::sqrt(static_cast<double>(n))) + 1;
    auto inner = [&](std::int64_t o) { return o + rng.between(1, cell - 1); };
    for (std::int64_t c = 0; b.num_vertices() < n && c < across * across * 2; ++c) {
        const std::int64_t ox = (c % across) * cell;
        const std::int64_t oy = (c / across) * cell;
        switch (rng.below(6)) {
            case 0: (void)b.add_point(at(inner(ox), inner(oy))); break;
            case 1: (void)b.add_segment(at(inner(ox), inner(oy)), at(inner(ox), inner(oy))); break;
            case 2: {
                const Point p = at(inner(ox), inner(oy)), q = at(inner(ox), inner(oy)), s = at(inner(ox), inner(oy));
                if (orient2d(p, q, s) == Sign::Zero) break;
                (void)b.add_segment(p, q);
                (void)b.add_segment(q, s);
                (void)b.add_segment(s, p);
                break;
            }
            case 3: {
                const std::int64_t x0 = ox + 1, y0 = oy + 1, x1 = ox + cell - 1, y1 = oy + cell - 1;
                (void)b.add_segment(at(x0, y0), at(x1, y0));
                (void)b.add_segment(at(x1, y0), at(x1, y1));
                (void)b.add_segment(at(x1, y1), at(x0, y1));
                (void)b.add_segment(at(x0, y1), at(x0, y0));
                (void)b.add_point(at(rng.between(x0 + 1, x1 - 1), rng.between(y0 + 1, y1 - 1)));  // strictly inside
                break;
            }
            case 4: {
                Point from = at(inner(ox), inner(oy));
                for (int k = 0; k < 3; ++k) {
                    const Point to = at(inner(ox), inner(oy));
                    (void)b.add_segment(from, to);
                    from = to;
                }
                break;
            }
            default: break;  // an empty cell
        }
    }
    return b.take();
}

}  // namespace dcel::gen::detail
