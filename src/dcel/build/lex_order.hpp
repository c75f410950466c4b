// The sweep order of the vertices: by x, then by y (lex_less), ties by id.
//
// A bucket sort on x followed by exact sorts inside each bucket (a bucket
// sort on y for a large bucket of one x, such as a grid's column): O(V) on
// spread-out points and on grids, O(V log V) in the worst case. The bucket
// of a point is floor((x - xmin) * scale): every IEEE operation in it is
// monotone, so x1 <= x2 gives bucket(x1) <= bucket(x2), and the order
// between buckets agrees with the exact order. Only comparisons of
// coordinates decide anything inside a bucket.
#pragma once

#include <vector>

#include "dcel/geometry/point.hpp"
#include "dcel/ids.hpp"

namespace dcel::detail {

struct LexOrder {
    std::vector<VertexId> vertex_of_rank;  // the vertices in sweep order
    std::vector<Index> rank_of_vertex;     // the inverse permutation
    std::vector<Point> point_of_rank;      // the points in sweep order (the sort has them at hand)
};

// Requires finite coordinates. Throws DuplicatePoint naming the first two
// vertices at one point, in sweep order (-0.0 and 0.0 are one point).
[[nodiscard]] LexOrder lex_order_checked(const std::vector<Point>& points);

}  // namespace dcel::detail
