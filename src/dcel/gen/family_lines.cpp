// Families made of straight runs: combs, stars of high degree, and collinear
// chains with branches.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <numeric>
#include <set>

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

PlanarGraph comb(Rng& rng, std::size_t n) {
    // Spine points s_i = i * gap * d; teeth run along n = perp(d). Teeth lie
    // on parallel lines through distinct spine points, so they never meet.
    GraphBuilder b;
    const Step d = random_direction(rng);
    const Step perp{-d.dy, d.dx};
    const std::int64_t gap = rng.between(1, 3);
    const std::int64_t spine = std::max<std::int64_t>(1, static_cast<std::int64_t>(n) / 4);
    for (std::int64_t i = 0; i < spine && b.num_vertices() < n; ++i) {
        const Point s = at(i * gap * d.dx, i * gap * d.dy);
        if (i > 0) (void)b.add_segment(at((i - 1) * gap * d.dx, (i - 1) * gap * d.dy), s);
        else (void)b.point(s);
        for (const int side : {1, -1}) {
            if (!rng.chance(2, 3)) continue;
            const std::int64_t teeth = rng.between(1, 4);
            const std::int64_t step = rng.between(1, 2);
            Point from = s;
            for (std::int64_t k = 1; k <= teeth && b.num_vertices() < n; ++k) {
                const Point to = at(i * gap * d.dx + side * k * step * perp.dx, i * gap * d.dy + side * k * step * perp.dy);
                (void)b.add_segment(from, to);
                from = to;
            }
        }
    }
    return b.take();
}

PlanarGraph star(Rng& rng, std::size_t n) {
    GraphBuilder b;
    if (n == 0) return b.take();
    const VertexId centre = *b.add_point(at(0, 0));
    // Distinct primitive directions: rays from one point never meet elsewhere.
    const auto limit = static_cast<std::int64_t>(std::sqrt(static_cast<double>(n))) + 2;
    std::set<std::pair<std::int64_t, std::int64_t>> used;
    std::vector<VertexId> tips;
    for (std::size_t tries = 0; b.num_vertices() < n && tries < 8 * n; ++tries) {
        const std::int64_t a = rng.between(-limit, limit);
        const std::int64_t c = rng.between(-limit, limit);
        if ((a == 0 && c == 0) || std::gcd(a, c) != 1 || !used.insert({a, c}).second) continue;
        const std::int64_t m = rng.between(1, 3);
        const std::optional<VertexId> tip = b.add_point(at(m * a, m * c));
        if (tip && b.add_edge(centre, *tip)) tips.push_back(*tip);
    }
    // A rim joining consecutive tips (where it meets nothing) makes a wheel.
    if (rng.chance(1, 2) && tips.size() > 2) {
        const PlanarGraph& g = b.graph();
        const Point o = g.vertices[centre.index()];
        auto upper = [&](Point p) { return p.y > o.y || (p.y == o.y && p.x > o.x); };
        std::sort(tips.begin(), tips.end(), [&](VertexId p, VertexId q) {
            const Point a = g.vertices[p.index()];
            const Point c = g.vertices[q.index()];
            if (upper(a) != upper(c)) return upper(a);
            return orient2d(o, a, c) == Sign::Positive;
        });
        for (std::size_t i = 0; i < tips.size(); ++i) {
            if (rng.chance(3, 4)) (void)b.add_edge(tips[i], tips[(i + 1) % tips.size()]);
        }
    }
    return b.take();
}

PlanarGraph collinear_chain(Rng& rng, std::size_t n) {
    GraphBuilder b;
    const Step d = random_direction(rng);
    std::int64_t t = 0;
    std::optional<VertexId> previous;
    std::vector<std::int64_t> positions;
    const std::size_t on_line = std::max<std::size_t>(1, n * 2 / 3);
    for (std::size_t i = 0; i < on_line; ++i) {
        const std::optional<VertexId> v = b.point(at(t * d.dx, t * d.dy));
        // A few gaps split the line into collinear pieces that share no point.
        if (v && previous && !rng.chance(1, 8)) (void)b.add_edge(*previous, *v);
        previous = v;
        positions.push_back(t);
        t += rng.between(1, 3);
    }
    // Branches: short chains leaving the line in other directions.
    for (std::size_t tries = 0; b.num_vertices() < n && tries < 4 * n; ++tries) {
        const std::int64_t p = rng.pick(positions);
        const Step e = random_direction(rng);
        const std::int64_t length = rng.between(1, 3);
        Point from = at(p * d.dx, p * d.dy);
        for (std::int64_t k = 1; k <= length; ++k) {
            const Point to = at(p * d.dx + k * e.dx, p * d.dy + k * e.dy);
            if (!b.add_segment(from, to)) break;
            from = to;
        }
    }
    return b.take();
}

}  // namespace dcel::gen::detail
