// Structure-aware mutations of planar straight-line graphs, for the custom
// mutators of the oracle, nonplanar and edit harnesses (graph_fuzzer.hpp).
//
// libFuzzer's byte mutations mostly break a graph's text or make it
// invalid; these act on the geometry directly: move a vertex a few ulps or
// onto (within rounding of) the line through two others, put a vertex
// within ulps of another, add a non-crossing edge, delete an edge or a
// vertex, split an edge, copy a component (scaled down) into a face, and
// apply the generators' exact transforms. With Validity::Keep every result
// is a valid graph by the brute-force oracle (a mutation that would break
// it is undone); with Validity::Break some mutations aim at a defect (a
// crossing, a touch, an overlap, a duplicate point or edge) instead.
//
// Randomness comes from the generators' one RNG (dcel/gen/rng.hpp), seeded
// by libFuzzer, so a mutation is reproducible from its seed.
#pragma once

#include <cstddef>
#include <string>

#include "dcel/gen/rng.hpp"
#include "dcel/graph.hpp"

namespace dcel::fuzz {

enum class Validity { Keep, Break };

struct GraphLimits {
    std::size_t vertices;
    std::size_t edges;
};

// One mutation of g, chosen by rng; false when none could be made (g is
// then unchanged). g must be valid when validity is Keep.
bool mutate_graph(PlanarGraph& g, gen::Rng& rng, Validity validity, const GraphLimits& limits);

// Puts a copy of a component of `other`, scaled down by a power of two, at
// a point of g (inside one of its faces, or beside it). false when no copy
// fits (g unchanged).
bool cross_over(PlanarGraph& g, const PlanarGraph& other, gen::Rng& rng, Validity validity, const GraphLimits& limits);

// Is g a valid planar straight-line graph (the brute-force oracle)?
[[nodiscard]] bool is_valid(const PlanarGraph& g);

// The same for g made from the valid graph `before` by changing or adding
// (never removing) vertices and edges: only what changed, and what meets
// it, is checked. O((changed edges + moved vertices) (V + E)).
[[nodiscard]] bool still_valid(const PlanarGraph& g, const PlanarGraph& before);

}  // namespace dcel::fuzz
