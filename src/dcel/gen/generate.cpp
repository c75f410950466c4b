// generate(): family dispatch, then a random relabelling (vertex order, edge
// order, edge directions) and sometimes a random exact transform, so that no
// family always presents its graph in construction order or one position.
#include "dcel/gen/generate.hpp"

#include <array>

#include "dcel/gen/families.hpp"
#include "dcel/gen/rng.hpp"

namespace dcel::gen {
namespace {

constexpr std::array<Family, 10> kFamilies = {
    Family::RandomSegments, Family::Triangulation, Family::GridWithHoles,  Family::NestedPolygons, Family::Tree,
    Family::Comb,           Family::Star,          Family::CollinearChain, Family::Components,     Family::NearDegenerate,
};

constexpr std::array<std::string_view, 10> kNames = {
    "random-segments", "triangulation", "grid-with-holes", "nested-polygons", "tree", "comb", "star",
    "collinear-chain", "components",    "near-degenerate",
};

PlanarGraph by_family(Family f, Rng& rng, std::size_t n) {
    switch (f) {
        case Family::RandomSegments: return detail::random_segments(rng, n);
        case Family::Triangulation: return detail::triangulation(rng, n);
        case Family::GridWithHoles: return detail::grid_with_holes(rng, n);
        case Family::NestedPolygons: return detail::nested_polygons(rng, n);
        case Family::Tree: return detail::tree(rng, n);
        case Family::Comb: return detail::comb(rng, n);
        case Family::Star: return detail::star(rng, n);
        case Family::CollinearChain: return detail::collinear_chain(rng, n);
        case Family::Components: return detail::components(rng, n);
        case Family::NearDegenerate: return detail::near_degenerate(rng, n);
    }
    return {};
}

PlanarGraph relabelled(const PlanarGraph& g, Rng& rng) {
    std::vector<Index> new_id(g.vertices.size());
    for (Index v = 0; v < new_id.size(); ++v) new_id[v] = v;
    rng.shuffle(new_id);
    PlanarGraph out;
    out.vertices.resize(g.vertices.size());
    for (Index v = 0; v < new_id.size(); ++v) out.vertices[new_id[v]] = g.vertices[v];
    for (const GraphEdge& e : g.edges) {
        const VertexId u(new_id[e.u.index()]), w(new_id[e.v.index()]);
        out.edges.push_back(rng.chance(1, 2) ? GraphEdge{u, w} : GraphEdge{w, u});
    }
    rng.shuffle(out.edges);
    return out;
}

// One of the four exact transforms with a random amount; the graph unchanged
// when that transform would round.
PlanarGraph randomly_transformed(PlanarGraph g, Rng& rng) {
    std::optional<PlanarGraph> t;
    switch (rng.below(4)) {
        case 0: t = apply(g, Transform::Translate, rng.between(-(1 << 20), 1 << 20)); break;
        case 1: t = apply(g, Transform::Rotate90); break;
        case 2: t = apply(g, Transform::Mirror); break;
        default: t = apply(g, Transform::ScalePow2, rng.between(-40, 40)); break;
    }
    return t ? std::move(*t) : std::move(g);
}

}  // namespace

std::span<const Family> all_families() { return kFamilies; }

std::string_view family_name(Family f) { return kNames[static_cast<std::size_t>(f)]; }

std::optional<Family> family_from_name(std::string_view name) {
    for (std::size_t i = 0; i < kNames.size(); ++i) {
        if (kNames[i] == name) return kFamilies[i];
    }
    return std::nullopt;
}

PlanarGraph generate(const Params& params) {
    // Mix the family into the seed so that families drawn with one seed are
    // unrelated.
    Rng rng(params.seed ^ (0x9e3779b97f4a7c15ULL * (static_cast<std::uint64_t>(params.family) + 1)));
    PlanarGraph g = relabelled(by_family(params.family, rng, params.vertices), rng);
    if (rng.chance(1, 4)) g = randomly_transformed(std::move(g), rng);
    return g;
}

}  // namespace dcel::gen
