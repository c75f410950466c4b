// Families made of straight runs: combs, stars of high degree, and collinear
// chains with branches.
#include <algorithm>
#include <array>
#include <iterator>
#include <numeric>
#include <optional>

#include "dcel/gen/brute_force.hpp"
#include "dcel/gen/families.hpp"
#include "dcel/gen/graph_builder.hpp"
#include "dcel/geometry/predicates.hpp"

namespace dcel::gen::detail {

Step random_direction(Rng& rng) {
    static const Step kSteps[] = {{1, 0},  {0, 1},  {1, 1}, {1, -1}, {2, 1},  {1, 2},
                                  {2, -1}, {1, -3}, {3, 1}, {3, -2}, {-1, 4}, {5, 3}};
    const Step s = kSteps[rng.below(std::size(kSteps))];
    return rng.chance(1, 2) ? s : Step{-s.dx, -s.dy};
}

// Valid by design: spine points s_i = i * gap * d on one line, joined in
// order; teeth run along perp(d) from s_i, so every tooth lies on the line
// through s_i perpendicular to the spine. Those lines are parallel and
// distinct, so teeth of different spine points never meet; the two teeth of
// one spine point point opposite ways; and a tooth meets the spine line only
// at its own s_i. No vertex lies inside a spine edge (teeth vertices are off
// the spine line) or inside a tooth edge (consecutive tooth vertices). A
// tree, so one boundary cycle of 2(n - 1) half-edges. O(n).
PlanarGraph comb(Rng& rng, std::size_t n) {
    PlanarGraph g;
    const Step d = random_direction(rng);
    const Step perp{-d.dy, d.dx};
    const std::int64_t gap = rng.between(1, 3);
    std::optional<VertexId> previous;
    for (std::int64_t i = 0; g.vertices.size() < n; ++i) {
        const VertexId s = add_vertex(g, at(i * gap * d.dx, i * gap * d.dy));
        if (previous) g.edges.push_back({*previous, s});
        previous = s;
        for (const std::int64_t side : {1, -1}) {
            if (!rng.chance(2, 3)) continue;
            const std::int64_t teeth = rng.between(1, 4);
            const std::int64_t step = rng.between(1, 2);
            VertexId from = s;
            for (std::int64_t k = 1; k <= teeth && g.vertices.size() < n; ++k) {
                const VertexId to = add_vertex(
                    g, at(i * gap * d.dx + side * k * step * perp.dx, i * gap * d.dy + side * k * step * perp.dy));
                g.edges.push_back({from, to});
                from = to;
            }
        }
    }
    return g;
}

// Valid by design: the centre joins n - 1 tips m (a, c) with distinct
// primitive directions (a, c), so two rays meet only at the centre and no tip
// lies on another ray. The rim joins angularly consecutive tips a, b only
// when they turn strictly counterclockwise (a wedge under 180 degrees): the
// rim edge then stays inside that wedge, which no other ray or rim edge
// enters. A vertex of degree n - 1. O(n log n).
PlanarGraph star(Rng& rng, std::size_t n) {
    PlanarGraph g;
    if (n == 0) return g;
    const VertexId centre = add_vertex(g, at(0, 0));
    // About 0.6 (2L + 1)^2 primitive vectors lie in [-L, L]^2: more than n.
    std::vector<Step> directions;
    for (std::int64_t limit = isqrt(n) + 2; directions.size() + 1 < n; limit *= 2) {
        directions.clear();
        for (std::int64_t a = -limit; a <= limit; ++a) {
            for (std::int64_t c = -limit; c <= limit; ++c) {
                if (std::gcd(a, c) == 1) directions.push_back({a, c});
            }
        }
    }
    for (std::size_t i = 0; i + 1 < n; ++i) std::swap(directions[i], directions[i + rng.below(directions.size() - i)]);
    std::vector<VertexId> tips;
    for (std::size_t i = 0; i + 1 < n; ++i) {
        const std::int64_t m = rng.between(1, 3);
        tips.push_back(add_vertex(g, at(m * directions[i].dx, m * directions[i].dy)));
        g.edges.push_back({centre, tips.back()});
    }
    if (rng.chance(1, 2) && tips.size() > 2) {
        const Point o = g.vertices[centre.index()];
        auto upper = [&](Point p) { return p.y > o.y || (p.y == o.y && p.x > o.x); };
        std::sort(tips.begin(), tips.end(), [&](VertexId p, VertexId q) {
            const Point a = g.vertices[p.index()];
            const Point c = g.vertices[q.index()];
            if (upper(a) != upper(c)) return upper(a);
            return orient2d(o, a, c) == Sign::Positive;
        });
        for (std::size_t i = 0; i < tips.size(); ++i) {
            const VertexId a = tips[i], c = tips[(i + 1) % tips.size()];
            if (orient2d(o, g.vertices[a.index()], g.vertices[c.index()]) == Sign::Positive && rng.chance(3, 4)) {
                g.edges.push_back({a, c});
            }
        }
    }
    return g;
}

// Two thirds of the vertices on one line, joined in order except at a few
// gaps (none at all one time in three: then the line and its branches are
// one component with one long boundary cycle); then short branches leaving
// the line in other directions, each edge checked by GraphBuilder (O(1)
// cells: the edges are a few units long). Isolated vertices make up what the
// branches could not place. O(n) expected.
PlanarGraph collinear_chain(Rng& rng, std::size_t n) {
    GraphBuilder b(8);
    if (n == 0) return b.take();
    const Step d = random_direction(rng);
    const std::uint64_t gap_odds = std::array<std::uint64_t, 3>{0, 8, 64}[rng.below(3)];  // a gap one time in this
    std::int64_t t = 0;
    std::optional<VertexId> previous;
    std::vector<std::int64_t> positions;
    const std::size_t on_line = std::max<std::size_t>(1, n * 2 / 3);
    for (std::size_t i = 0; i < on_line; ++i) {
        const std::optional<VertexId> v = b.add_point(at(t * d.dx, t * d.dy));
        if (v && previous && (gap_odds == 0 || !rng.chance(1, gap_odds))) (void)b.add_edge(*previous, *v);
        previous = v;
        positions.push_back(t);
        t += rng.between(1, 3);
    }
    for (std::size_t tries = 0; b.num_vertices() < n && tries < 4 * n; ++tries) {
        const std::int64_t p = rng.pick(positions);
        const Step e = random_direction(rng);
        const std::int64_t length = rng.between(1, 3);
        Point from = at(p * d.dx, p * d.dy);
        for (std::int64_t k = 1; k <= length && b.num_vertices() < n; ++k) {
            const Point to = at(p * d.dx + k * e.dx, p * d.dy + k * e.dy);
            if (!b.add_segment(from, to)) break;
            from = to;
        }
    }
    fill_with_isolated(b, rng, n);
    return b.take();
}

}  // namespace dcel::gen::detail
