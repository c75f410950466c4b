// The properties' graphs: dcel/testing/graph_cases.hpp (the generator the
// in-process checking helpers use too), with the graph size following
// RapidCheck's size parameter at 3 vertices per unit (0 .. 3 * size + 3
// vertices, so the default max_size of 100 reaches a few hundred edges), all
// families drawn uniformly.
#pragma once

#include <rapidcheck.h>

#include <ostream>
#include <vector>

#include "dcel/gen/generate.hpp"
#include "dcel/graph.hpp"
#include "dcel/testing/graph_cases.hpp"

namespace dcel::props {

using testing::GraphCase;  // printed by testing::showValue

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
