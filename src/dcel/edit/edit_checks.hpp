// The preconditions of the edits (edit.hpp), checked exactly before anything
// changes. Each throws InvalidInput (a bad id or coordinate) or TopologyError
// (the edit would break the subdivision) with a one-line message that starts
// with the edit's name and names the ids involved.
#pragma once

#include <string>
#include <string_view>

#include "dcel/core/finite.hpp"
#include "dcel/dcel.hpp"

namespace dcel::detail {

// "v3 (1, 2)" and "e5 [v1 (0, 0), v2 (4, 0)]".
[[nodiscard]] std::string describe(const Dcel& d, VertexId v);
[[nodiscard]] std::string describe(const Dcel& d, EdgeId e);

void require_vertex(const Dcel& d, VertexId v, std::string_view edit);
void require_edge(const Dcel& d, EdgeId e, std::string_view edit);

// p is neither at a vertex nor inside an edge. O(V + E).
void require_point_free(const Dcel& d, Point p, std::string_view edit);

// The segment from u to `to` (the point of vertex v, or a new point when v
// is null) meets no edge and no vertex except at u and v: no crossing, no
// overlap, no vertex inside it. Assumes `to` is already known to be free.
// O(V + E).
void require_segment_clear(const Dcel& d, VertexId u, Point to, VertexId v, std::string_view edit);

[[noreturn]] void refuse(std::string_view edit, const std::string& reason);

}  // namespace dcel::detail
