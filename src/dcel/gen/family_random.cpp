// Families built from random integer points: random non-crossing segments,
// subsets of a triangulation, and random trees.
#include <algorithm>
#include <cmath>

#include "dcel/gen/families.hpp"
#include "dcel/gen/graph_builder.hpp"

namespace dcel::gen::detail {
namespace {

// The side of the square the points come from. A tight square (about as many
// lattice points as vertices) makes collinear triples, shared directions and
// touching candidates common; a loose one gives general position.
std::int64_t point_square(Rng& rng, std::size_t n) {
    const auto root = static_cast<std::int64_t>(std::sqrt(static_cast<double>(n))) + 2;
    switch (rng.below(3)) {
        case 0: return root;
        case 1: return 3 * root;
        default: return 64 * root;
    }
}

void add_random_points(GraphBuilder& b, Rng& rng, std::size_t n, std::int64_t side) {
    for (std::size_t tries = 0; b.num_vertices() < n && tries < 4 * n; ++tries) {
        (void)b.add_point(at(rng.between(0, side - 1), rng.between(0, side - 1)));
    }
}

}  // namespace

PlanarGraph random_segments(Rng& rng, std::size_t n) {
    GraphBuilder b;
    add_random_points(b, rng, n, point_square(rng, n));
    const std::size_t v = b.num_vertices();
    if (v < 2) return b.take();
    // Near pairs survive far more often than random ones; mix both.
    for (std::size_t tries = 0; tries < 4 * v; ++tries) {
        const auto u = static_cast<Index>(rng.below(v));
        const auto w = rng.chance(1, 2) ? static_cast<Index>(rng.below(v))
                                        : static_cast<Index>((u + 1 + rng.below(std::min<std::size_t>(v - 1, 6))) % v);
        (void)b.add_edge(VertexId(u), VertexId(w));
    }
    return b.take();
}

PlanarGraph triangulation(Rng& rng, std::size_t n) {
    GraphBuilder b;
    add_random_points(b, rng, std::min<std::size_t>(n, 160), point_square(rng, n));
    const auto v = static_cast<Index>(b.num_vertices());
    // Greedy: shortest pairs first, each kept when it meets nothing. The
    // result is maximal, so its bounded faces are triangles (a triangulation
    // of the points, collinear points included).
    struct Pair {
        std::int64_t length2;
        std::uint64_t tie;
        Index u, w;
    };
    std::vector<Pair> pairs;
    const PlanarGraph& g = b.graph();
    for (Index u = 0; u < v; ++u) {
        for (Index w = u + 1; w < v; ++w) {
            const auto dx = static_cast<std::int64_t>(g.vertices[u].x - g.vertices[w].x);
            const auto dy = static_cast<std::int64_t>(g.vertices[u].y - g.vertices[w].y);
            pairs.push_back({dx * dx + dy * dy, rng.next(), u, w});
        }
    }
    std::sort(pairs.begin(), pairs.end(),
              [](const Pair& a, const Pair& c) { return a.length2 != c.length2 ? a.length2 < c.length2 : a.tie < c.tie; });
    for (const Pair& p : pairs) (void)b.add_edge(VertexId(p.u), VertexId(p.w));
    // Keep a random subset: dropping edges never breaks validity.
    PlanarGraph t = b.take();
    const std::uint64_t keep = 1 + rng.below(4);  // keep each edge with probability keep/4
    std::vector<GraphEdge> kept;
    for (const GraphEdge& e : t.edges) {
        if (rng.chance(keep, 4)) kept.push_back(e);
    }
    t.edges = std::move(kept);
    return t;
}

PlanarGraph tree(Rng& rng, std::size_t n) {
    GraphBuilder b;
    const std::int64_t side = point_square(rng, n) * 2;
    if (n == 0) return b.take();
    (void)b.add_point(at(rng.between(0, side - 1), rng.between(0, side - 1)));
    for (std::size_t tries = 0; b.num_vertices() < n && tries < 4 * n; ++tries) {
        const std::optional<VertexId> p = b.add_point(at(rng.between(0, side - 1), rng.between(0, side - 1)));
        if (!p) continue;
        // Attach to an earlier vertex; a vertex that cannot be attached stays
        // isolated (the forest gains a component).
        for (int attempt = 0; attempt < 8; ++attempt) {
            if (b.add_edge(*p, VertexId(static_cast<Index>(rng.below(p->index()))))) break;
        }
    }
    return b.take();
}

}  // namespace dcel::gen::detail
