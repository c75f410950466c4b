// Reading and writing a PlanarGraph as JSON.
//
// Two input forms are accepted:
//   {"vertices": [[x, y], ...], "edges": [[u, v], ...]}   (other keys are ignored)
//   [[[x, y], ...], [[u, v], ...]]                        (positional)
// Coordinates are finite JSON numbers, read correctly rounded. Vertex indexes
// are non-negative integers below 2^32 - 1 (1.0 and 1e0 count as integers);
// whether they name existing vertices is checked later, by build().
//
// Errors are InvalidInput with a one-line message naming the place: "line L,
// column C: ..." for syntax errors, a JSON path for the rest, e.g.
//   edges[0][0]: vertex index -1 is negative: ids count from 0
//   vertices[2]: expected a point [x, y], found an array of 3 elements
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "dcel/graph.hpp"
#include "dcel/io/text_sink.hpp"

namespace dcel::io {

[[nodiscard]] PlanarGraph read_graph(std::string_view text);

// One line, numbers in their shortest round-trip form, then "\n":
//   {"vertices": [[0, 0], [1, 0.5]], "edges": [[0, 1]]}
// A null vertex id is written as null (which read_graph rejects). Throws
// InvalidInput(BadCoordinate) for a NaN or infinite coordinate, which JSON
// cannot express.
[[nodiscard]] std::string write_graph(const PlanarGraph& graph);
// The same text, streamed to `sink` a piece of at most 16 KiB at a time
// (text_sink.hpp); a NaN or infinite coordinate throws after the sink took
// the text before it.
void write_graph(const PlanarGraph& graph, const TextSink& sink);

// A document that is one array of points, [[x, y], ...] (as `dcel locate
// --points` reads). Throws InvalidInput like read_graph.
[[nodiscard]] std::vector<Point> read_points(std::string_view text);

}  // namespace dcel::io
