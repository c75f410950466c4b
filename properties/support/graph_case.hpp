// RapidCheck generators of planar straight-line graphs, drawn from dcel::gen.
//
// A case is (family, seed, size) -> gen::generate, with the graph size
// following RapidCheck's size parameter (0 .. 3 * size + 3 vertices, so the
// default max_size of 100 reaches a few hundred edges). The parameters never
// shrink; the graph shrinks through gen::shrink_candidates, which yields only
// valid graphs, so a counterexample ends as a small valid graph. A case prints
// as its parameters plus the graph as one line of JSON that pastes straight
// into `dcel faces`.
#pragma once

#include <rapidcheck.h>

#include <ostream>
#include <vector>

#include "dcel/gen/generate.hpp"
#include "dcel/graph.hpp"

namespace dcel::props {

struct GraphCase {
    gen::Params params;  // where the graph came from (before shrinking)
    PlanarGraph graph;
};

void showValue(const GraphCase& c, std::ostream& os);

// Graphs from any family (or from the given ones), shrinking to valid graphs.
[[nodiscard]] rc::Gen<GraphCase> graphs();
[[nodiscard]] rc::Gen<GraphCase> graphs(std::vector<gen::Family> families);

// True when every coordinate is an integer, so areas and orientations are
// exact in integer arithmetic (the "exact for integer coordinates").
[[nodiscard]] bool has_integer_coordinates(const PlanarGraph& g);

}  // namespace dcel::props

namespace dcel::gen {
// Readable names in counterexamples.
void showValue(Defect d, std::ostream& os);
void showValue(Transform t, std::ostream& os);
}  // namespace dcel::gen
