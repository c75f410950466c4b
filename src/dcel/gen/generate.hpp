// Random valid planar straight-line graphs, their exact transforms, planted
// defects and shrinking: the one generator library that the property tests
// (properties/), the fuzz harnesses (fuzz/) and the CLI (`dcel gen`,
// `dcel diff`) all draw from. Library target dcel::gen.
//
// Everything is deterministic in its arguments: the same (family, seed,
// vertices) gives the same graph on every platform (own PRNG, no
// std::uniform_*_distribution, whose output is implementation-defined).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "dcel/graph.hpp"

namespace dcel::gen {

enum class Family : std::uint8_t {
    RandomSegments,  // random integer points joined by random non-crossing segments
    Triangulation,   // a random subset of the edges of a triangulation of random integer points
    GridWithHoles,   // a grid with some cells' edges removed, leaving holes and islands
    NestedPolygons,  // polygons inside polygons, holes inside holes, to any depth
    Tree,            // random trees (dangling edges everywhere)
    Comb,            // a spine with teeth
    Star,            // one vertex of high degree
    CollinearChain,  // many collinear consecutive edges, with branches
    Components,      // many small components mixed with isolated vertices
    NearDegenerate,  // large offsets with tiny differences, tiny magnitudes,
                     // subnormals, -0.0, nearly parallel directions
};

[[nodiscard]] std::span<const Family> all_families();
[[nodiscard]] std::string_view family_name(Family f);  // "random-segments", ...
[[nodiscard]] std::optional<Family> family_from_name(std::string_view name);

struct Params {
    Family family = Family::RandomSegments;
    std::uint64_t seed = 0;
    std::size_t vertices = 16;  // every family gives exactly this many vertices
};

// A valid planar straight-line graph: build() accepts it. Deterministic.
[[nodiscard]] PlanarGraph generate(const Params& params);

// Exact transforms. Each maps every coordinate without rounding, or returns
// nullopt when that is impossible for this graph (e.g. a translation that
// would round, a scaling that would overflow or underflow).
enum class Transform : std::uint8_t {
    Translate,  // by (amount, -amount)
    Rotate90,   // (x, y) -> (-y, x): same cycles
    Mirror,     // (x, y) -> (-x, y): every cycle reversed
    ScalePow2,  // multiply by 2^amount
};
[[nodiscard]] std::optional<PlanarGraph> apply(const PlanarGraph& g, Transform t, std::int64_t amount = 0);

// Plants one defect into a valid graph, giving a graph that build() must
// reject: a crossing, a vertex touching an edge's interior, or a collinear
// overlap. nullopt when the graph offers no place for it.
enum class Defect : std::uint8_t { Crossing, Touch, Overlap };
[[nodiscard]] std::optional<PlanarGraph> plant(const PlanarGraph& g, Defect d, std::uint64_t seed);

// Smaller valid graphs derived from g, most aggressive first: drop edges,
// drop vertices (renumbering), snap coordinates to small integers where no
// crossing, touch or overlap appears. Every candidate is valid.
[[nodiscard]] std::vector<PlanarGraph> shrink_candidates(const PlanarGraph& g);

// Greedy shrinking: repeatedly moves to the first candidate for which
// still_fails holds, until none does or max_steps predicate calls are spent.
[[nodiscard]] PlanarGraph shrink(PlanarGraph g, const std::function<bool(const PlanarGraph&)>& still_fails,
                                 std::size_t max_steps = 20000);

}  // namespace dcel::gen
