// What keeps a graph from being a planar straight-line drawing, for
// validate()'s embedding check: found here, independently of build().
//
// Why not build()'s input checks (build/input_checks, build/ring_sort,
// build/sweep): validate() judges build()'s own dumps, so it must not decide
// with the code it judges, or one bug would pass in both. These checks use
// only the exact predicates of dcel/geometry/ (tested on their own against
// exact rationals), std::sort, and validate()'s own sweep (segment_sweep).
// They word each problem as build() does (the same InputErrorKind and the
// same message), so a dump and its graph are refused alike.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "dcel/error.hpp"
#include "dcel/graph.hpp"
#include "dcel/ids.hpp"

namespace dcel::detail {

struct DrawingProblem {
    InputErrorKind kind = InputErrorKind::Crossing;
    std::string message;
    std::vector<VertexId> vertices;  // the offending vertices
    std::vector<EdgeId> edges;       // the offending edges
};

// The first problem, in this order (build()'s): a non-finite coordinate (the
// lowest vertex id), a self-loop (the lowest edge id), two vertices at one
// point (the lex-first point), two edges leaving a vertex in one direction
// (the lowest vertex id; there, the first direction counterclockwise from
// east), then the first improper contact the sweep meets: a crossing, a
// vertex inside an edge, or an overlap. Requires edge ends in range.
// O((V + E) log(V + E)).
[[nodiscard]] std::optional<DrawingProblem> find_drawing_problem(const PlanarGraph& g);

}  // namespace dcel::detail
