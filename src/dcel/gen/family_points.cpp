// Constructions on sets of random points that several families share:
// distinct random lattice points, a sweep triangulation, a monotone polygon,
// and filling up with isolated vertices.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_set>

#include "dcel/gen/brute_force.hpp"
#include "dcel/gen/families.hpp"
#include "dcel/geometry/predicates.hpp"

namespace dcel::gen::detail {
namespace {

std::vector<Index> lexicographic_order(const std::vector<Point>& p) {
    std::vector<Index> order(p.size());
    std::iota(order.begin(), order.end(), Index{0});
    std::sort(order.begin(), order.end(), [&](Index a, Index b) { return lex_less(p[a], p[b]); });
    return order;
}

}  // namespace

std::int64_t isqrt(std::size_t n) {
    auto r = static_cast<std::int64_t>(std::sqrt(static_cast<double>(n)));
    while (r > 0 && static_cast<std::size_t>(r * r) > n) --r;
    while (static_cast<std::size_t>((r + 1) * (r + 1)) <= n) ++r;
    return r;
}

std::int64_t point_square(Rng& rng, std::size_t n) {
    const std::int64_t root = isqrt(n) + 2;  // root^2 > n
    switch (rng.below(3)) {
        case 0: return root;
        case 1: return 3 * root;
        default: return 64 * root;
    }
}

std::vector<Point> distinct_points(Rng& rng, std::size_t n, std::int64_t side) {
    const auto cells = static_cast<std::uint64_t>(side) * static_cast<std::uint64_t>(side);
    std::vector<Point> out;
    out.reserve(n);
    if (2 * n >= cells) {
        // Dense: the first n of a random permutation of all lattice points.
        std::vector<std::uint64_t> all(cells);
        std::iota(all.begin(), all.end(), std::uint64_t{0});
        for (std::size_t i = 0; i < n; ++i) {
            std::swap(all[i], all[i + rng.below(cells - i)]);
            out.push_back(at(static_cast<std::int64_t>(all[i] % static_cast<std::uint64_t>(side)),
                             static_cast<std::int64_t>(all[i] / static_cast<std::uint64_t>(side))));
        }
        return out;
    }
    // Sparse: at least half the lattice points are free at every draw, so
    // rejection takes fewer than two draws per point on average.
    std::unordered_set<std::uint64_t> taken;
    while (out.size() < n) {
        const std::uint64_t c = rng.below(cells);
        if (!taken.insert(c).second) continue;
        out.push_back(at(static_cast<std::int64_t>(c % static_cast<std::uint64_t>(side)),
                         static_cast<std::int64_t>(c / static_cast<std::uint64_t>(side))));
    }
    return out;
}

std::vector<GraphEdge> sweep_triangulation(const std::vector<Point>& p) {
    // Points join in lexicographic order, so each new point q lies outside
    // the hull of the earlier ones (or on the line of a collinear hull
    // boundary). q joins the previous point, then walks back along the upper
    // and the lower hull chains: it joins every chain vertex it sees past a
    // strict turn (the triangle it closes holds no earlier point, since that
    // vertex was on the hull), and stops at a straight or convex turn. A
    // collinear turn stops it, so no new edge runs through a vertex. This is
    // Andrew's monotone-chain hull with the popped vertices kept as edges.
    std::vector<GraphEdge> edges;
    std::vector<Index> upper, lower;
    auto v = [](Index i) { return VertexId(i); };
    for (const Index q : lexicographic_order(p)) {
        if (!upper.empty()) edges.push_back({v(upper.back()), v(q)});  // the previous point ends both chains
        while (upper.size() >= 2 && orient2d(p[upper[upper.size() - 2]], p[upper.back()], p[q]) == Sign::Positive) {
            upper.pop_back();
            edges.push_back({v(upper.back()), v(q)});
        }
        while (lower.size() >= 2 && orient2d(p[lower[lower.size() - 2]], p[lower.back()], p[q]) == Sign::Negative) {
            lower.pop_back();
            edges.push_back({v(lower.back()), v(q)});
        }
        upper.push_back(q);
        lower.push_back(q);
    }
    return edges;
}

std::vector<GraphEdge> monotone_polygon(const std::vector<Point>& p) {
    // Every point of a segment lies lexicographically between its ends, so a
    // chain through points in lexicographic order is simple (non-adjacent
    // segments cover disjoint lexicographic ranges). With L the line from the
    // first point f to the last point l: the upper chain runs f, the points
    // strictly on one side of L, l, and touches L only at f and l; the lower
    // chain runs through all the others, on L or on the other side. So the
    // chains meet only at f and l, and together they bound a simple polygon.
    std::vector<GraphEdge> edges;
    const std::vector<Index> order = lexicographic_order(p);
    if (order.size() < 2) return edges;
    const Point f = p[order.front()], l = p[order.back()];
    Sign upper_side = Sign::Zero;
    for (const Index i : order) {
        const Sign s = orient2d(f, l, p[i]);
        if (s != Sign::Zero) upper_side = s;
    }
    auto chain = [&](bool upper) {
        Index previous = order.front();
        for (std::size_t k = 1; k < order.size(); ++k) {
            const Index i = order[k];
            const bool end = k + 1 == order.size();
            const bool in_upper = upper_side != Sign::Zero && orient2d(f, l, p[i]) == upper_side;
            if (!end && in_upper != upper) continue;
            edges.push_back({VertexId(previous), VertexId(i)});
            previous = i;
        }
    };
    chain(false);
    if (upper_side != Sign::Zero) chain(true);
    return edges;
}

void fill_with_isolated(GraphBuilder& b, Rng& rng, std::size_t n) {
    if (b.num_vertices() >= n) return;
    double x0 = 0, x1 = 0, y1 = 0, y0 = 0;
    for (std::size_t i = 0; i < b.num_vertices(); ++i) {
        const Point p = b.graph().vertices[i];
        if (i == 0 || p.x < x0) x0 = p.x;
        if (i == 0 || p.x > x1) x1 = p.x;
        if (i == 0 || p.y < y0) y0 = p.y;
        if (i == 0 || p.y > y1) y1 = p.y;
    }
    const auto lx = static_cast<std::int64_t>(x0), hx = static_cast<std::int64_t>(x1);
    const auto ly = static_cast<std::int64_t>(y0), hy = static_cast<std::int64_t>(y1);
    for (std::size_t tries = 4 * (n - b.num_vertices()) + 16; tries > 0 && b.num_vertices() < n; --tries) {
        const std::int64_t y = rng.between(ly - 2, hy + 2);  // one draw per statement (rng.hpp)
        const std::int64_t x = rng.between(lx - 2, hx + 2);
        (void)b.add_point(at(x, y));
    }
    // Above the bounding box no point can be taken or lie on an edge.
    for (std::int64_t k = 0; b.num_vertices() < n; ++k) (void)b.add_point(at(lx + k, hy + 3 + rng.between(0, 1)));
}

}  // namespace dcel::gen::detail
