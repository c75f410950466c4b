// Internal to dcel::io: the readers of graph_json.hpp and dcel_json.hpp with
// caps on the element counts, for the tests and for callers that refuse
// huge inputs early, the point-list reader the graph and dump readers share,
// and the point reader the CLI's edit scripts use too. The public readers use
// CountLimits{}.
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
// At a value position: one point [x, y], two numbers (a Shape error naming
// the count otherwise). Shared with the CLI's edit scripts. Forced inline:
// read_points calls it for every vertex of a graph, and as a call it costs
// read_graph about 1% more instructions.
[[nodiscard, gnu::always_inline]] inline Point read_point(JsonReader& r) {
    constexpr std::string_view kPoint = "a point [x, y]";
    r.begin_array(kPoint);
    if (!r.next_element()) r.fail_arity(kPoint, 0);
    Point p;
    p.x = r.read_double();
    if (!r.next_element()) r.fail_arity(kPoint, 1);
    p.y = r.read_double();
    if (r.next_element()) {
        r.skip_value();
        r.fail_arity(kPoint, r.finish_array());
    }
    return p;
}
// At a value position: an array of points [[x, y], ...] appended to `out`
// (TooLarge past `limit` points). Shared with the dump reader.
void read_points(JsonReader& r, std::vector<Point>& out, std::uint64_t limit);
// The dump and faces readers with caps on the counts.
[[nodiscard]] DcelDump read_dump(std::string_view text, const CountLimits& limits);
[[nodiscard]] std::vector<std::vector<Index>> read_faces_answer(std::string_view text, const CountLimits& limits);
}  // namespace detail

}  // namespace dcel::io
