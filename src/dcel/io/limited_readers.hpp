// Internal to dcel::io: the readers of graph_json.hpp and dcel_json.hpp with
// caps on the element counts, for the tests and for callers that refuse
// huge inputs early, and the point-list reader the graph and dump readers
// share. The public readers use CountLimits{}.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "dcel/dump.hpp"
#include "dcel/graph.hpp"
#include "dcel/ids.hpp"
#include "dcel/io/json_reader.hpp"

namespace dcel::io {

// Caps on element counts. The defaults are what 32-bit ids can name (kNoIndex
// is the null id): vertex, half-edge and face ids up to 2^32 - 2, and edges up
// to 2^31 - 1 so that half-edge 2k+1 fits. Lower caps are for tests (and for
// callers that want to refuse huge inputs early); exceeding one is TooLarge.
struct CountLimits {
    std::uint64_t vertices = kNoIndex;
    std::uint64_t edges = kNoIndex / 2;
    std::uint64_t half_edges = kNoIndex;
    std::uint64_t faces = kNoIndex;
};

namespace detail {
// read_graph with caps on the counts (TooLarge beyond them).
[[nodiscard]] PlanarGraph read_graph(std::string_view text, const CountLimits& limits);
// At a value position: an array of points [[x, y], ...] appended to `out`
// (TooLarge past `limit` points). Shared with the dump reader.
void read_points(JsonReader& r, std::vector<Point>& out, std::uint64_t limit);
// The dump and faces readers with caps on the counts.
[[nodiscard]] DcelDump read_dump(std::string_view text, const CountLimits& limits);
[[nodiscard]] std::vector<std::vector<Index>> read_faces_answer(std::string_view text, const CountLimits& limits);
}  // namespace detail

}  // namespace dcel::io
