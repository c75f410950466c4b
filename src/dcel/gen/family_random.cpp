// Families built from random integer points: random non-crossing segments
// (or one big simple polygon through all the points), subsets of a
// triangulation, and random trees.
#include <algorithm>

#include "dcel/core/union_find.hpp"
#include "dcel/gen/families.hpp"
#include "dcel/gen/graph_builder.hpp"

namespace dcel::gen::detail {
namespace {

PlanarGraph with_edges(std::vector<Point> points, std::vector<GraphEdge> edges) {
    return {std::move(points), std::move(edges)};
}

// Points in [0, side)^2 sorted by square cell (row by row), so that each
// cell's points are one run of ids: a random near neighbour is O(1), and
// near pairs have near ids (the builder's arrays stay in cache).
class NearPoints {
public:
    NearPoints(std::vector<Point>& p, std::int64_t side, std::int64_t cell)
        : cell_(cell), across_(side / cell + 1), start_(static_cast<std::size_t>(across_ * across_) + 1, 0), points_(&p) {
        std::vector<Point> sorted(p.size());
        for (const Point& q : p) ++start_[index(q) + 1];
        std::partial_sum(start_.begin(), start_.end(), start_.begin());
        std::vector<Index> next(start_.begin(), start_.end() - 1);
        for (const Point& q : p) sorted[next[index(q)]++] = q;
        p = std::move(sorted);
    }
    // A random point in the cell of point i or one of its eight neighbours,
    // or i itself when that cell is empty or off the grid.
    Index near(Index i, Rng& rng) const {
        const Point q = (*points_)[i];
        const std::int64_t cx = static_cast<std::int64_t>(q.x) / cell_ + rng.between(-1, 1);
        const std::int64_t cy = static_cast<std::int64_t>(q.y) / cell_ + rng.between(-1, 1);
        if (cx < 0 || cy < 0 || cx >= across_ || cy >= across_) return i;
        const auto c = static_cast<std::size_t>(cy * across_ + cx);
        const Index count = start_[c + 1] - start_[c];
        return count == 0 ? i : start_[c] + static_cast<Index>(rng.below(count));
    }

private:
    [[nodiscard]] std::size_t index(Point q) const {
        return static_cast<std::size_t>(static_cast<std::int64_t>(q.y) / cell_ * across_ +
                                        static_cast<std::int64_t>(q.x) / cell_);
    }
    std::int64_t cell_, across_;
    std::vector<Index> start_;
    const std::vector<Point>* points_;
};

std::int64_t squared_length(const std::vector<Point>& p, const GraphEdge& e) {
    const auto dx = static_cast<std::int64_t>(p[e.u.index()].x - p[e.v.index()].x);
    const auto dy = static_cast<std::int64_t>(p[e.u.index()].y - p[e.v.index()].y);
    return dx * dx + dy * dy;
}

}  // namespace

// One time in four, a simple polygon through all n points (valid by design,
// see monotone_polygon). Otherwise the points joined by random segments that
// GraphBuilder accepts: about sqrt(n) attempts between random pairs (long
// segments, O(sqrt n) grid cells each), then 3n between near pairs (O(1)
// cells each). O(n log n) either way.
PlanarGraph random_segments(Rng& rng, std::size_t n) {
    const std::int64_t side = point_square(rng, n);
    std::vector<Point> points = distinct_points(rng, n, side);
    if (n >= 3 && rng.chance(1, 4)) {
        std::vector<GraphEdge> ring = monotone_polygon(points);
        return with_edges(std::move(points), std::move(ring));
    }
    // Cells about two point spacings wide hold a few points each.
    const std::int64_t cell = std::max<std::int64_t>(1, 2 * side / (isqrt(n) + 1));
    const NearPoints near(points, side, cell);
    GraphBuilder b(cell);
    for (const Point& p : points) (void)b.add_point(p);  // distinct, and no edge yet
    if (n < 2) return b.take();
    const auto v = static_cast<Index>(n);
    for (std::int64_t tries = isqrt(n) + 2; tries > 0; --tries) {
        const auto w = static_cast<Index>(rng.below(v));  // one draw per statement (rng.hpp)
        const auto u = static_cast<Index>(rng.below(v));
        (void)b.add_edge(VertexId(u), VertexId(w));
    }
    for (std::size_t tries = 0; tries < 3 * n; ++tries) {
        const auto u = static_cast<Index>(rng.below(v));
        (void)b.add_edge(VertexId(u), VertexId(near.near(u, rng)));
    }
    return b.take();
}

// The sweep triangulation of n random points (valid by design, see
// sweep_triangulation), then each edge kept with probability 1/4, 2/4, 3/4
// or 1 (dropping edges keeps a graph valid). O(n log n).
PlanarGraph triangulation(Rng& rng, std::size_t n) {
    std::vector<Point> points = distinct_points(rng, n, point_square(rng, n));
    std::vector<GraphEdge> all = sweep_triangulation(points);
    const std::uint64_t keep = 1 + rng.below(4);
    std::vector<GraphEdge> kept;
    for (const GraphEdge& e : all) {
        if (keep == 4 || rng.chance(keep, 4)) kept.push_back(e);
    }
    return with_edges(std::move(points), std::move(kept));
}

// A random spanning tree of the sweep triangulation of n random points
// (Kruskal over its edges in random order, or shortest first): a subgraph of
// a valid graph, so valid. One time in three a forest: a few tree edges
// dropped, leaving components and isolated vertices. O(n log n).
PlanarGraph tree(Rng& rng, std::size_t n) {
    std::vector<Point> points = distinct_points(rng, n, point_square(rng, n) * 2);
    std::vector<GraphEdge> candidates = sweep_triangulation(points);
    rng.shuffle(candidates);
    if (rng.chance(1, 2)) {
        std::stable_sort(candidates.begin(), candidates.end(), [&](const GraphEdge& a, const GraphEdge& c) {
            return squared_length(points, a) < squared_length(points, c);
        });
    }
    const bool forest = rng.chance(1, 3);
    dcel::detail::UnionFind sets(static_cast<Index>(n));  // Kruskal: an edge joining two trees is taken
    std::vector<GraphEdge> edges;
    for (const GraphEdge& e : candidates) {
        if (!sets.unite(e.u.index(), e.v.index())) continue;
        if (!forest || !rng.chance(1, 16)) edges.push_back(e);
    }
    return with_edges(std::move(points), std::move(edges));
}

}  // namespace dcel::gen::detail
