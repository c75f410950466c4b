#include "dcel/lex_order.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "dcel/error.hpp"
#include "dcel/format.hpp"

namespace dcel {
namespace {

struct Keyed {
    Point p;
    Index id;
};

bool keyed_less(const Keyed& a, const Keyed& b) {
    if (lex_less(a.p, b.p)) return true;
    if (lex_less(b.p, a.p)) return false;
    return a.id < b.id;
}

// Buckets hold two points on average; larger ones (many equal or close x)
// fall back to std::sort.
void sort_bucket(Keyed* first, Keyed* last) {
    if (last - first > 16) {
        std::sort(first, last, keyed_less);
        return;
    }
    for (Keyed* i = first + 1; i < last; ++i) {  // insertion sort
        const Keyed k = *i;
        Keyed* j = i;
        for (; j > first && keyed_less(k, *(j - 1)); --j) *j = *(j - 1);
        *j = k;
    }
}

}  // namespace

LexOrder lex_order_checked(const std::vector<Point>& points) {
    const auto n = static_cast<Index>(points.size());
    LexOrder out;
    out.vertex_of_rank.resize(n);
    out.rank_of_vertex.resize(n);
    if (n == 0) return out;

    double xmin = points[0].x;
    double xmax = points[0].x;
    for (const Point& p : points) {
        xmin = std::min(xmin, p.x);
        xmax = std::max(xmax, p.x);
    }
    const Index buckets = std::max<Index>(1, n / 2);
    // A range that overflows, or one so small that scale overflows, puts
    // everything in bucket 0: still exact, just O(V log V).
    const double range = xmax - xmin;
    double scale = range > 0 ? static_cast<double>(buckets) / range : 0.0;
    if (!std::isfinite(range) || !std::isfinite(scale)) scale = 0.0;
    auto bucket_of = [&](double x) -> Index {
        const double t = (x - xmin) * scale;  // in [0, buckets] up to rounding, never NaN
        return t < static_cast<double>(buckets) ? static_cast<Index>(t) : buckets - 1;
    };

    // Counting sort by bucket (O(V)), then each bucket exactly.
    std::vector<Index> start(buckets + 1, 0);
    for (const Point& p : points) ++start[bucket_of(p.x) + 1];
    for (Index b = 0; b < buckets; ++b) start[b + 1] += start[b];
    std::vector<Keyed> sorted(n);
    for (Index v = 0; v < n; ++v) sorted[start[bucket_of(points[v].x)]++] = Keyed{points[v], v};
    // start[b] is now the end of bucket b.
    Index begin = 0;
    for (Index b = 0; b < buckets; ++b) {
        sort_bucket(sorted.data() + begin, sorted.data() + start[b]);
        begin = start[b];
    }
    for (Index r = 0; r < n; ++r) {
        out.vertex_of_rank[r] = VertexId(sorted[r].id);
        out.rank_of_vertex[sorted[r].id] = r;
    }
    for (Index r = 1; r < n; ++r) {
        if (sorted[r - 1].p == sorted[r].p) {
            const VertexId a(sorted[r - 1].id);
            const VertexId b(sorted[r].id);
            throw InvalidInput(InputErrorKind::DuplicatePoint,
                               "vertices " + std::to_string(a.index()) + " and " + std::to_string(b.index()) +
                                   " are at the same point " + format_point(sorted[r].p) +
                                   "; merge them into one vertex",
                               {a, b});
        }
    }
    return out;
}

}  // namespace dcel
