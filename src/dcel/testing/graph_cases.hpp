// RapidCheck generator of valid planar straight-line graphs drawn from
// dcel::gen: the one generator behind the properties (properties/) and the
// in-process checking helpers (check_testing.hpp), public so that a user's
// own properties draw the same graphs.
//
// A case is (family, seed, vertices) -> gen::generate, then in targeted
// mode perhaps an exact scaling by 2^-700 or 2^700. The parameters never
// shrink; the graph shrinks by dropping blocks of vertices, then through
// gen::shrink_candidates, both of which yield only valid graphs, so a
// counterexample ends as a small valid graph. A case
// prints as its parameters plus the graph as one line of JSON.
//
// Header-only (the library never depends on RapidCheck): link
// dcel::testing and rapidcheck.
#pragma once

#include <rapidcheck.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <ostream>
#include <utility>
#include <vector>

#include "dcel/gen/generate.hpp"
#include "dcel/graph.hpp"
#include "dcel/io/graph_json.hpp"

namespace dcel::testing {

struct GraphCase {
    gen::Params params;  // where the graph came from (before shrinking)
    PlanarGraph graph;
    int scale_exponent = 0;  // the generated graph was multiplied by 2^scale_exponent
};

inline void showValue(const GraphCase& c, std::ostream& os) {
    os << "family " << gen::family_name(c.params.family) << ", seed " << c.params.seed << ", " << c.params.vertices
       << " vertices asked";
    if (c.scale_exponent != 0) os << ", scaled by 2^" << c.scale_exponent;
    os << "; " << c.graph.vertices.size() << " vertices, " << c.graph.edges.size()
       << " edges after shrinking. Paste into `dcel faces -`:\n"
       << io::write_graph(c.graph);
}

struct GraphCaseOptions {
    // The families to draw from; empty means all of them.
    std::vector<gen::Family> families = {};
    // The size parameter: an ordinary case asks for 0 .. vertices_per_size *
    // size + 3 vertices, where size is RapidCheck's (0 on the first case,
    // rising to max_size, 100 by default, on the last).
    int vertices_per_size = 3;
    // Targeted cases from the first case on. Out of 16 draws: 6 ordinary (any
    // family, the size above), 4 near-degenerate graphs of 6 to 40 vertices
    // (directions 1e-17 rad apart, large offsets, subnormals, -0.0), 3 nested
    // polygons of 8 to 48 (holes inside holes), 2 many components with
    // isolated vertices (6 to 40), 1 large graph (200 to 800 vertices, any
    // family), whatever the size. A uniform draw whose size grows from 0
    // reaches these late or rarely: 100 such cases let a textbook atan2
    // solver pass on about one seed in four. Then, whatever was drawn, one
    // graph in four is scaled by 2^-700 and one in four by 2^700 (exactly;
    // left as it is when a coordinate would round or overflow), so that tiny
    // and huge magnitudes come from every family: without it a solver that
    // clamps coordinates to +-1e200 passed all 100 cases on 20 seeds of 20.
    bool targeted = false;
};

namespace graph_cases_detail {

inline std::vector<gen::Family> families_or_all(std::vector<gen::Family> families) {
    if (!families.empty()) return families;
    const auto all = gen::all_families();
    return {all.begin(), all.end()};
}

inline rc::Gen<gen::Params> params(rc::Gen<gen::Family> family, rc::Gen<std::uint64_t> seed, rc::Gen<int> vertices) {
    return rc::gen::apply(
        [](gen::Family f, std::uint64_t s, int n) {
            return gen::Params{f, s, static_cast<std::size_t>(n)};
        },
        std::move(family), std::move(seed), std::move(vertices));
}

// RapidCheck scales its integer draws by the size, which is 0 on the first
// case: at size 0, inRange(lo, hi) is always lo and arbitrary<uint64_t>()
// always 0. The targeted draws take the whole range from the first case.
template <class T>
rc::Gen<T> unscaled(rc::Gen<T> g) {
    return rc::gen::resize(100, std::move(g));
}

struct Weighted {
    int weight;
    rc::Gen<gen::Params> params;
};

// Size-independent parameters of `family` (lo <= vertices < hi), when the
// family is one of the allowed ones.
inline void add_targeted(std::vector<Weighted>& mix, const std::vector<gen::Family>& allowed, int weight, gen::Family family,
                         int lo, int hi) {
    for (const gen::Family f : allowed) {
        if (f == family) {
            mix.push_back({weight, params(rc::gen::just(f), unscaled(rc::gen::arbitrary<std::uint64_t>()),
                                          unscaled(rc::gen::inRange(lo, hi)))});
        }
    }
}

inline rc::Gen<gen::Params> one_of(std::vector<Weighted> mix) {
    int total = 0;
    for (const Weighted& w : mix) total += w.weight;
    return rc::gen::mapcat(unscaled(rc::gen::inRange(0, total)), [mix = std::move(mix)](int r) {
        for (const Weighted& w : mix) {
            if (r < w.weight) return w.params;
            r -= w.weight;
        }
        return mix.back().params;
    });
}

// One of the scalings above: none twice as often as either of the others.
inline rc::Gen<int> scale_exponent(bool targeted) {
    if (!targeted) return rc::gen::just(0);
    return unscaled(rc::gen::elementOf(std::vector<int>{0, 0, -700, 700}));
}

// The generated graph scaled by 2^k, or unscaled when that would round.
inline GraphCase generated(const gen::Params& p, int k) {
    PlanarGraph g = gen::generate(p);
    if (k == 0) return GraphCase{p, std::move(g), 0};
    std::optional<PlanarGraph> scaled = gen::apply(g, gen::Transform::ScalePow2, k);
    if (!scaled) return GraphCase{p, std::move(g), 0};
    return GraphCase{p, std::move(*scaled), k};
}

inline rc::Gen<gen::Params> case_params(const std::vector<gen::Family>& families, int per_size, bool targeted) {
    return rc::gen::withSize([families, per_size, targeted](int size) {
        const rc::Gen<int> vertices = rc::gen::inRange(0, per_size * size + 4);
        if (!targeted) return params(rc::gen::elementOf(families), rc::gen::arbitrary<std::uint64_t>(), vertices);
        const rc::Gen<std::uint64_t> any_seed = unscaled(rc::gen::arbitrary<std::uint64_t>());
        std::vector<Weighted> mix;
        mix.push_back({6, params(rc::gen::elementOf(families), any_seed, unscaled(vertices))});
        add_targeted(mix, families, 4, gen::Family::NearDegenerate, 6, 41);
        add_targeted(mix, families, 3, gen::Family::NestedPolygons, 8, 49);
        add_targeted(mix, families, 2, gen::Family::Components, 6, 41);
        mix.push_back({1, params(rc::gen::elementOf(families), any_seed, unscaled(rc::gen::inRange(200, 801)))});
        return one_of(std::move(mix));
    });
}

// g without the vertices begin .. end-1 and their edges, the others
// renumbered in order: still valid (fewer points, a subset of the segments).
inline PlanarGraph without_vertex_block(const PlanarGraph& g, std::size_t begin, std::size_t end) {
    PlanarGraph out;
    out.vertices.insert(out.vertices.end(), g.vertices.begin(), g.vertices.begin() + static_cast<std::ptrdiff_t>(begin));
    out.vertices.insert(out.vertices.end(), g.vertices.begin() + static_cast<std::ptrdiff_t>(end), g.vertices.end());
    const auto renumbered = [&](VertexId v) {
        return VertexId(v.index() < begin ? v.index() : static_cast<Index>(v.index() - (end - begin)));
    };
    for (const GraphEdge& e : g.edges) {
        const bool dropped = (e.u.index() >= begin && e.u.index() < end) || (e.v.index() >= begin && e.v.index() < end);
        if (!dropped) out.edges.push_back({renumbered(e.u), renumbered(e.v)});
    }
    return out;
}

// Smaller valid graphs, lazily (RapidCheck stops at the first that still
// fails): first blocks of half, a quarter, ... of the vertices dropped (so a
// graph of 800 vertices loses hundreds in one step), then
// gen::shrink_candidates, computed only when no block could go.
inline rc::Seq<PlanarGraph> smaller_graphs(const PlanarGraph& g) {
    std::vector<std::pair<std::size_t, std::size_t>> blocks;
    const std::size_t n = g.vertices.size();
    for (std::size_t chunk = n / 2; chunk >= 2; chunk /= 2) {
        for (std::size_t begin = 0; begin < n; begin += chunk) blocks.emplace_back(begin, std::min(n, begin + chunk));
    }
    auto by_blocks = rc::seq::map(rc::seq::fromContainer(std::move(blocks)), [g](std::pair<std::size_t, std::size_t> b) {
        return without_vertex_block(g, b.first, b.second);
    });
    auto the_rest = rc::seq::join(
        rc::seq::map(rc::seq::just(0), [g](int) { return rc::seq::fromContainer(gen::shrink_candidates(g)); }));
    return rc::seq::concat(std::move(by_blocks), std::move(the_rest));
}

}  // namespace graph_cases_detail

[[nodiscard]] inline rc::Gen<GraphCase> graph_cases(GraphCaseOptions options = {}) {
    const rc::Gen<gen::Params> params = graph_cases_detail::case_params(
        graph_cases_detail::families_or_all(std::move(options.families)), options.vertices_per_size, options.targeted);
    const rc::Gen<std::pair<gen::Params, int>> drawn = rc::gen::pair(params,
                                                                     graph_cases_detail::scale_exponent(options.targeted));
    return rc::gen::mapcat(rc::gen::noShrink(drawn), [](const std::pair<gen::Params, int>& d) {
        return rc::Gen<GraphCase>([d](const rc::Random&, int) {
            return rc::shrinkable::shrinkRecur(graph_cases_detail::generated(d.first, d.second), [](const GraphCase& c) {
                return rc::seq::map(graph_cases_detail::smaller_graphs(c.graph),
                                    [params = c.params, k = c.scale_exponent](PlanarGraph g) {
                                        return GraphCase{params, std::move(g), k};
                                    });
            });
        });
    });
}

}  // namespace dcel::testing
