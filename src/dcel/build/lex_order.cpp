#include "dcel/build/lex_order.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "dcel/build/huge_pages.hpp"
#include "dcel/error.hpp"
#include "dcel/format.hpp"

namespace dcel::detail {
namespace {

struct Keyed {
    Point p;
    Index id = 0;
};

bool keyed_less(const Keyed& a, const Keyed& b) {
    if (lex_less(a.p, b.p)) return true;
    if (lex_less(b.p, a.p)) return false;
    return a.id < b.id;
}

void insertion_sort(Keyed* first, const Keyed* last) {
    for (Keyed* i = first + 1; i < last; ++i) {
        const Keyed k = *i;
        Keyed* j = i;
        for (; j > first && keyed_less(k, *(j - 1)); --j) *j = *(j - 1);
        *j = k;
    }
}

// Distributes the n elements source(0) .. source(n - 1) into `out`, in about
// half as many buckets as elements by the coordinate `key` selects, through
// floor((c - min) * scale): every IEEE operation in it is monotone, so
// c1 <= c2 gives bucket(c1) <= bucket(c2) and the buckets come in exact
// order. Within a bucket the elements keep their source order. Returns the
// bucket ends.
template <class Source, class Key>
std::vector<Index> distribute(Index n, Source source, Keyed* out, Key key) {
    double lo = key(source(0));
    double hi = lo;
    for (Index i = 0; i < n; ++i) {
        lo = std::min(lo, key(source(i)));
        hi = std::max(hi, key(source(i)));
    }
    const Index buckets = std::max<Index>(1, n / 2);
    // A range that overflows, or one so small that scale overflows, puts
    // everything in bucket 0: still exact, the caller then sorts it.
    const double range = hi - lo;
    double scale = range > 0 ? static_cast<double>(buckets) / range : 0.0;
    if (!std::isfinite(range) || !std::isfinite(scale)) scale = 0.0;
    auto bucket_of = [&](const Keyed& k) -> Index {
        const double t = (key(k) - lo) * scale;  // in [0, buckets] up to rounding, never NaN
        return t < static_cast<double>(buckets) ? static_cast<Index>(t) : buckets - 1;
    };
    std::vector<Index> end;
    assign_huge(end, buckets + std::size_t{1}, Index{0});
    for (Index i = 0; i < n; ++i) ++end[bucket_of(source(i)) + 1];
    for (Index b = 0; b < buckets; ++b) end[b + 1] += end[b];
    for (Index i = 0; i < n; ++i) {
        const Keyed k = source(i);
        out[end[bucket_of(k)]++] = k;
    }
    end.pop_back();  // end[b] is now the end of bucket b
    return end;
}

// Sorts one bucket of the x pass. Most hold a couple of points; a large one
// already in order (the x pass keeps input order within a bucket, and a
// grid's column, row-major, comes bottom to top) is left as it is; a large
// one whose points share one x (a vertical chain in any order) is bucketed
// again by y; anything else large goes to std::sort.
void sort_bucket(Keyed* first, Keyed* last) {
    if (last - first <= 16) {
        insertion_sort(first, last);
        return;
    }
    if (std::is_sorted(first, last, keyed_less)) return;
    const bool one_x = std::all_of(first, last, [&](const Keyed& k) { return k.p.x == first->p.x; });
    if (!one_x) {
        std::sort(first, last, keyed_less);
        return;
    }
    const auto n = static_cast<Index>(last - first);
    const std::vector<Keyed> copy(first, last);
    const std::vector<Index> ends = distribute(
        n, [&](Index i) { return copy[i]; }, first, [](const Keyed& k) { return k.p.y; });
    Index begin = 0;
    for (const Index end : ends) {
        if (end - begin > 16) {
            std::sort(first + begin, first + end, keyed_less);
        } else {
            insertion_sort(first + begin, first + end);
        }
        begin = end;
    }
}

}  // namespace

LexOrder lex_order_checked(const std::vector<Point>& points) {
    const auto n = static_cast<Index>(points.size());
    LexOrder out;
    assign_huge(out.vertex_of_rank, n);
    assign_huge(out.rank_of_vertex, n);
    if (n == 0) return out;

    // Points that come already in strictly increasing order (a chain or a
    // polyline generated left to right) are their own sweep order, and
    // strictly increasing means no two are equal: one pass of lex_less.
    Index sorted_prefix = 1;
    while (sorted_prefix < n && lex_less(points[sorted_prefix - 1], points[sorted_prefix])) ++sorted_prefix;
    if (sorted_prefix == n) {
        for (Index v = 0; v < n; ++v) {
            out.vertex_of_rank[v] = VertexId(v);
            out.rank_of_vertex[v] = v;
        }
        out.point_of_rank = points;
        return out;
    }

    // The x pass reads the points where they are: no copy of them as Keyed.
    std::vector<Keyed> sorted;
    assign_huge(sorted, n);
    const std::vector<Index> ends = distribute(
        n,
        [&](Index v) {
            return Keyed{points[v], v};
        },
        sorted.data(), [](const Keyed& k) { return k.p.x; });
    Index begin = 0;
    for (const Index end : ends) {
        sort_bucket(sorted.data() + begin, sorted.data() + end);
        begin = end;
    }
    assign_huge(out.point_of_rank, n);  // only now: the peak is while the bucket ends live
    for (Index r = 0; r < n; ++r) {
        out.vertex_of_rank[r] = VertexId(sorted[r].id);
        out.rank_of_vertex[sorted[r].id] = r;
        out.point_of_rank[r] = sorted[r].p;
    }
    for (Index r = 1; r < n; ++r) {
        if (sorted[r - 1].p == sorted[r].p) {
            const VertexId a(sorted[r - 1].id);
            const VertexId b(sorted[r].id);
            throw InvalidInput(InputErrorKind::DuplicatePoint,
                               "vertices " + std::to_string(a.index()) + " and " + std::to_string(b.index()) +
                                   " are at the same point " + format_point(sorted[r].p) + "; merge them into one vertex",
                               {a, b});
        }
    }
    return out;
}

}  // namespace dcel::detail
