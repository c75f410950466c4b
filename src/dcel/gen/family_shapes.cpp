// Families with faces inside faces: grids with holes and islands, nested
// polygons, and many small components mixed with isolated vertices.
#include <algorithm>
#include <array>
#include <optional>
#include <tuple>
#include <unordered_set>
#include <utility>

#include "dcel/gen/brute_force.hpp"
#include "dcel/gen/families.hpp"
#include "dcel/gen/graph_builder.hpp"
#include "dcel/geometry/predicates.hpp"

namespace dcel::gen::detail {

// Valid by design: an h-row grid of n / h full columns and one partial
// column of n % h points (exactly n), spaced s apart. Edges are sides of the
// grid's cells and at most one diagonal per cell, so two edges meet only at
// a shared grid point, and no grid point lies inside an edge. Removing edges
// keeps that: random ones leave holes, and cutting every edge that leaves a
// few rectangles turns each rectangle into an island inside a hole. O(n).
PlanarGraph grid_with_holes(Rng& rng, std::size_t n) {
    PlanarGraph g;
    if (n == 0) return g;
    const std::int64_t side = isqrt(n);
    const std::int64_t h = std::max<std::int64_t>(1, side + rng.between(-side / 2, side / 2));
    const std::int64_t w = static_cast<std::int64_t>(n) / h;
    const std::int64_t rest = static_cast<std::int64_t>(n) % h;
    const std::int64_t s = rng.between(1, 2);
    auto exists = [&](std::int64_t i, std::int64_t j) { return j < h && (i < w || (i == w && j < rest)); };
    auto id = [&](std::int64_t i, std::int64_t j) { return VertexId(static_cast<Index>(i * h + j)); };
    for (std::int64_t i = 0; i <= w; ++i) {
        for (std::int64_t j = 0; exists(i, j); ++j) (void)add_vertex(g, at(i * s, j * s));
    }
    struct Rect {
        std::int64_t i0, i1, j0, j1;
        [[nodiscard]] bool inside(std::int64_t i, std::int64_t j) const { return i0 <= i && i <= i1 && j0 <= j && j <= j1; }
    };
    std::vector<Rect> islands;
    for (std::int64_t k = rng.between(0, 3); k > 0 && w > 2 && h > 2; --k) {
        const std::int64_t i0 = rng.between(1, w - 2), j0 = rng.between(1, h - 2);
        islands.push_back({i0, rng.between(i0, w - 2), j0, rng.between(j0, h - 2)});
    }
    auto join = [&](std::int64_t i, std::int64_t j, std::int64_t k, std::int64_t l) {
        if (!exists(k, l)) return;
        const bool cut = std::any_of(islands.begin(), islands.end(),
                                     [&](const Rect& r) { return r.inside(i, j) != r.inside(k, l); });
        if (!cut) g.edges.push_back({id(i, j), id(k, l)});
    };
    const std::uint64_t keep = rng.between(5, 8);  // each grid edge survives with probability keep/8
    for (std::int64_t i = 0; i <= w; ++i) {
        for (std::int64_t j = 0; exists(i, j); ++j) {
            if (rng.chance(keep, 8)) join(i, j, i + 1, j);
            if (rng.chance(keep, 8)) join(i, j, i, j + 1);
            if (rng.chance(1, 6)) {  // one diagonal of the cell above and to the right
                if (rng.chance(1, 2)) join(i, j, i + 1, j + 1);
                else if (exists(i + 1, j)) join(i + 1, j, i, j + 1);
            }
        }
    }
    return g;
}

namespace {

// Nested polygons, each vertex budget spent exactly. A polygon around centre
// c with "radius" r (r >= 8, a = floor(3r/4)) has one vertex on each
// diagonal ray from c at L-infinity distance in [a, r], and its other
// vertices on the four sides: a right-side vertex is c + (x, y) with x in
// [a, r] and |y| <= a - 1, so strictly inside the cone |y| <= x; the sides'
// offsets y are distinct and visited in increasing order (counterclockwise).
// Valid by design: each side's chain, from one diagonal vertex to the next,
// is strictly monotone in its offset, so simple; it stays in its closed
// cone, which meets the neighbouring cones only on the diagonal rays, where
// the chain has only its end vertices; and every point of it has |x| >= a
// (or |y| >= a), so the open square of half-side a around c is inside the
// polygon and untouched. Children (polygons or leaves) get disjoint squares
// inside the square of half-side a - 1, so nothing they hold meets this
// polygon or each other.
//
// Budgets: a square of radius r is given at most r / 2 vertices, so a
// polygon always fits (a side holds up to 2a - 1 vertices) and the children
// of every shape can take what the polygon leaves (the polygon takes at
// least budget - what the children can hold).
class Nest {
public:
    Nest(PlanarGraph& g, Rng& rng) : g_(g), rng_(rng) {}

    static std::size_t capacity(std::int64_t r) { return r < 0 ? 0 : static_cast<std::size_t>(r / 2); }

    // Spends exactly `budget` (at most capacity(r)) vertices in the square
    // of radius r around c; the polygon takes at least half when `big`.
    // Recursive on purpose: the depth is at most log_{4/3} of the radius.
    // NOLINTNEXTLINE(misc-no-recursion)
    void shape(std::int64_t cx, std::int64_t cy, std::int64_t r, std::size_t budget, bool big = false) {
        if (budget == 0) return;
        if (budget < 4 || r < 8) return leaf(cx, cy, budget);
        const std::int64_t a = 3 * r / 4;
        const std::int64_t half = a / 2;  // children's centres, for two or four children
        const std::size_t children = std::array<std::size_t, 3>{1, 2, 4}[rng_.below(3)];
        const std::int64_t child_r = children == 1 ? a - 1 : half - 1;
        const std::size_t centre = children > 1 && budget >= 5 && rng_.chance(1, 2) ? 1 : 0;
        const std::size_t room = children * capacity(child_r);
        // One time in four a single big polygon; otherwise a small one with
        // the rest nested inside it.
        const std::size_t upper = budget - centre;
        const std::size_t least_for_children = upper > room ? upper - room : 0;
        const std::size_t lower = std::max({std::size_t{4}, least_for_children, big ? (upper + 1) / 2 : 0});
        const std::size_t k = rng_.chance(1, 4) ? upper : lower + rng_.below((upper - lower) / 3 + 1);
        polygon(cx, cy, r, a, k);
        if (centre != 0) (void)add_vertex(g_, at(cx, cy));
        std::size_t rest = budget - centre - k;
        for (std::size_t i = 0; i < children; ++i) {
            // As much as the later children cannot hold, at least.
            const std::size_t later = (children - 1 - i) * capacity(child_r);
            const std::size_t least = rest > later ? rest - later : 0;
            const std::size_t most = std::min(rest, capacity(child_r));
            const std::size_t share = least + rng_.below(most - least + 1);
            rest -= share;
            if (children == 1) {
                shape(cx, cy, child_r, share);
            } else {
                const std::int64_t dx = (i & 1U) != 0 ? half : -half;
                const std::int64_t dy = children == 2 ? 0 : ((i & 2U) != 0 ? half : -half);
                shape(cx + dx, cy + dy, child_r, share);
            }
        }
    }

private:
    // budget <= r / 2 points on a row through the centre, some of them
    // joined: a piece of a collinear path, or isolated vertices.
    void leaf(std::int64_t cx, std::int64_t cy, std::size_t budget) {
        const auto from = cx - static_cast<std::int64_t>(budget / 2);
        std::optional<VertexId> previous;
        for (std::size_t j = 0; j < budget; ++j) {
            const VertexId v = add_vertex(g_, at(from + static_cast<std::int64_t>(j), cy));
            if (previous && rng_.chance(1, 2)) g_.edges.push_back({*previous, v});
            previous = v;
        }
    }

    // m distinct offsets in [-(a - 1), a - 1], increasing (Floyd's sampling).
    std::vector<std::int64_t> offsets(std::int64_t a, std::size_t m) {
        const auto range = static_cast<std::uint64_t>(2 * a - 1);
        std::unordered_set<std::uint64_t> chosen;
        for (std::uint64_t j = range - m; j < range; ++j) {
            const std::uint64_t t = rng_.below(j + 1);
            chosen.insert(chosen.contains(t) ? j : t);
        }
        std::vector<std::int64_t> out;
        out.reserve(m);
        for (const std::uint64_t c : chosen) out.push_back(static_cast<std::int64_t>(c) - (a - 1));
        std::sort(out.begin(), out.end());
        return out;
    }

    void polygon(std::int64_t cx, std::int64_t cy, std::int64_t r, std::int64_t a, std::size_t k) {
        std::array<std::size_t, 4> per_side{};
        for (std::size_t i = 4; i < k; ++i) ++per_side[rng_.below(4)];
        // Side q runs counterclockwise from diagonal vertex q to diagonal
        // vertex q + 1: in local coordinates (depth, offset) rotated by q
        // quarter turns, starting with the right side (x = depth, y = offset).
        const VertexId first(static_cast<Index>(g_.vertices.size()));
        std::optional<VertexId> previous;
        auto place = [&](std::int64_t u, std::int64_t w, unsigned quarter) {
            std::int64_t x = u, y = w;
            for (unsigned t = 0; t < quarter; ++t) std::tie(x, y) = std::pair{-y, x};
            const VertexId v = add_vertex(g_, at(cx + x, cy + y));
            if (previous) g_.edges.push_back({*previous, v});
            previous = v;
        };
        for (unsigned q = 0; q < 4; ++q) {
            const std::int64_t rho = rng_.between(a, r);
            place(rho, -rho, q);  // the diagonal vertex that starts side q
            for (const std::int64_t y : offsets(a, per_side[q])) place(rng_.between(a, r), y, q);
        }
        g_.edges.push_back({*previous, first});
    }

    PlanarGraph& g_;
    Rng& rng_;
};

}  // namespace

// Nested polygons (see Nest) in one to three groups side by side, exactly n
// vertices: polygons inside polygons to any depth, with isolated vertices and
// collinear pieces as leaves. One time in three a single group whose outer
// polygon has at least half the vertices (a boundary cycle of n/2 to n
// half-edges). The radius is at least 2n, so every group's budget fits.
// O(n log n).
PlanarGraph nested_polygons(Rng& rng, std::size_t n) {
    PlanarGraph g;
    Nest nest(g, rng);
    std::int64_t r = std::int64_t{1} << rng.between(12, 24);
    while (Nest::capacity(r) < n) r *= 2;
    const bool big = rng.chance(1, 3);
    const auto groups = big ? 1 : static_cast<std::size_t>(rng.between(1, 3));
    std::size_t rest = n;
    for (std::size_t i = 0; i < groups; ++i) {
        const std::size_t share = i + 1 == groups ? rest : rng.below(rest + 1);
        rest -= share;
        nest.shape(static_cast<std::int64_t>(i) * 3 * r, rng.between(-r, r), r, share, big);
    }
    return g;
}

namespace {

constexpr std::int64_t kCell = 8;  // the side of a cell of components()

// A point strictly inside a cell, y drawn first. One draw per statement
// (rng.hpp): at(draw(), draw()) would draw in the compiler's order.
Point inner_point(Rng& rng) {
    const std::int64_t y = rng.between(1, kCell - 1);
    const std::int64_t x = rng.between(1, kCell - 1);
    return at(x, y);
}

// The shape of the next cell: 0 a point, 1 a segment, 2 a triangle, 3 a
// square with a point inside, 4 a path of three segments, 5 nothing; a
// shape with more vertices than there is room for becomes a point.
std::uint64_t cell_kind(Rng& rng, std::size_t room) {
    const std::uint64_t kind = rng.below(6);
    if ((kind == 2 && room < 3) || (kind == 3 && room < 5) || (kind == 4 && room < 4) || (kind == 1 && room < 2)) return 0;
    return kind;
}

// Draws a shape of the given kind in b's cell. (A triangle whose corners
// fall on one line is left out.)
void draw_shape(GraphBuilder& b, Rng& rng, std::uint64_t kind) {
    switch (kind) {
        case 0: (void)b.add_point(inner_point(rng)); break;
        case 1: {
            const Point q = inner_point(rng);  // q first: the order gen.digests records
            const Point p = inner_point(rng);
            (void)b.add_segment(p, q);
            break;
        }
        case 2: {
            const Point p = inner_point(rng), q = inner_point(rng), s = inner_point(rng);
            if (orient2d(p, q, s) == Sign::Zero) break;
            (void)b.add_segment(p, q);
            (void)b.add_segment(q, s);
            (void)b.add_segment(s, p);
            break;
        }
        case 3: {
            const std::int64_t lo = 1, hi = kCell - 1;
            (void)b.add_segment(at(lo, lo), at(hi, lo));
            (void)b.add_segment(at(hi, lo), at(hi, hi));
            (void)b.add_segment(at(hi, hi), at(lo, hi));
            (void)b.add_segment(at(lo, hi), at(lo, lo));
            // Strictly inside; one draw per statement (rng.hpp).
            const std::int64_t y = rng.between(lo + 1, hi - 1);
            const std::int64_t x = rng.between(lo + 1, hi - 1);
            (void)b.add_point(at(x, y));
            break;
        }
        case 4: {
            Point from = inner_point(rng);
            for (int k = 0; k < 3; ++k) {
                const Point to = inner_point(rng);
                (void)b.add_segment(from, to);
                from = to;
            }
            break;
        }
        default: break;  // an empty cell
    }
}

// Appends the graph `part` to g, moved by (dx, dy).
void append_moved(PlanarGraph& g, const PlanarGraph& part, std::int64_t dx, std::int64_t dy) {
    const auto base = static_cast<Index>(g.vertices.size());
    for (const Point& p : part.vertices)
        g.vertices.push_back({p.x + static_cast<double>(dx), p.y + static_cast<double>(dy)});
    for (const GraphEdge& e : part.edges) g.edges.push_back({VertexId(base + e.u.index()), VertexId(base + e.v.index())});
}

}  // namespace

// One small shape per cell of a coarse grid, each drawn through its own
// GraphBuilder in the cell's open interior, so shapes of different cells
// never meet and each check is O(1): many components, isolated vertices,
// and isolated vertices in bounded faces. Exactly n vertices: a shape that
// would overshoot becomes an isolated vertex. O(n).
PlanarGraph components(Rng& rng, std::size_t n) {
    PlanarGraph g;
    const std::int64_t across = isqrt(n) + 1;
    for (std::int64_t c = 0; g.vertices.size() < n; ++c) {
        GraphBuilder b(kCell);
        draw_shape(b, rng, cell_kind(rng, n - g.vertices.size()));
        append_moved(g, b.graph(), (c % across) * kCell, (c / across) * kCell);
    }
    return g;
}

}  // namespace dcel::gen::detail
